#pragma once

#include "cli/CliOptions.h"

#include <QTextStream>

namespace learnid::cli {

/// `learnid-cli run` (and `replay`): a commissioning session on the simulated robot, the CAN
/// robot, or the CAN robot answered by recorded candump logs. Writes the table to out,
/// progress and errors to err, and the requested files only when every trial completed.
ExitCode runCommand(const RunOptions &options, QTextStream &out, QTextStream &err);

} // namespace learnid::cli
