#pragma once

#include "cli/CliOptions.h"

#include <QTextStream>

namespace learnid::cli {

/// `learnid-cli scenario --print [--robot ROBOT]`: the complete scenario for the robot as JSON
/// on out (the paper scenario without --robot). A robot that is unknown or a URDF that cannot be
/// read is named on err with ExitBadInput, and nothing goes to out. samplePeriod: the robot's
/// clock [s], at which the designed gains must hold (scenarioForRobot()).
ExitCode printScenarioCommand(const QString &robot, const std::optional<PayloadOptions> &payload,
                              double samplePeriod, QTextStream &out, QTextStream &err);

} // namespace learnid::cli
