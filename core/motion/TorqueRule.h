#pragma once

#include "model/RobotModel.h"
#include "motion/CartesianLine.h"
#include "motion/JointPath.h"

namespace learnid {

/// Result of the torque rule: the shortest motion duration for which the planned peak torque,
/// computed with a parameter estimate, is `fraction` of the torque limits (docs/method.md §1).
struct TorqueRuleResult
{
    double duration = 0.0;      ///< T [s]
    Eigen::VectorXd peakTorque; ///< planned max |tau_j| over the motion at T [N m] (n)
    int limitingJoint = 0;      ///< the joint whose peak reaches fraction * limit
};

/// A path's geometry (a line or a JointPath) for the torque rule, independent of the parameters:
/// regressor rows on a grid of normalised time u in [0, 1] at T = 1. Torque is linear in phi, so
/// the rule for any estimate is a product with these rows.
struct TorqueRuleGrid
{
    int dof = 0;
    Eigen::MatrixXd inertial; ///< W(q, q', q'') - W(q, 0, 0), block i*dof.. of each grid point
    Eigen::MatrixXd gravity;  ///< W(q, 0, 0)
};

TorqueRuleGrid torqueRuleGrid(const RobotModel &model, const Kinematics &kinematics,
                              const CartesianLine &line, int gridPoints = 2001);

/// The same grid for a joint-space path (q' = dq/du, q'' = d2q/du2 at T = 1). Throws Error when
/// the path's joints are not the model's or gridPoints < 2.
TorqueRuleGrid torqueRuleGrid(const RobotModel &model, const JointPath &path,
                              int gridPoints = 2001);

/// The torque rule over a precomputed grid (see shortestDuration below).
TorqueRuleResult shortestDuration(const TorqueRuleGrid &grid, const Eigen::VectorXd &phi,
                                  const Eigen::VectorXd &torqueLimit, double fraction);

/// Shortest duration T of the line such that max_t |tau_j(t)| <= fraction * limit_j for all j,
/// with tau computed from the model and the estimate phi.
/// Without gravity tau scales exactly as 1/T^2 (qd ~ 1/T, qdd ~ 1/T^2, Coriolis ~ qd^2), so T
/// is found in closed form; with gravity tau = A(u)/T^2 + g(q(u)) and T is found by bisection.
/// gridPoints: samples of normalised time u in [0, 1]. Throws Error when no T can meet the rule.
TorqueRuleResult shortestDuration(const RobotModel &model, const Eigen::VectorXd &phi,
                                  const Kinematics &kinematics, const CartesianLine &line,
                                  const Eigen::VectorXd &torqueLimit, double fraction,
                                  int gridPoints = 2001);

} // namespace learnid
