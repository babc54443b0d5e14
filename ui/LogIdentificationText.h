#pragma once

#include "service/LogIdentification.h"

#include <QString>

namespace learnid {

/// What the "Recorded data" window says while a stage runs, e.g. "Reading training log 2 of 3:
/// trajectory_01.csv…".
QString logIdentificationStageText(const LogIdentificationProgress &progress);

/// The fit in a few paragraphs (rich text): the robot, logs and samples, the determined
/// directions and their condition, the consistency verdict, the undetermined base parameters
/// by name and the training residual per joint; the figures `learnid-cli identify` prints.
QString logIdentificationSummaryHtml(const LogIdentificationResult &result);

/// One line for the message bar: identified, and the first validation log's overall figure
/// against the URDF as given.
QString logIdentificationMessage(const LogIdentificationResult &result);

} // namespace learnid
