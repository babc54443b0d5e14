#pragma once

#include "canrobot/CanRobotOptions.h"
#include "cli/IdentifyOptions.h"
#include "cli/LoopOptions.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>
#include <functional>
#include <optional>

namespace learnid::cli {

/// Exit codes of learnid-cli (docs/cli.md).
enum ExitCode {
    ExitOk = 0,
    ExitUsage = 1,       ///< unknown command or option
    ExitBadInput = 2,    ///< a file or value the tool cannot use; nothing was written
    ExitTrialFailed = 3, ///< a trial was refused, aborted or faulted; nothing was written
    ExitWriteFailed = 4, ///< an output could not be written; no output was left half-written
};

/// What `learnid-cli run` was asked to do. Output paths are already absolute (resolveOutputPath).
struct RunOptions
{
    QString scenarioPath;          ///< empty: the built-in paper scenario
    std::optional<QString> law;    ///< overrides estimator.law
    std::optional<int> iterations; ///< overrides estimator.iterations
    QString reportPath;
    QString exportPath;
    QString trialCsvDir;
    bool apply = false;
    bool consistent = false; ///< export and apply the nearest consistent estimate
    bool quiet = false;
    QString robot = QStringLiteral("sim"); ///< "sim", "can", or "replay" (`learnid-cli replay`)
    CanRobotOptions can;                   ///< --can-plugin, --can-interface, --nodes, --can-log
    bool nodesGiven = false;  ///< --nodes was set; else joint j is node j (checkCanAgainstScenario)
    QStringList candumpFiles; ///< `replay`: the trial logs, in trial order
};

/// The parsed command line: a command and its options, or an error to print with usage.
struct CommandLine
{
    enum class Command {
        None,
        PrintScenario,
        Run,
        Replay,
        Identify,
        Plan,
        Learn,
        Help,
        Version
    } command = Command::None;
    RunOptions run;
    IdentifyOptions identify;
    LoopOptions loop; ///< `plan` and `learn`
    /// `scenario --print --robot R`: paper, panda, puma560, double-pendulum or a URDF file;
    /// empty: the paper scenario.
    QString scenarioRobot;
    /// `scenario --print --payload ...`: a payload section, the gains for the arm carrying it.
    std::optional<PayloadOptions> scenarioPayload;
    /// `scenario --print --sample-period MS`: the robot's clock the gains must hold at [s].
    double scenarioSamplePeriod = 0.002;
    QString error;
    ExitCode errorCode = ExitUsage; ///< ExitUsage for syntax, ExitBadInput for a bad value
    QString usage;
};

/// Parses arguments (without the program name's special handling: args[0] is the program).
/// Relative output paths are taken from --workspace (default: the current directory); an error
/// names the option and the path. `COMMAND --help` gives Help with that command's usage.
CommandLine parseCommandLine(const QStringList &args);

/// A command's option; description is a QT_TRANSLATE_NOOP("learnid-cli", ...) text, translated
/// here; value names the option's argument (none: a switch).
QCommandLineOption cliOption(const char *name, const char *description,
                             const char *value = nullptr);

/// -h, --help: every command's.
QCommandLineOption helpOption();

/// The "Options:" part of the parser's help text, for a command's --help.
QString optionsHelp(const QCommandLineParser &parser);

/// A command's --help: "Usage: learnid-cli COMMAND [options]", the summary, optionsHelp().
QString commandHelp(const QString &command, const QString &summary,
                    const QCommandLineParser &parser);

/// Parses a command's arguments (args[1] is the command) with parser, whose options include
/// --help. Returns false when cl is complete: a syntax error or a positional argument (cl->error),
/// or --help (command Help, cl->usage = usage()). True: the caller reads the options.
bool parseCommandOptions(QCommandLineParser &parser, const QStringList &args, CommandLine *cl,
                         const std::function<QString()> &usage);

} // namespace learnid::cli
