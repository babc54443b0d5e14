#pragma once

#include "model/RobotModel.h"
#include "types/Trial.h"

#include <Eigen/Core>
#include <QVector>

namespace learnid {

/// Everything the master streams in one trial after the drives are enabled, one column per
/// SYNC (docs/can-protocol.md, "A trial", steps 3 to 5): the return move from where the arm
/// stands to the plan's start, the hold there, the plan's samples, and the final hold.
struct SetpointSchedule
{
    Eigen::MatrixXd q;   ///< target positions [rad] (n x size())
    Eigen::MatrixXd tau; ///< torque offsets [N m] (n x size())
    QVector<int> sample; ///< the plan sample of each column, -1 for the moves and holds

    int size() const { return int(q.cols()); }
    int firstPlanColumn() const { return sample.indexOf(0); }
};

/// Limits of the return move: at least minDuration, no joint faster than maxSpeed, and the
/// model feedforward within torqueFraction of each joint's torque limit.
struct ReturnMoveLimits
{
    double minDuration = 0.5;    ///< [s]
    double maxSpeed = 1.0;       ///< [rad/s]
    double torqueFraction = 0.5; ///< of plan.torqueLimit, for (W(q, qd, qdd) - W(q, 0, 0)) phi
    double hold = 0.3;           ///< at the plan's start before sample 0 [s]
    int finalHold = 5;           ///< SYNCs holding the last target after the last sample
};

/// The quintic move q0 -> plan start, the hold, the plan and the final hold. The move lasts
/// max(minDuration, 15/8 |dq|max / maxSpeed), lengthened until the motion part of its
/// feedforward (without gravity) stays within torqueFraction of the limits (a heavy arm cannot
/// cross its workspace at 1 rad/s). Torque
/// offsets: W(q, qd, qdd) phi_hat along the move, gravity W(q, 0, 0) phi_hat in the holds
/// (phi_hat: plan.feedforwardParameters; zero when it does not fit the model), the plan's
/// feedforward for its samples. q0: measured position [rad] (n).
SetpointSchedule buildSetpointSchedule(const RobotModel &model, const TrialPlan &plan,
                                       const Eigen::VectorXd &q0, const ReturnMoveLimits &limits);

} // namespace learnid
