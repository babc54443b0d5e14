#pragma once

#include "cli/CliOptions.h"
#include "types/Scenario.h"

#include <QTextStream>

namespace learnid::cli {

/// `learnid-cli run --scenario FILE` for a scenario with a payload section: the payload learned
/// in the learning loop on the simulated robot (PayloadSession, docs/payload.md), the arm's model
/// held fixed. Per trial on out: the tracking error, the payload's mass and centre of mass and
/// which of its values the trials identified; then the estimate's table. The CAN robot and the
/// output files (--report, --export, --trial-csv, --apply) are not available with a payload yet.
ExitCode runPayloadCommand(const RunOptions &options, const Scenario &scenario, QTextStream &out,
                           QTextStream &err);

} // namespace learnid::cli
