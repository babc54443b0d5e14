#pragma once

#include "identify/LogFit.h"

#include <QString>
#include <QStringList>

namespace learnid {
class ChainModel;
}

namespace learnid::cli {

/// One row per standard parameter (ChainModel's layout): its link or joint, name and unit, the
/// URDF's value, the identified one, the share of its direction the data determined and where it
/// came from: "data" (share at least 0.5) or "undetermined (kept near the prior)": near the
/// URDF's value, not at it.
QString parameterTable(const ChainModel &model, const LogFit &fit);

/// The URDF's own values' problems as a real robot's (LogRobot::warnings), one "warning:"
/// sentence each, wrapped at width characters (wrapText()); empty without any.
QString modelWarningText(const QStringList &warnings, int width = 100);

} // namespace learnid::cli
