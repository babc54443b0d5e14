#pragma once

#include "identify/LogFit.h"
#include "service/LogIdentification.h"

#include <QString>
#include <QStringList>

namespace learnid {
class ChainModel;
}

namespace learnid::cli {

/// The identification in a few lines (LogIdentificationSummary, the window's words): the robot,
/// logs and samples, how the determined directions relate to the standard and base parameters,
/// the base parameters the logs leave mostly undetermined, the consistency verdict of the result
/// and what the reader dropped from each log (before the fit). Sentences are wrapped at `width`
/// characters, their continuation lines indented by two spaces (the PDF report prints the lines as
/// they are).
QString identifySummary(const LogIdentificationResult &result, int width = 100);

/// text in lines of at most width characters (a longer word on a line of its own), the lines
/// after the first indented by two spaces, each ended by a newline.
QString wrapText(const QString &text, int width = 100);

/// One row per link (LinkVerdictTable): its smallest principal moment about the centre of mass
/// and the CAD link's, (I1 + I2) / I3, the centre of mass inside its bounding volume, consistent
/// and plausible; the title above wrapped at width.
QString verdictTable(const LogIdentificationResult &result, int width = 100);

/// One row per joint: the RMS of the fitted torque's residual on the --log files [N m].
QString trainingTable(const ChainModel &model, const LogFit &fit);

/// One row per joint for a --validate log: the RMS of the measured torque, then per model (the
/// URDF as given, the identified parameters) the RMS error [N m] and its ratio to the measured
/// RMS; then the overall sqrt(sum e^2 / sum tau^2) and the mean of the joint ratios, in %.
QString validationTable(const ChainModel &model, const QString &source, long long samples,
                        const TorqueFigures &given, const TorqueFigures &identified);

} // namespace learnid::cli
