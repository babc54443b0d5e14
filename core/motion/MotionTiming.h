#pragma once

#include "types/JointTrajectory.h"

#include <Eigen/Core>
#include <functional>

namespace learnid {

/// Timing of a trial: rest, motion of duration T, rest; sampled every samplePeriod.
struct MotionTiming
{
    double motionDuration = 1.0; ///< T [s]
    double restBefore = 0.1;     ///< [s]
    double restAfter = 0.5;      ///< [s]
    double samplePeriod = 0.002; ///< Ts [s]
    /// Sample k is taken at t_k + sampleOffset [s], in [0, Ts): Ts / 2 gives the middle of each
    /// sample's hold interval (the samples and their count stay those of t_k).
    double sampleOffset = 0.0;
};

/// The joint state at motion time t in [0, T] into q, qd, qdd (n each).
using MotionState =
    std::function<void(double t, Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                       Eigen::Ref<Eigen::VectorXd> qdd)>;

/// The sampled trajectory of a motion with its rests, every path's one rule: samples at
/// t_k = k Ts, k = 0 .. floor(total / Ts), total = restBefore + T + restAfter; motion time
/// t_k + sampleOffset - restBefore clamped to [0, T]; at rest (before, after and on the motion's
/// first and last instant) velocity and acceleration exactly 0 and the position the previous
/// sample's. state is called once per distinct motion time, in order. Throws Error for a
/// non-positive period or duration, a negative rest or an offset outside [0, Ts).
JointTrajectory sampleMotion(int dof, const MotionTiming &timing, const MotionState &state);

} // namespace learnid
