#pragma once

#include <QStringList>

namespace learnid::cli {

struct CommandLine;

/// Parses `learnid-cli run ...` or `learnid-cli replay ...` (args[1] is the command) into cl:
/// cl->run and the command Run or Replay, or Help with the command's usage, or an error with its
/// exit code (ExitUsage for a syntax error or an option that does not belong to the robot;
/// ExitBadInput for a bad value or an output path that cannot be used).
void parseRunCommandLine(const QStringList &args, CommandLine *cl);

} // namespace learnid::cli
