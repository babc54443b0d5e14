#include "cli/ScenarioCommand.h"

#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "session/RobotScenario.h"

#include <QCoreApplication>

namespace learnid::cli {

ExitCode printScenarioCommand(const QString &robot, QTextStream &out, QTextStream &err)
{
    QByteArray json;
    try {
        // The window's starter for the robot: the same gains, path and limits it opens with.
        const Scenario scenario = robot.isEmpty() ? Scenario{} : scenarioForRobotName(robot);
        validateScenario(scenario);
        json = scenarioToJson(scenario);
    } catch (const Error &e) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: --robot %1: %2")
                   .arg(robot, e.message())
            << Qt::endl;
        return ExitBadInput;
    }
    out << QString::fromUtf8(json);
    return ExitOk;
}

} // namespace learnid::cli
