#pragma once

#include <limits>

namespace learnid {

/// Settings shared by the learning laws.
struct EstimatorSettings
{
    double rho = 40.0;           ///< bandwidth of F(s) = rho^3/(s + rho)^3 [rad/s]
    double rankTolerance = 1e-3; ///< relative singular value below which a direction is kept
    // Experiments on the observability rule (docs/benchmarks.md, "Realistic robots"; off by
    // default: neither carries every robot measured there):
    /// Decide observability on rows divided by each joint's measured torque level.
    bool jointLevelObservability = false;
    /// After a trial stopped early (a partial record), a direction whose standard deviation,
    /// relative to the parameters' scale, is above this is not learned from.
    double partialMaxRelativeStd = std::numeric_limits<double>::infinity();
    bool accumulate = true; ///< improved law: fit all valid trials so far, not the last
    /// The measured torques come from joint torque sensors behind the gears (docs/scenario.md,
    /// estimator.jointTorqueSensor): the improved law adds the rotor's torque, which such a
    /// sensor does not see, from the drive's command (identify/RotorTorque.h).
    bool jointTorqueSensor = false;
    /// The torque sensors' first-order lag [s] (docs/scenario.md, estimator.torqueSensorLag):
    /// the improved law undoes it on the recorded torques (identify/SensorLag.h); 0: none.
    double torqueSensorLag = 0.0;
};

} // namespace learnid
