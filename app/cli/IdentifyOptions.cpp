#include "cli/IdentifyOptions.h"

#include "cli/CliOptions.h"
#include "io/OutputPath.h"
#include "model/Error.h"
#include "service/SessionExport.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <cmath>
#include <optional>

namespace learnid::cli {

namespace {

// A finite number in (low, high); nullopt otherwise.
std::optional<double> numberIn(const QString &text, double low, double high)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v) || v <= low || v >= high)
        return std::nullopt;
    return v;
}

// --joint-terms: a comma-separated subset of armature, viscous, coulomb, offset, or "none".
QString parseJointTerms(const QString &text, JointTerms *terms)
{
    *terms = JointTerms{false, false, false, false};
    if (text.trimmed() == QLatin1String("none"))
        return {};
    for (const QString &entry : text.split(QLatin1Char(','))) {
        const QString name = entry.trimmed();
        if (name == QLatin1String("armature"))
            terms->armature = true;
        else if (name == QLatin1String("viscous"))
            terms->viscous = true;
        else if (name == QLatin1String("coulomb"))
            terms->coulomb = true;
        else if (name == QLatin1String("offset"))
            terms->offset = true;
        else
            return QCoreApplication::translate(
                       "learnid-cli",
                       "--joint-terms: unknown term '%1'; the terms are armature, viscous, "
                       "coulomb and offset, or none")
                .arg(name);
    }
    return {};
}

// The values of the options; an error names the option and the value.
QString readValues(const QCommandLineParser &parser, IdentifyOptions *o)
{
    const auto value = [&parser](const char *name) {
        return parser.value(QLatin1String(name));
    };
    const auto isSet = [&parser](const char *name) {
        return parser.isSet(QLatin1String(name));
    };
    if (isSet("columns"))
        o->columns = parseLogColumns(value("columns")); // throws "--columns: ..."
    if (isSet("joint-terms")) {
        const QString error = parseJointTerms(value("joint-terms"), &o->terms);
        if (!error.isEmpty())
            return error;
    }
    if (isSet("rho")) {
        const auto rho = numberIn(value("rho"), 0.0, HUGE_VAL);
        if (!rho)
            return QCoreApplication::translate("learnid-cli",
                                               "--rho: must be a positive number [rad/s], got '%1'")
                .arg(value("rho"));
        o->filter.rho = *rho;
    }
    if (isSet("prior-share")) {
        const auto share = numberIn(value("prior-share"), 0.0, 1.0);
        if (!share)
            return QCoreApplication::translate(
                       "learnid-cli", "--prior-share: must be a number between 0 and 1, got '%1'")
                .arg(value("prior-share"));
        o->fit.priorShare = *share;
    }
    if (isSet("velocity")) {
        const QString v = value("velocity");
        if (v == QLatin1String("auto"))
            o->filter.velocity = LogFilterSettings::Velocity::Auto;
        else if (v == QLatin1String("measured"))
            o->filter.velocity = LogFilterSettings::Velocity::Measured;
        else if (v == QLatin1String("q"))
            o->filter.velocity = LogFilterSettings::Velocity::FromPositions;
        else
            return QCoreApplication::translate("learnid-cli",
                                               "--velocity: must be auto, measured or q, got '%1'")
                .arg(v);
    }
    if (isSet("max-gap")) {
        const auto ms = numberIn(value("max-gap"), 0.0, 1e6);
        if (!ms)
            return QCoreApplication::translate(
                       "learnid-cli", "--max-gap: must be a positive number of ms, got '%1'")
                .arg(value("max-gap"));
        o->resample.maxGap = *ms / 1000.0;
    }
    if (isSet("torque-sensor-lag")) {
        bool ok = false; // 0 and 1000 included (numberIn's interval is open)
        const double ms = value("torque-sensor-lag").trimmed().toDouble(&ok);
        if (!ok || !(ms >= 0.0 && ms <= 1000.0))
            return QCoreApplication::translate("learnid-cli",
                                               "--torque-sensor-lag: must be a number of ms from "
                                               "0 to 1000, got '%1'")
                .arg(value("torque-sensor-lag"));
        o->filter.torqueSensorLag = ms / 1000.0;
    }
    const QString ws = isSet("workspace") ? value("workspace") : QDir::currentPath();
    if (isSet("export"))
        o->exportPath = resolveOutputPath(ws, value("export"), QStringLiteral("--export"));
    if (isSet("urdf-out"))
        o->urdfPath = resolveOutputPath(ws, value("urdf-out"), QStringLiteral("--urdf-out"));
    if (isSet("report"))
        o->reportPath = resolveOutputPath(ws, value("report"), QStringLiteral("--report"));
    if (isSet("plots"))
        o->plotsDir = resolveOutputPath(ws, value("plots"), QStringLiteral("--plots"));
    if (!o->urdfPath.isEmpty() &&
        (o->urdfPath == o->exportPath || o->urdfPath == dcfPathFor(o->exportPath)))
        return QCoreApplication::translate("learnid-cli", "--urdf-out: %1 is where --export writes")
            .arg(o->urdfPath);
    const QString payload = readPayloadOptions(parser, &o->payload);
    if (!payload.isEmpty())
        return payload;
    return {};
}

} // namespace

