#pragma once

#include "model/RobotModel.h"
#include "robot/Robot.h"

#include <memory>
#include <random>

namespace learnid {

/// How the simulated robot measures: encoder quantisation of q and white noise on tau.
struct MeasurementOptions
{
    qint64 encoderCounts = 0;  ///< counts per revolution; 0 = ideal angle measurement
    double torqueNoise = 0.0;  ///< standard deviation of torque noise as a fraction of the limit
    quint64 seed = 1;          ///< noise seed; trial i of a robot uses (seed, i)
    int substeps = 10;         ///< RK4 steps per sample period (0.2 ms at Ts = 2 ms)
};

/// Faults the simulated robot injects on request, so fault paths are tested without hardware.
/// Sample indices < 0 disable a fault.
struct SimulatedFaults
{
    int driveFaultAtSample = -1;      ///< the drive reports a fault and stops
    int nanTorqueAtSample = -1;       ///< the torque measurement of joint 0 turns NaN
    int disturbanceFromSample = -1;   ///< an external torque acts from this sample on
    Eigen::VectorXd disturbanceTorque; ///< [N m] (n)
    bool refuseApply = false;         ///< the controller refuses parameter writes
};

/// The robot as a simulation: the true dynamics integrated with RK4 at a sub-step of the sample
/// period, torque held over each sample, the joint PID of the plan, torque saturation.
class SimulatedRobot final : public Robot
{
public:
    SimulatedRobot(std::shared_ptr<const RobotModel> model, Eigen::VectorXd truePhi,
                   MeasurementOptions options = {});

    void setFaults(const SimulatedFaults &faults) { m_faults = faults; }

    QString description() const override;
    TrialRecord runTrial(const TrialPlan &plan, const TrialMonitor &monitor) override;
    QString applyParameters(const Eigen::VectorXd &phi) override;
    Eigen::VectorXd storedParameters() const override { return m_stored; }
    std::optional<Eigen::VectorXd> trueParameters() const override { return m_truePhi; }

private:
    template <int N>
    TrialRecord simulate(const TrialPlan &plan, const TrialMonitor &monitor,
                         std::mt19937_64 &rng) const;

    std::shared_ptr<const RobotModel> m_model;
    Eigen::VectorXd m_truePhi;
    MeasurementOptions m_options;
    SimulatedFaults m_faults;
    Eigen::VectorXd m_stored;
    quint64 m_trialCount = 0;
};

} // namespace learnid
