#pragma once

#include "types/Trial.h"

#include <Eigen/Core>

namespace learnid {

class FilteringEstimator;

/// The torque the drives commanded in a recorded trial, as the controller computed it: the
/// plan's feedforward plus the joints' PIDs (control/PidController.h) on the recorded tracking
/// error q_d - q, saturated at the plan's torque limits (n x samples). Exact for the simulated
/// robot and learnid-robot-sim's drives, which run these PIDs on the angles they report; a drive
/// that ran its position loop otherwise (docs/can-protocol.md §5) commanded something else.
Eigen::MatrixXd driveCommand(const TrialPlan &plan, const TrialRecord &record);

/// What a joint torque sensor does not see (estimator.jointTorqueSensor). A sensor between the
/// gear and the link measures the link's torque; the motor's rotor, before it, takes Ia_j qdd_j
/// of the drive's command. So the command minus the measured torque is the rotor's torque: per
/// joint, its least-squares fit against the joint's acceleration estimate qddHat (n x samples,
/// the law's), both zero-phase filtered as the law filters its rows, over the first `used`
/// mid-sample rows, gives Ia_j. `measured` is the torque the sensors measured (n x samples:
/// record.tau, or it with their lag undone). Returns Ia_j qdd_j at the law's mid-sample rows
/// (samples - 1 rows x n): added to the measured torque, the model's armature term learns the
/// rotor. `inertia`, when given, gets the Ia_j [kg m^2] (n).
Eigen::MatrixXd rotorTorque(const FilteringEstimator &filter, const TrialPlan &plan,
                            const TrialRecord &record, const Eigen::MatrixXd &measured,
                            const Eigen::MatrixXd &qddHat, Eigen::Index used,
                            Eigen::VectorXd *inertia = nullptr);

} // namespace learnid
