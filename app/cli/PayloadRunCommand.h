#pragma once

#include "cli/CliOptions.h"
#include "service/RobotRequest.h"
#include "types/Scenario.h"

#include <QTextStream>

namespace learnid::cli {

/// `learnid-cli run --scenario FILE` for a scenario with a payload section: the payload learned
/// in the learning loop (PayloadSession, docs/payload.md) on the simulated robot, or on the CAN
/// robot of `robot` (--robot can: connected here, carrying the payload from its first trial),
/// the arm's model held fixed. Per trial on out: the tracking error, the payload's mass and
/// centre of mass and which of its values the trials identified; then the estimate's table.
/// --export and --trial-csv write their files; --report, --apply and --consistent are not
/// available with a payload yet.
ExitCode runPayloadCommand(const RunOptions &options, const Scenario &scenario,
                           const RobotRequest &robot, QTextStream &out, QTextStream &err);

} // namespace learnid::cli
