#include "cli/RunCommandLine.h"

#include "cli/CliOptions.h"
#include "io/OutputPath.h"
#include "io/ParameterFile.h"
#include "model/Error.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>

namespace learnid::cli {

namespace {

// --robot and the CAN options; returns the error naming the option and value. An empty
// run->robot on return marks a usage error (an option that does not belong to the robot).
QString parseCanOptions(const QCommandLineParser &parser, const QCommandLineOption &robot,
                        const QCommandLineOption &plugin, const QCommandLineOption &interface,
                        const QCommandLineOption &nodes, bool replay, RunOptions *run)
{
    run->robot = replay ? QStringLiteral("replay")
                        : (parser.isSet(robot) ? parser.value(robot) : QStringLiteral("sim"));
    if (run->robot != QLatin1String("sim") && run->robot != QLatin1String("can") && !replay)
        return QCoreApplication::translate("learnid-cli",
                                           "--robot: must be 'sim' or 'can', got '%1'")
            .arg(run->robot);
    const bool can = run->robot == QLatin1String("can");
    if (!replay && !can) {
        for (const QCommandLineOption *o : {&plugin, &interface, &nodes}) {
            if (parser.isSet(*o)) {
                const QString name = o->names().constFirst();
                run->robot.clear();
                return QCoreApplication::translate("learnid-cli", "--%1 needs --robot can")
                    .arg(name);
            }
        }
        for (const char *name : {"can-log", "can-sync-timeout", "commission", "can-drives"}) {
            if (parser.isSet(QLatin1String(name))) {
                run->robot.clear();
                return QCoreApplication::translate("learnid-cli", "--%1 needs --robot can")
                    .arg(QLatin1String(name));
            }
        }
        return {};
    }
    if (can) {
        if (!parser.isSet(plugin) || parser.value(plugin).isEmpty())
            return QCoreApplication::translate(
                "learnid-cli", "--robot can needs --can-plugin (e.g. socketcan, virtualcan)");
        if (!parser.isSet(interface) || parser.value(interface).isEmpty())
            return QCoreApplication::translate("learnid-cli",
                                               "--robot can needs --can-interface (e.g. can0)");
        run->can.plugin = parser.value(plugin);
        run->can.interface = parser.value(interface);
        run->can.commissioning = parser.isSet(QStringLiteral("commission"));
        if (parser.isSet(QStringLiteral("can-drives"))) {
            const QString file = parser.value(QStringLiteral("can-drives"));
            try {
                run->can.recordedDrives = readParameterFile(file).drives;
            } catch (const Error &e) {
                return QCoreApplication::translate("learnid-cli", "--can-drives: %1")
                    .arg(e.message());
            }
            if (run->can.recordedDrives.isEmpty())
                return QCoreApplication::translate(
                           "learnid-cli", "--can-drives: %1 records no drives (robot.drives): "
                                          "export it from a session on CAN drives")
                    .arg(file);
        }
    } // a replay's device (candump/replay) is the robot factory's (makeRobot)
    if (parser.isSet(nodes)) {
        QString error;
        run->nodesGiven = true;
        run->can.nodes = parseNodeList(parser.value(nodes), &error);
        if (run->can.nodes.isEmpty())
            return QCoreApplication::translate("learnid-cli", "--nodes: %1 in '%2'")
                .arg(error, parser.value(nodes));
    }
    if (!replay && parser.isSet(QStringLiteral("can-sync-timeout"))) {
        const QString text = parser.value(QStringLiteral("can-sync-timeout"));
        bool ok = false;
        const int ms = text.trimmed().toInt(&ok);
        if (!ok || ms < 1 || ms > 60000)
            return QCoreApplication::translate(
                       "learnid-cli",
                       "--can-sync-timeout: must be a whole number of ms from 1 to 60000, got '%1'")
                .arg(text);
        setSyncTimeoutMs(run->can, ms);
    }
    // The bus load needs the scenario's SYNC period: checkCanAgainstScenario, once it is read.
    const QString invalid = canNodeOptionsError(run->can);
    if (!invalid.isEmpty())
        return parser.isSet(nodes) ? QCoreApplication::translate("learnid-cli", "--nodes %1: %2")
                                         .arg(parser.value(nodes), invalid)
                                   : QCoreApplication::translate("learnid-cli", "--robot %1: %2")
                                         .arg(run->robot, invalid);
    return {};
}

} // namespace

void parseRunCommandLine(const QStringList &args, CommandLine *cl)
{
    QCommandLineParser parser;
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help = helpOption();
    const QCommandLineOption scenario = cliOption(
        "scenario",
        QT_TRANSLATE_NOOP("learnid-cli",
                          "Scenario file (JSON, docs/scenario.md); default: the paper scenario."),
        "FILE");
    const QCommandLineOption estimator = cliOption(
        "estimator", QT_TRANSLATE_NOOP("learnid-cli", "Learning law: paper or improved."), "LAW");
    const QCommandLineOption iterations = cliOption(
        "iterations", QT_TRANSLATE_NOOP("learnid-cli", "Learning trials, 1 to 100."), "N");
    const QCommandLineOption report = cliOption(
        "report", QT_TRANSLATE_NOOP("learnid-cli", "Write the session report (JSON) to FILE."),
        "FILE");
    const QCommandLineOption exportFile = cliOption(
        "export",
        QT_TRANSLATE_NOOP("learnid-cli", "Write the parameter file (JSON and DCF) to FILE."),
        "FILE");
    const QCommandLineOption trialCsv = cliOption(
        "trial-csv",
        QT_TRANSLATE_NOOP("learnid-cli", "Write each trial's samples as CSV into DIR."), "DIR");
    const QCommandLineOption apply =
        cliOption("apply", QT_TRANSLATE_NOOP("learnid-cli",
                                             "Accept and apply the final estimate to the robot."));
    const QCommandLineOption consistent = cliOption(
        "consistent",
        QT_TRANSLATE_NOOP("learnid-cli", "Export and apply the nearest physically consistent "
                                         "estimate to the final one (URDF robots)."));
    const QCommandLineOption workspace = cliOption(
        "workspace",
        QT_TRANSLATE_NOOP(
            "learnid-cli",
            "Folder that relative output paths are taken from; default: the current directory."),
        "DIR");
    const QCommandLineOption quiet =
        cliOption("quiet", QT_TRANSLATE_NOOP("learnid-cli", "No progress lines on stderr."));
    const QCommandLineOption robot =
        cliOption("robot", QT_TRANSLATE_NOOP("learnid-cli", "sim (default) or can."), "R");
    const QCommandLineOption canPlugin = cliOption(
        "can-plugin",
        QT_TRANSLATE_NOOP("learnid-cli", "QCanBus plugin, e.g. socketcan or virtualcan."), "P");
    const QCommandLineOption canInterface = cliOption(
        "can-interface", QT_TRANSLATE_NOOP("learnid-cli", "CAN interface, e.g. can0."), "I");
    const QCommandLineOption nodes = cliOption(
        "nodes",
        QT_TRANSLATE_NOOP("learnid-cli", "CANopen node id of each joint's drive, e.g. 1,2."),
        "LIST");
    const QCommandLineOption canSyncTimeout =
        cliOption("can-sync-timeout",
                  QT_TRANSLATE_NOOP("learnid-cli", "Longest SYNC gap in a trial [ms]."), "MS");
    const QCommandLineOption canLog =
        cliOption("can-log",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Write each trial's CAN frames as a candump log into DIR."),
                  "DIR");
    const QCommandLineOption commission = cliOption(
        "commission",
        QT_TRANSLATE_NOOP("learnid-cli", "First commissioning: you confirmed that each node is the "
                                         "drive of its joint (docs/can-protocol.md 2.4)."));
    const QCommandLineOption canDrives =
        cliOption("can-drives",
                  QT_TRANSLATE_NOOP("learnid-cli", "A parameter file of this robot: its drives' "
                                                   "identities (0x1018) must match."),
                  "FILE");
    const QCommandLineOption candump =
        cliOption("candump",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "A recorded trial (candump log); once per trial, in order."),
                  "FILE");

