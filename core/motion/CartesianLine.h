#pragma once

#include "motion/Kinematics.h"
#include "motion/MotionTiming.h"
#include "types/CartesianLine.h"
#include "types/JointTrajectory.h"

#include <Eigen/Core>

namespace learnid {

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

/// The sampled joint trajectory of the line with rests, all samples t_k <= total time.
/// Throws Error when the line leaves the workspace or passes a singularity.
JointTrajectory planLine(const Kinematics &kinematics, const CartesianLine &line,
                         const MotionTiming &timing);

} // namespace learnid
