#include "cli/CliOptions.h"

#include "io/OutputPath.h"
#include "model/Error.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <cmath>

namespace learnid::cli {

namespace {

QString usageText()
{
    return QCoreApplication::translate(
        "learnid-cli",
        "Usage:\n"
        "  learnid-cli scenario --print\n"
        "      Print the default scenario (the paper scenario) as JSON.\n"
        "  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]\n"
        "                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]\n"
        "                  [--consistent] [--workspace DIR] [--quiet]\n"
        "      Run a commissioning session on the simulated robot. The table goes to\n"
        "      stdout, progress to stderr. Relative output paths are taken from\n"
        "      --workspace (default: the current directory). Files are written only\n"
        "      when every trial completed.\n"
        "      --robot can --can-plugin P --can-interface I [--nodes 1,2] [--can-log DIR]\n"
        "      runs it on CiA 402 drives on a CAN bus instead (docs/can-protocol.md);\n"
        "      --can-log writes every trial's frames as a candump log into DIR;\n"
        "      --can-sync-timeout MS stops a trial when no SYNC comes for MS (default 20).\n"
        "  learnid-cli replay --candump FILE [--candump FILE2 ...] [--scenario FILE]\n"
        "                     [--estimator paper|improved] [--nodes 1,2] [--report FILE]\n"
        "                     [--export FILE] [--trial-csv DIR] [--workspace DIR] [--quiet]\n"
        "      Re-identify from recorded trials: the session runs again with each log\n"
        "      (one per trial, in order) answering in place of the robot.\n"
        "  learnid-cli identify --robot ROBOT --log FILE [--log FILE2 ...]\n"
        "                       [--validate FILE ...] [--columns SPEC] [--joint-terms LIST]\n"
        "                       [--rho R] [--prior-share S] [--velocity auto|measured|q]\n"
        "                       [--max-gap MS] [--base-link L] [--tip-link L] [--export FILE]\n"
        "                       [--urdf-out FILE] [--report FILE] [--plots DIR] [--scenario FILE]\n"
        "                       [--workspace DIR] [--quiet]\n"
        "      Identify a real robot's inertia and friction from its recorded logs (CSV)\n"
        "      and compare the result with its URDF on the --validate logs.\n"
        "  learnid-cli plan --out DIR [--scenario FILE] [--estimate FILE] [--history DIR]\n"
        "                   [--workspace DIR] [--quiet]\n"
        "      Plan the next trial for the robot's own controller: q_d(t) and tau_f(t)\n"
        "      (DIR/plan.csv) and the pre-trial check (DIR/check.txt).\n"
        "  learnid-cli learn --trial-log FILE [--scenario FILE] [--history DIR]\n"
        "                    [--workspace DIR] [--quiet]\n"
        "      Learn from the controller's log of a plan; the next plan uses the new\n"
        "      estimate.\n"
        "  learnid-cli COMMAND --help\n"
        "      The options of one command.\n");
}

// `learnid-cli COMMAND --help`: what the command does and its options, as the parser lists them.
QString commandHelp(const QString &command, const QString &summary,
                    const QCommandLineParser &parser)
{
    return QCoreApplication::translate("learnid-cli", "Usage: learnid-cli %1 [options]\n\n%2\n\n%3")
        .arg(command, summary, optionsHelp(parser));
}

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
        for (const char *name : {"can-log", "can-sync-timeout"}) {
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

CommandLine parseCommandLine(const QStringList &args)
{
    CommandLine cl;
    cl.usage = usageText();
    const QString command = args.size() > 1 ? args.at(1) : QString();
    if (command == QLatin1String("--help") || command == QLatin1String("-h") ||
        command == QLatin1String("help")) {
        cl.command = CommandLine::Command::Help;
        return cl;
    }
    if (command == QLatin1String("--version")) {
        cl.command = CommandLine::Command::Version;
        return cl;
    }

    QCommandLineParser parser;
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help(
        {QStringLiteral("h"), QStringLiteral("help")},
        QCoreApplication::translate("learnid-cli", "Show this command's options."));
    const QCommandLineOption print(
        QStringLiteral("print"),
        QCoreApplication::translate("learnid-cli", "Print the default scenario."));
    const QCommandLineOption scenario(
        QStringLiteral("scenario"),
        QCoreApplication::translate("learnid-cli",
                                    "Scenario file (JSON, docs/scenario.md); default: the "
                                    "paper scenario."),
        QStringLiteral("FILE"));
    const QCommandLineOption estimator(
        QStringLiteral("estimator"),
        QCoreApplication::translate("learnid-cli", "Learning law: paper or improved."),
        QStringLiteral("LAW"));
    const QCommandLineOption iterations(
        QStringLiteral("iterations"),
        QCoreApplication::translate("learnid-cli", "Learning trials, 1 to 100."),
        QStringLiteral("N"));
    const QCommandLineOption report(
        QStringLiteral("report"),
        QCoreApplication::translate("learnid-cli", "Write the session report (JSON) to FILE."),
        QStringLiteral("FILE"));
    const QCommandLineOption exportFile(
        QStringLiteral("export"),
        QCoreApplication::translate("learnid-cli",
                                    "Write the parameter file (JSON and DCF) to FILE."),
        QStringLiteral("FILE"));
    const QCommandLineOption trialCsv(
        QStringLiteral("trial-csv"),
        QCoreApplication::translate("learnid-cli", "Write each trial's samples as CSV into DIR."),
        QStringLiteral("DIR"));
    const QCommandLineOption apply(
        QStringLiteral("apply"),
        QCoreApplication::translate("learnid-cli",
                                    "Accept and apply the final estimate to the robot."));
    const QCommandLineOption consistent(
        QStringLiteral("consistent"),
        QCoreApplication::translate("learnid-cli",
                                    "Export and apply the nearest physically consistent "
                                    "estimate to the final one (URDF robots)."));
    const QCommandLineOption workspace(
        QStringLiteral("workspace"),
        QCoreApplication::translate("learnid-cli",
                                    "Folder that relative output paths are taken from; default: "
                                    "the current directory."),
        QStringLiteral("DIR"));
    const QCommandLineOption quiet(
        QStringLiteral("quiet"),
        QCoreApplication::translate("learnid-cli", "No progress lines on stderr."));
    const QCommandLineOption robot(
        QStringLiteral("robot"),
        QCoreApplication::translate("learnid-cli", "sim (default) or can."), QStringLiteral("R"));
    const QCommandLineOption canPlugin(
        QStringLiteral("can-plugin"),
        QCoreApplication::translate("learnid-cli", "QCanBus plugin, e.g. socketcan or virtualcan."),
        QStringLiteral("P"));
    const QCommandLineOption canInterface(
        QStringLiteral("can-interface"),
        QCoreApplication::translate("learnid-cli", "CAN interface, e.g. can0."),
        QStringLiteral("I"));
    const QCommandLineOption nodes(
        QStringLiteral("nodes"),
        QCoreApplication::translate("learnid-cli",
                                    "CANopen node id of each joint's drive, e.g. 1,2."),
        QStringLiteral("LIST"));
    const QCommandLineOption canSyncTimeout(
        QStringLiteral("can-sync-timeout"),
        QCoreApplication::translate("learnid-cli", "Longest SYNC gap in a trial [ms]."),
        QStringLiteral("MS"));
    const QCommandLineOption canLog(
        QStringLiteral("can-log"),
        QCoreApplication::translate("learnid-cli",
                                    "Write each trial's CAN frames as a candump log into DIR."),
        QStringLiteral("DIR"));
    const QCommandLineOption candump(
        QStringLiteral("candump"),
        QCoreApplication::translate("learnid-cli",
                                    "A recorded trial (candump log); once per trial, in order."),
        QStringLiteral("FILE"));

    if (command == QLatin1String("scenario")) {
        parser.addOptions({print, help});
        if (!parser.parse(args.mid(1))) {
            cl.error = parser.errorText();
        } else if (parser.isSet(help)) {
            cl.command = CommandLine::Command::Help;
            cl.usage = commandHelp(
                command,
                QCoreApplication::translate("learnid-cli", "Print the default scenario as JSON."),
                parser);
        } else if (!parser.isSet(print) || !parser.positionalArguments().isEmpty()) {
            cl.error = QCoreApplication::translate("learnid-cli", "'scenario' needs --print");
        } else {
            cl.command = CommandLine::Command::PrintScenario;
        }
        return cl;
    }
    if (command == QLatin1String("identify")) {
        parseIdentifyCommandLine(args, &cl);
        return cl;
    }
    if (command == QLatin1String("plan") || command == QLatin1String("learn")) {
        parseLoopCommandLine(args, &cl);
        return cl;
    }
    const bool replay = command == QLatin1String("replay");
    if (command != QLatin1String("run") && !replay) {
        cl.error =
            command.isEmpty()
                ? QCoreApplication::translate("learnid-cli", "no command given")
                : QCoreApplication::translate("learnid-cli", "unknown command '%1'").arg(command);
        return cl;
    }

    parser.addOptions({scenario, estimator, iterations, report, exportFile, trialCsv, apply,
                       consistent, workspace, quiet, help});
    parser.addOption(nodes);
    if (replay)
        parser.addOption(candump);
    else
        parser.addOptions({robot, canPlugin, canInterface, canLog, canSyncTimeout});
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
    if (!parseCommandOptions(parser, args, &cl, usage))
        return cl;
    RunOptions &run = cl.run;
    run.scenarioPath = parser.value(scenario);
    if (parser.isSet(estimator))
        run.law = parser.value(estimator);
    if (parser.isSet(iterations)) {
        bool ok = false;
        const int n = parser.value(iterations).toInt(&ok);
        if (!ok || n < 1 || n > 100) {
            cl.error =
                QCoreApplication::translate(
                    "learnid-cli", "--iterations: must be a whole number from 1 to 100, got '%1'")
                    .arg(parser.value(iterations));
            cl.errorCode = ExitBadInput;
            return cl;
        }
        run.iterations = n;
    }
    const QString canError =
        parseCanOptions(parser, robot, canPlugin, canInterface, nodes, replay, &run);
    if (!canError.isEmpty()) {
        cl.error = canError;
        cl.errorCode = run.robot.isEmpty() ? ExitUsage : ExitBadInput;
        return cl;
    }
    if (replay) {
        run.candumpFiles = parser.values(candump);
        if (run.candumpFiles.isEmpty()) {
            cl.error = QCoreApplication::translate("learnid-cli",
                                                   "'replay' needs at least one --candump FILE");
            return cl;
        }
        if (run.iterations && *run.iterations > run.candumpFiles.size()) {
            cl.error = QCoreApplication::translate("learnid-cli",
                                                   "--iterations: %1 trials need %1 logs, %2 given")
                           .arg(*run.iterations)
                           .arg(run.candumpFiles.size());
            cl.errorCode = ExitBadInput;
            return cl;
        }
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
        cl.error = e.message();
        cl.errorCode = ExitBadInput;
        return cl;
    }
    cl.command = replay ? CommandLine::Command::Replay : CommandLine::Command::Run;
    return cl;
}

QCommandLineOption cliOption(const char *name, const char *description, const char *value)
{
    const QString text = QCoreApplication::translate("learnid-cli", description);
    return value ? QCommandLineOption(QLatin1String(name), text, QLatin1String(value))
                 : QCommandLineOption(QLatin1String(name), text);
}

QString optionsHelp(const QCommandLineParser &parser)
{
    const QString text = parser.helpText();
    const qsizetype at = text.indexOf(QLatin1String("Options:"));
    return at >= 0 ? text.mid(at) : text;
}

bool parseCommandOptions(QCommandLineParser &parser, const QStringList &args, CommandLine *cl,
                         const std::function<QString()> &usage)
{
    if (!parser.parse(args.mid(1))) {
        cl->error = parser.errorText();
        return false;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        cl->command = CommandLine::Command::Help;
        cl->usage = usage();
        return false;
    }
    if (!parser.positionalArguments().isEmpty()) {
        cl->error = QCoreApplication::translate("learnid-cli", "unexpected argument '%1'")
                        .arg(parser.positionalArguments().constFirst());
        return false;
    }
    return true;
}

} // namespace learnid::cli
