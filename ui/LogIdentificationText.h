#pragma once

#include "service/LogIdentification.h"

#include <QString>

namespace learnid {

/// What the "Recorded data" window says while a stage runs, e.g. "Reading training log 2 of 3:
/// trajectory_01.csv…".
QString logIdentificationStageText(const LogIdentificationProgress &progress);

/// The fit in a few paragraphs (rich text): the sentences `learnid-cli identify` prints
/// (LogIdentificationSummary: the robot, logs and samples, how the determined directions relate
/// to the standard and base parameters, the base parameters left mostly undetermined by name,
/// the rows dropped from each log), the verdict on the identified parameters with its table per
/// link (LinkVerdictTable) and the training residual per joint.
QString logIdentificationSummaryHtml(const LogIdentificationResult &result);

/// One line for the message bar: identified, and the first validation log's overall figure
/// against the URDF as given.
QString logIdentificationMessage(const LogIdentificationResult &result);

} // namespace learnid
