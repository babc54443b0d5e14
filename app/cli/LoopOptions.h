#pragma once

#include <QString>
#include <QStringList>

namespace learnid::cli {

struct CommandLine;

/// What `learnid-cli plan` or `learnid-cli learn` was asked to do (docs/cli.md). Output folders
/// are already absolute (resolveOutputPath against --workspace); input files are as given,
/// relative to the current directory.
struct LoopOptions
{
    QString scenarioPath;  ///< empty: the built-in paper scenario
    QString estimatePath;  ///< plan: --estimate; empty: the history's newest or the scenario's
    QString outDir;        ///< plan: --out, receives plan.csv and check.txt
    QStringList trialLogs; ///< learn: --trial-log, one per repetition
    QString historyDir;    ///< plan: default OUT/learnid-history; learn: the first log's folder's
    bool quiet = false;
};

/// The history folder's name when --history is not given, beside plan.csv or the log.
inline constexpr char defaultHistoryFolder[] = "learnid-history";

/// Parses `learnid-cli plan ...` or `learnid-cli learn ...` (args[1] is the command) into cl:
/// cl->loop and the command Plan or Learn, or Help with the command's usage, or an error with
/// its exit code (ExitUsage for a syntax error, an unknown option, no --out or no --trial-log;
/// ExitBadInput for an output path that cannot be used).
void parseLoopCommandLine(const QStringList &args, CommandLine *cl);

} // namespace learnid::cli
