#pragma once

#include "cli/CliOptions.h"

#include <QTextStream>

namespace learnid::cli {

/// `learnid-cli run`: a commissioning session on the simulated robot. Writes the table to out,
/// progress and errors to err, and the requested files only when every trial completed.
ExitCode runCommand(const RunOptions &options, QTextStream &out, QTextStream &err);

/// `learnid-cli scenario --print`.
ExitCode printScenarioCommand(QTextStream &out);

} // namespace learnid::cli
