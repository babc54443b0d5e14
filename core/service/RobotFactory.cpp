#include "service/RobotFactory.h"

#include "can/CandumpLog.h"
#include "canrobot/CanRobot.h"
#include "canrobot/CandumpReplayDevice.h"
#include "session/ScenarioRobot.h"

namespace learnid {

int recordedTrialCount(const QStringList &candumpFiles)
{
    int total = 0;
    for (const QString &file : candumpFiles) {
        int trials = 0;
        replayEntries(candump::readFile(file), &trials);
        total += trials;
    }
    return total;
}

RobotConnection makeRobot(const RobotRequest &request, const Scenario &scenario,
                          std::shared_ptr<const RobotModel> model)
{
    RobotConnection c;
    if (request.kind == RobotRequest::Kind::Simulated) {
        c.simulated = makeSimulatedRobot(scenario, std::move(model));
        c.robot = c.simulated;
        return c;
    }
    CanDeviceFactory factory; // empty: the plugin and interface of request.can
    if (request.kind == RobotRequest::Kind::Replay) {
        QList<CandumpEntry> entries;
        int trials = 0;
        for (const QString &file : request.candumpFiles) // throws Error naming file and line
            entries += replayEntries(candump::readFile(file), &trials);
        factory = [entries](QString *) {
            return new CandumpReplayDevice(entries);
        };
    }
    CanRobotOptions options = request.can;
    setSyncPeriod(options, scenario.controller.samplePeriod); // the bus load at the real cycle
    if (request.kind == RobotRequest::Kind::Replay)
        options = replayOptions(std::move(options));
    auto robot = std::make_shared<CanRobot>(std::move(model), options, std::move(factory));
    c.connectError = robot->connectBus();
    if (c.connectError.isEmpty())
        c.robot = std::move(robot);
    return c;
}

} // namespace learnid
