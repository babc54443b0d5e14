#include "cli/ScenarioCommand.h"

#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "session/RobotScenario.h"

#include <QCoreApplication>

namespace learnid::cli {

namespace {

// The scenario's payload section for the options' prior.
PayloadSettings payloadSettings(const PayloadOptions &o)
{
    PayloadSettings p;
    p.enabled = true;
    p.link = o.link;
    p.mass = o.prior.mass;
    p.com = o.prior.com;
    if (o.prior.inertiaAtCom) {
        const Eigen::Matrix3d &i = *o.prior.inertiaAtCom;
        p.inertia.resize(6);
        p.inertia << i(0, 0), i(0, 1), i(1, 1), i(0, 2), i(1, 2), i(2, 2);
    }
    if (o.prior.bound.box) {
        p.box.resize(6);
        p.box << o.prior.bound.lower, o.prior.bound.upper;
    } else {
        p.radius = o.prior.bound.radius;
    }
    return p;
}

} // namespace

ExitCode printScenarioCommand(const QString &robot, const std::optional<PayloadOptions> &payload,
                              double samplePeriod, QTextStream &out, QTextStream &err)
{
    QByteArray json;
    const QString name = robot.isEmpty() ? QStringLiteral("paper") : robot;
    try {
        // The window's starter for the robot: the same gains, path and limits it opens with.
        const Scenario scenario = scenarioForRobotName(
            name, payload ? payloadSettings(*payload) : PayloadSettings(), samplePeriod);
        validateScenario(scenario);
        json = scenarioToJson(scenario);
    } catch (const Error &e) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: --robot %1: %2")
                   .arg(name, e.message())
            << Qt::endl;
        return ExitBadInput;
    }
    out << QString::fromUtf8(json);
    return ExitOk;
}

} // namespace learnid::cli
