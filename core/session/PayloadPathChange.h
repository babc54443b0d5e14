#pragma once

#include "identify/PayloadObservability.h"
#include "model/ChainModel.h"
#include "model/Payload.h"
#include "model/PayloadPrior.h"
#include "types/JointTrajectory.h"
#include "types/Scenario.h"

#include <QString>
#include <array>
#include <memory>

namespace learnid {

/// A change of one joint at one waypoint that lets a payload session's path observe what it
/// misses (issue 25: "offer the smallest change to the path's wrist motion that would observe
/// them, if it fits the limits"; docs/payload.md).
struct PayloadPathChange
{
    int waypoint = -1;                  ///< index into path.waypoints; -1: no change offered
    int joint = -1;                     ///< index of the joint changed
    double change = 0.0;                ///< added to that waypoint's value of the joint [rad]
    double value = 0.0;                 ///< the waypoint's new value [rad]
    PayloadObservability observability; ///< of the changed path as planned
    /// The parameters the path missed that the changed one measures.
    std::array<bool, 10> measured{};

    bool valid() const { return waypoint >= 0; }
    /// One line for the technician: the waypoint (counted from 1), the joint by name, the
    /// change and the new value, and what the changed path measures that the path did not.
    QString describe(const ChainModel &model) const;
};

/// The standard errors a path predicts for the payload's 10 parameters (m, m cx, ..., Izz, the
/// parameters' own units): white torque noise of `noise` [N m, per joint] on every sample of the
/// path's regressor, sigma_p^2 = (A^T W A)^-1_pp with W = diag(1 / noise_j^2). Infinite for a
/// parameter the path does not see at all.
Eigen::Matrix<double, 10, 1> payloadPredictedStdErrors(const PayloadModel &payload,
                                                       const JointTrajectory &path,
                                                       const Eigen::VectorXd &noise);

/// The size each payload parameter is measured against: the prior's mass; m times a hundredth
/// of the bound's size (its radius, or the box's largest half side) for m cx, m cy, m cz (3 mm
/// in the default 0.3 m sphere); the prior's mean principal moment about the link frame for the
/// six inertia entries.
Eigen::Matrix<double, 10, 1> payloadParameterScale(const PayloadPrior &prior);

/// The smallest change of a waypoint path that measures the payload parameters `before` does
/// not identify: identified by the changed path (PayloadObservability) with a predicted standard
/// error (payloadPredictedStdErrors, noise 1 % of each joint's torque limit, the scenario's) at
/// most its scale (payloadParameterScale). All of them if one change does; else the smallest
/// change that measures the missing mass and centre of mass (the inertia may need rotations no
/// single joint gives). One of the three joints nearest the payload's link (its own first) at
/// one waypoint, by 0.05, 0.1, 0.2, 0.3, 0.5, 0.75 or 1 rad either way, smallest first, kept
/// 0.05 rad inside the joint's limits, planned as the session plans its next trial (the torque
/// rule with phi, gentle or not; a change whose plan fails is skipped). Not valid when the path is
/// not made of waypoints, identifies everything, or no change measures anything it misses. Throws
/// nothing: the search only offers.
PayloadPathChange smallestPayloadPathChange(const Scenario &scenario,
                                            const std::shared_ptr<const ChainModel> &model,
                                            const PayloadModel &payload, const PayloadPrior &prior,
                                            const Eigen::VectorXd &phi, bool gentle,
                                            const PayloadObservability &before);

} // namespace learnid
