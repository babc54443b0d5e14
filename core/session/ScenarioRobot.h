#pragma once

#include "robot/SimulatedRobot.h"
#include "types/Scenario.h"

#include <memory>

namespace learnid {

/// The scenario with what a URDF robot leaves to the robot filled in (docs/scenario.md):
/// empty torqueLimits take the URDF's effort limits, empty initialParameters the CAD model's
/// base parameters, empty simulation.trueParameters the simulated real robot's (its own URDF,
/// simulation.realUrdf, or else the CAD robot perturbed by simulation.inertiaPerturbation with
/// simulation.seed). Other models return the scenario unchanged. Throws Error naming the key
/// when the URDF has no effort limit for a joint or the real robot's URDF does not fit: other
/// joints, or a robot that could not be built (modelProblems(): a link that is not a real or
/// plausible body, a negative friction, damping or armature; each named).
Scenario withRobotDefaults(const Scenario &scenario, const RobotModel &model);

/// The base parameters of the simulated robot a scenario describes: simulation.trueParameters
/// plus the payload it carries (simulation.payload, or the prior body), added to its link's body.
/// The simulated robot and learnid-robot-sim's drives (canArmSettings) move with these.
Eigen::VectorXd simulatedTrueParameters(const Scenario &scenario, const RobotModel &model);

/// The simulated robot a scenario describes: its true parameters and measurement options.
std::shared_ptr<SimulatedRobot> makeSimulatedRobot(const Scenario &scenario,
                                                   std::shared_ptr<const RobotModel> model);

/// The same simulated robot without the payload it carries (simulation.payload, or the prior
/// body): the robot of a payload session's baseline trials (payload.baselineTrials).
std::shared_ptr<SimulatedRobot> makeSimulatedBareRobot(const Scenario &scenario,
                                                       std::shared_ptr<const RobotModel> model);

} // namespace learnid
