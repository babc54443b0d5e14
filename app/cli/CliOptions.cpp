#include "cli/CliOptions.h"

#include "cli/RunCommandLine.h"

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
        "  learnid-cli scenario --print [--robot ROBOT]\n"
        "      Print a complete scenario as JSON. ROBOT: paper (the default: the paper\n"
        "      scenario), panda, puma560, double-pendulum or a URDF file; for a robot\n"
        "      other than paper, the gains the window designs for it and a path of\n"
        "      joint waypoints inside its limits. With --payload --payload-mass KG\n"
        "      [--payload-com X,Y,Z] [--payload-link LINK] ...: a scenario that learns\n"
        "      that payload, the gains designed for the arm carrying it. With\n"
        "      --sample-period MS: gains that hold at the robot's clock (default 2 ms).\n"
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
        "                       [--max-gap MS] [--torque-sensor-lag MS] [--base-link L]\n"
        "                       [--tip-link L] [--export FILE] [--urdf-out FILE] [--report FILE]\n"
        "                       [--plots DIR] [--scenario FILE] [--workspace DIR] [--quiet]\n"
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

} // namespace

QString commandHelp(const QString &command, const QString &summary,
                    const QCommandLineParser &parser)
{
    return QCoreApplication::translate("learnid-cli", "Usage: learnid-cli %1 [options]\n\n%2\n\n%3")
        .arg(command, summary, optionsHelp(parser));
}

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
    const QCommandLineOption help = helpOption();
    const QCommandLineOption print(
        QStringLiteral("print"),
        QCoreApplication::translate("learnid-cli", "Print the default scenario."));
    const QCommandLineOption robot(
        QStringLiteral("robot"),
        QCoreApplication::translate("learnid-cli",
                                    "The robot: paper (default), panda, puma560, double-pendulum, "
                                    "or a URDF file."),
        QStringLiteral("robot"));
    const QCommandLineOption samplePeriod(
        QStringLiteral("sample-period"),
        QCoreApplication::translate("learnid-cli",
                                    "The robot's clock in ms (default 2): the gains are designed "
                                    "to hold in discrete time at it."),
        QStringLiteral("ms"));
    if (command == QLatin1String("scenario")) {
        parser.addOptions({print, robot, samplePeriod, help});
        parser.addOptions(payloadCliOptions(false));
        if (!parser.parse(args.mid(1))) {
            cl.error = parser.errorText();
        } else if (parser.isSet(help)) {
            cl.command = CommandLine::Command::Help;
            cl.usage =
                commandHelp(command,
                            QCoreApplication::translate(
                                "learnid-cli", "Print a complete scenario for a robot as JSON."),
                            parser);
        } else if (!parser.isSet(print) || !parser.positionalArguments().isEmpty()) {
            cl.error = QCoreApplication::translate("learnid-cli", "'scenario' needs --print");
        } else if (const QString error = readPayloadOptions(parser, &cl.scenarioPayload, false);
                   !error.isEmpty()) {
            cl.error = error;
            cl.errorCode = ExitBadInput;
        } else {
            bool ok = true;
            const QString text = parser.value(samplePeriod);
            const double ms = parser.isSet(samplePeriod) ? text.toDouble(&ok) : 2.0;
            if (!ok || !std::isfinite(ms) || ms <= 0.0 || ms > 100.0) {
                cl.error = QCoreApplication::translate(
                               "learnid-cli",
                               "--sample-period: the robot's clock must be a number of ms above "
                               "0 and at most 100, not '%1'")
                               .arg(text);
                cl.errorCode = ExitBadInput;
                return cl;
            }
            cl.command = CommandLine::Command::PrintScenario;
            cl.scenarioRobot = parser.value(robot);
            cl.scenarioSamplePeriod = ms / 1000.0;
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
    if (command == QLatin1String("run") || command == QLatin1String("replay")) {
        parseRunCommandLine(args, &cl);
        return cl;
    }
    cl.error =
        command.isEmpty()
            ? QCoreApplication::translate("learnid-cli", "no command given")
            : QCoreApplication::translate("learnid-cli", "unknown command '%1'").arg(command);
    return cl;
}

QCommandLineOption helpOption()
{
    return QCommandLineOption(
        {QStringLiteral("h"), QStringLiteral("help")},
        QCoreApplication::translate("learnid-cli", "Show this command's options."));
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
