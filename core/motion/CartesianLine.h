#pragma once

#include "motion/Kinematics.h"
#include "types/JointTrajectory.h"

#include <Eigen/Core>

namespace learnid {

/// A straight Cartesian line traversed with quintic time scaling
/// s(u) = 10u^3 - 15u^4 + 6u^5, u = t / T (zero velocity and acceleration at both ends).
struct CartesianLine
{
    Eigen::Vector2d start{0.5, 0.5}; ///< [m]
    double length = 0.5;             ///< [m]
    double directionDeg = 135.0;     ///< [deg] from the base x axis

    Eigen::Vector2d direction() const;
    Eigen::Vector2d end() const { return start + length * direction(); }
};

/// Joint state on the line at motion time t in [0, T]: q [rad], qd [rad/s], qdd [rad/s^2].
struct JointState
{
    Eigen::VectorXd q;
    Eigen::VectorXd qd;
    Eigen::VectorXd qdd;
};

/// Joint state at time t of a motion of duration T. near: the previous q, keeping its branch.
JointState lineStateAt(const Kinematics &kinematics, const CartesianLine &line, double T, double t,
                       const Eigen::VectorXd &near);

/// The same into caller storage (no allocation); the kinematics must have 2 joints.
void lineStateInto(const Kinematics &kinematics, const CartesianLine &line, double T, double t,
                   const Eigen::Ref<const Eigen::VectorXd> &near, Eigen::Ref<Eigen::VectorXd> q,
                   Eigen::Ref<Eigen::VectorXd> qd, Eigen::Ref<Eigen::VectorXd> qdd);

/// Timing of a trial: rest, motion of duration T, rest; sampled every samplePeriod.
struct MotionTiming
{
    double motionDuration = 1.0; ///< T [s]
    double restBefore = 0.1;     ///< [s]
    double restAfter = 0.5;      ///< [s]
    double samplePeriod = 0.002; ///< Ts [s]
};

/// The sampled joint trajectory of the line with rests, all samples t_k <= total time.
/// Throws Error when the line leaves the workspace or passes a singularity.
JointTrajectory planLine(const Kinematics &kinematics, const CartesianLine &line,
                         const MotionTiming &timing);

} // namespace learnid
