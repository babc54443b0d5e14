#pragma once

#include "cli/CliOptions.h"

#include <QTextStream>

namespace learnid::cli {

/// `learnid-cli plan`: plans and checks the next trial for the robot's own controller; writes
/// plan.csv and check.txt into --out and records the plan in the history, or refuses a plan
/// that fails the check (ExitTrialFailed, nothing written). The check goes to out.
ExitCode planCommand(const LoopOptions &options, QTextStream &out, QTextStream &err);

/// `learnid-cli learn`: learns from the controller's log of a plan of the history, writes the
/// new estimate into the history and prints the convergence table to out.
ExitCode learnCommand(const LoopOptions &options, QTextStream &out, QTextStream &err);

} // namespace learnid::cli