    const QString command = args.at(1);
    const bool replay = command == QLatin1String("replay");

    parser.addOptions({scenario, estimator, iterations, report, exportFile, trialCsv, apply,
                       consistent, workspace, quiet, help});
    parser.addOption(nodes);
    if (replay)
        parser.addOption(candump);
    else
        parser.addOptions(
            {robot, canPlugin, canInterface, canLog, canSyncTimeout, commission, canDrives});
    const auto usage = [&] {
        return commandHelp(
            command,
            replay ? QCoreApplication::translate(
                         "learnid-cli",
                         "Re-identify from recorded trials: the session runs again with each log\n"
                         "answering in place of the robot.")
                   : QCoreApplication::translate(
                         "learnid-cli",
                         "Run a commissioning session on the simulated robot, or with --robot can\n"
                         "on CiA 402 drives on a CAN bus (docs/can-protocol.md)."),
            parser);
    };
    if (!parseCommandOptions(parser, args, cl, usage))
        return;
    RunOptions &run = cl->run;
    run.scenarioPath = parser.value(scenario);
    if (parser.isSet(estimator))
        run.law = parser.value(estimator);
    if (parser.isSet(iterations)) {
        bool ok = false;
        const int n = parser.value(iterations).toInt(&ok);
        if (!ok || n < 1 || n > 100) {
            cl->error =
                QCoreApplication::translate(
                    "learnid-cli", "--iterations: must be a whole number from 1 to 100, got '%1'")
                    .arg(parser.value(iterations));
            cl->errorCode = ExitBadInput;
            return;
        }
        run.iterations = n;
    }
    const QString canError =
        parseCanOptions(parser, robot, canPlugin, canInterface, nodes, replay, &run);
    if (!canError.isEmpty()) {
        cl->error = canError;
        cl->errorCode = run.robot.isEmpty() ? ExitUsage : ExitBadInput;
        return;
    }
    if (replay) {
        run.candumpFiles = parser.values(candump);
        if (run.candumpFiles.isEmpty()) {
            cl->error = QCoreApplication::translate("learnid-cli",
                                                    "'replay' needs at least one --candump FILE");
            return;
        }
        // --iterations against the trials the logs hold: runCommand, once they are read.
    }
    run.apply = parser.isSet(apply);
    run.consistent = parser.isSet(consistent);
    run.quiet = parser.isSet(quiet);
    const QString ws = parser.isSet(workspace) ? parser.value(workspace) : QDir::currentPath();
    try {
        if (parser.isSet(report))
            run.reportPath =
                resolveOutputPath(ws, parser.value(report), QStringLiteral("--report"));
        if (parser.isSet(exportFile))
            run.exportPath =
                resolveOutputPath(ws, parser.value(exportFile), QStringLiteral("--export"));
        if (parser.isSet(trialCsv))
            run.trialCsvDir =
                resolveOutputPath(ws, parser.value(trialCsv), QStringLiteral("--trial-csv"));
        if (!replay && parser.isSet(canLog))
            run.can.candumpDir =
                resolveOutputPath(ws, parser.value(canLog), QStringLiteral("--can-log"));
    } catch (const Error &e) {
        cl->error = e.message();
        cl->errorCode = ExitBadInput;
        return;
    }
    cl->command = replay ? CommandLine::Command::Replay : CommandLine::Command::Run;
}

} // namespace learnid::cli
