#pragma once

#include "model/RobotModel.h"
#include "types/JointTrajectory.h"

#include <Eigen/Core>

namespace learnid {

/// The largest relative difference of x from ref over the parameters, in percent, with its sign:
/// (x_i - ref_i) / |ref_i| * 100 for the i of largest magnitude (entries with ref_i = 0 are
/// skipped). The "relative change" of an estimate from the previous one and the "error against
/// the truth" of the convergence table (CLI and GUI alike).
double largestRelativeDifferencePercent(const Eigen::VectorXd &x, const Eigen::VectorXd &ref);

/// The path-torque error in percent: ||W_path (phiHat - phi)|| / ||W_path phi|| * 100, W_path
/// the regressor along the desired trajectory (all joints, all samples): how far the torque the
/// estimate predicts on the path is from the torque the robot phi needs there. Directions the
/// path does not excite do not count (docs/method.md). NaN when phi needs no torque there.
double pathTorqueErrorPercent(const RobotModel &model, const JointTrajectory &path,
                              const Eigen::VectorXd &phiHat, const Eigen::VectorXd &phi);

} // namespace learnid
