#pragma once

#include "model/RobotModel.h"
#include "types/Trial.h"

#include <QString>

namespace learnid {

/// The pre-trial check (docs/method.md §3): before the robot moves.
struct SafetyVerdict
{
    bool physical = true;           ///< M(q, phi_hat) positive definite along the path
    bool stable = true;             ///< all linearised closed loops along the path stable
    double worstSpectralRadius = 0; ///< max |z| of the discrete closed loop along the path
    double worstDecayRate = 0;      ///< ln(max |z|) / Ts [1/s]; < 0 is stable
    double worstTime = 0;           ///< where along the trial it occurs [s]
    bool torqueWithinLimits = true;
    bool withinJointLimits = true; ///< planned positions and speeds within the robot's limits
    Eigen::VectorXd peakTorque;    ///< planned max |tau_f| per joint [N m] (n)
    Eigen::VectorXd torqueLimit;   ///< [N m] (n)
    /// Planned max |g_j(q)| over the path with phi_hat: what holding the arm against gravity
    /// takes of each joint [N m] (n); the rest of the limit is left for moving.
    Eigen::VectorXd peakGravityTorque;
    double motionDuration = 0; ///< [s]
    QString reason;            ///< why the trial is refused, empty when it may run

    bool passed() const { return physical && stable && torqueWithinLimits && withinJointLimits; }
};

/// Closed-loop stability of the planned controller, linearised along the planned path with the
/// estimate phi_hat standing for the robot: at each checked sample, the plant
/// x = (q, qd), x' = (qd, M^-1 (tau - h)) linearised by central differences and discretised
/// with zero-order hold, in closed loop with the Tustin PID of every joint (e = -dq, torque held
/// over the sample). Stable when every spectral radius is < exp(-margin Ts).
/// Also checks that phi_hat is physical, the planned torques are within the limits and the
/// planned positions and speeds within the joints' limits (the plan's, from the URDF).
/// points: samples checked, spread evenly over the motion.
SafetyVerdict checkTrial(const RobotModel &model, const Eigen::VectorXd &phiHat,
                         const TrialPlan &plan, double margin = 0.0, int points = 25);

} // namespace learnid
