#pragma once

#include "identify/LogFit.h"

#include <QString>
#include <QStringList>

namespace learnid {
class ChainModel;
}

namespace learnid::cli {

/// The fit in a few lines: logs and samples used, the determined standard-parameter directions
/// and their condition, how many base parameters the data left undetermined, whether the
/// consistent fit converged, and the consistency verdict of the result (consistency: the lines
/// of EstimateConsistency::describe()).
QString identifySummary(const ChainModel &model, const LogFit &fit, int logs,
                        const QStringList &consistency);

/// One row per joint: the RMS of the fitted torque's residual on the --log files [N m].
QString trainingTable(const ChainModel &model, const LogFit &fit);

/// One row per joint for a --validate log: the RMS of the measured torque, then per model (the
/// URDF as given, the identified parameters) the RMS error [N m] and its ratio to the measured
/// RMS; then the overall sqrt(sum e^2 / sum tau^2) and the mean of the joint ratios, in %.
QString validationTable(const ChainModel &model, const QString &source, long long samples,
                        const TorqueFigures &given, const TorqueFigures &identified);

} // namespace learnid::cli