void parseIdentifyCommandLine(const QStringList &args, CommandLine *cl)
{
    QCommandLineParser parser;
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    parser.addOptions({
        cliOption("robot",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "A built-in URDF robot (e.g. double-pendulum) or a URDF file."),
                  "ROBOT"),
        cliOption("log",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "A recorded log (CSV) to identify from; once per log."),
                  "FILE"),
        cliOption("validate",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "A recorded log to check the result on; once per log."),
                  "FILE"),
        cliOption(
            "columns",
            QT_TRANSLATE_NOOP("learnid-cli",
                              "The log's column names, e.g. t=time,q=pos%1,dq=vel%1,tau=tau%1."),
            "SPEC"),
        cliOption(
            "joint-terms",
            QT_TRANSLATE_NOOP(
                "learnid-cli",
                "Joint terms to identify: armature, viscous, coulomb, offset, or none; default: "
                "viscous,coulomb,offset."),
            "LIST"),
        cliOption("rho",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Bandwidth of the zero-phase log filter [rad/s]; default 50."),
                  "R"),
        cliOption("prior-share",
                  QT_TRANSLATE_NOOP(
                      "learnid-cli",
                      "Directions weaker than this share of the strongest keep the URDF's values; "
                      "default 0.03."),
                  "S"),
        cliOption("velocity",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Joint velocities: auto, measured or q (from positions)."),
                  "V"),
        cliOption(
            "max-gap",
            QT_TRANSLATE_NOOP("learnid-cli",
                              "Longest time step allowed in a log [ms]; default half the time "
                              "constant 1/rho of the fit's filter (10 ms at rho 50), at least 2.5 "
                              "sample periods."),
            "MS"),
        cliOption("torque-sensor-lag",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "First-order lag of the torque sensors [ms], undone on the "
                                    "log's grid before the fit; default 0 (as measured)."),
                  "MS"),
        cliOption(
            "base-link",
            QT_TRANSLATE_NOOP("learnid-cli", "The chain's base link; default: the URDF's root."),
            "LINK"),
        cliOption("tip-link",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "The chain's tip link; default: the one leaf below the base."),
                  "LINK"),
        cliOption("export",
                  QT_TRANSLATE_NOOP(
                      "learnid-cli",
                      "Write the identified model as a parameter file (and DCF); it records "
                      "controller gains only with --scenario."),
                  "FILE"),
        cliOption("urdf-out",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Write the URDF with the identified inertia and friction."),
                  "FILE"),
        cliOption("report",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Write the report (PDF): the tables and the torque plots."),
                  "FILE"),
        cliOption(
            "plots",
            QT_TRANSLATE_NOOP("learnid-cli",
                              "Write the predicted and measured torque of each validation log "
                              "as PNG into this folder (made if missing)."),
            "DIR"),
        cliOption("scenario",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Scenario whose controller gains the parameter file records."),
                  "FILE"),
        cliOption(
            "workspace",
            QT_TRANSLATE_NOOP("learnid-cli", "Folder that relative output paths are taken from."),
            "DIR"),
        cliOption("quiet", QT_TRANSLATE_NOOP("learnid-cli", "No progress lines on stderr.")),
        helpOption(),
    });
    parser.addOptions(payloadCliOptions());
    const auto usage = [&] {
        return QCoreApplication::translate(
                   "learnid-cli",
                   "Usage: learnid-cli identify --robot ROBOT --log FILE [options]\n\n"
                   "Identify a robot's inertia and joint friction from its recorded logs,\n"
                   "and compare the result with the URDF as given on --validate logs.\n\n%1")
            .arg(optionsHelp(parser));
    };
    if (!parseCommandOptions(parser, args, cl, usage))
        return;
    IdentifyOptions &o = cl->identify;
    o.robot = parser.value(QStringLiteral("robot"));
    o.logs = parser.values(QStringLiteral("log"));
    if (o.robot.isEmpty() || o.logs.isEmpty()) {
        cl->error =
            o.robot.isEmpty()
                ? QCoreApplication::translate("learnid-cli", "'identify' needs --robot ROBOT")
                : QCoreApplication::translate("learnid-cli",
                                              "'identify' needs at least one --log FILE");
        return;
    }
    o.validationLogs = parser.values(QStringLiteral("validate"));
    o.baseLink = parser.value(QStringLiteral("base-link"));
    o.tipLink = parser.value(QStringLiteral("tip-link"));
    o.scenarioPath = parser.value(QStringLiteral("scenario"));
    o.quiet = parser.isSet(QStringLiteral("quiet"));
    try {
        cl->error = readValues(parser, &o);
    } catch (const Error &e) {
        cl->error = e.message();
    }
    if (!cl->error.isEmpty()) {
        cl->errorCode = ExitBadInput;
        return;
    }
    cl->command = CommandLine::Command::Identify;
}

} // namespace learnid::cli
