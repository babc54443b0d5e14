#pragma once

#include "robot/Robot.h"
#include "robot/SimulatedRobot.h"
#include "service/RobotRequest.h"
#include "types/Scenario.h"

#include <memory>

namespace learnid {

/// A robot made for a session. A CAN robot is connected already; `simulated` is the same
/// robot when it is the simulated one (to inject faults), else null.
struct RobotConnection
{
    std::shared_ptr<Robot> robot; ///< null when connecting failed
    std::shared_ptr<SimulatedRobot> simulated;
    QString connectError; ///< why the robot could not be reached
};

/// The one place robots are made, for the window and learnid-cli alike: the simulated robot of
/// the scenario, a CanRobot on the bus of request.can (connected here, so that an unreachable
/// bus is reported before a session starts), or a CanRobot whose bus replays candump logs.
/// Throws Error for input it cannot use (a candump log it cannot read, naming file and line);
/// an unreachable robot is no exception: connectError says why.
/// How many trials the replay of these candump logs plays (CandumpReplayDevice.h,
/// replayEntries). Throws Error naming the file and line of a log it cannot read.
int recordedTrialCount(const QStringList &candumpFiles);

RobotConnection makeRobot(const RobotRequest &request, const Scenario &scenario,
                          std::shared_ptr<const RobotModel> model);

} // namespace learnid
