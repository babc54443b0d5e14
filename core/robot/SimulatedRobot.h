#pragma once

#include "model/RobotModel.h"
#include "robot/ArmSimulation.h"
#include "robot/Robot.h"

#include <memory>
#include <optional>

namespace learnid {

/// Faults the simulated robot injects on request, so fault paths are tested without hardware.
/// Sample indices < 0 disable a fault.
struct SimulatedFaults
{
    int driveFaultAtSample = -1;       ///< the drive reports a fault and stops
    int nanTorqueAtSample = -1;        ///< the torque measurement of joint 0 turns NaN
    int disturbanceFromSample = -1;    ///< an external torque acts from this sample on
    Eigen::VectorXd disturbanceTorque; ///< [N m] (n)
    bool refuseApply = false;          ///< the controller refuses parameter writes
};

/// The robot as a simulation: the true dynamics integrated with RK4 at a sub-step of the sample
/// period, torque held over each sample, the joint PID of the plan, torque saturation.
///
/// The arm is deterministic: the torque noise is measurement noise and reaches neither the plant
/// nor the controller. A run of the plan the robot ran last (with no fault injected) is therefore
/// not integrated again: its motion and noise-free torques are reused and the run's own noise
/// is drawn, which gives the record a new simulation would, to the bit (tst_simulatedrobot). So
/// N runs per trial (estimator.repetitions) cost one simulation.
class SimulatedRobot final : public Robot
{
public:
    SimulatedRobot(std::shared_ptr<const RobotModel> model, Eigen::VectorXd truePhi,
                   MeasurementOptions options = {});

    void setFaults(const SimulatedFaults &faults) { m_faults = faults; }
    const SimulatedFaults &faults() const { return m_faults; }

    QString description() const override;
    TrialRecord runTrial(const TrialPlan &plan, const TrialMonitor &monitor) override;
    QString applyParameters(const Eigen::VectorXd &phi) override;
    Eigen::VectorXd storedParameters() const override { return m_stored; }
    std::optional<Eigen::VectorXd> trueParameters() const override { return m_truePhi; }

private:
    /// The run without torque noise.
    template <int N> TrialRecord simulate(const TrialPlan &plan, const TrialMonitor &monitor) const;
    /// The last run served again: noise-free samples up to where it ended, or up to a stop the
    /// monitor asks for, as simulate() would stop.
    TrialRecord replayLastRun(const TrialMonitor &monitor) const;
    bool faultsInjected() const;

    struct NoiseFreeRun
    {
        TrialPlan plan;
        TrialRecord record;
    };

    std::shared_ptr<const RobotModel> m_model;
    Eigen::VectorXd m_truePhi;
    MeasurementOptions m_options;
    SimulatedFaults m_faults;
    Eigen::VectorXd m_stored;
    quint64 m_trialCount = 0;
    std::optional<NoiseFreeRun> m_lastRun;
};

} // namespace learnid
