#pragma once

#include "robot/SimulatedRobot.h"
#include "types/Scenario.h"

#include <memory>

namespace learnid {

/// The simulated robot a scenario describes: its true parameters and measurement options.
std::shared_ptr<SimulatedRobot> makeSimulatedRobot(const Scenario &scenario,
                                                   std::shared_ptr<const RobotModel> model);

} // namespace learnid
