#pragma once

#include "service/LogIdentification.h"

#include <QString>
#include <QStringList>

namespace learnid {

/// An identification from logs in plain sentences, worded once for both front ends:
/// `learnid-cli identify` prints them (and its PDF report holds them), the window's "Identify
/// from recorded data" shows them as paragraphs. Each is a complete sentence.
struct LogIdentificationSummary
{
    /// `fr3.urdf (URDF robot "panda") in /home/lab/robots, 7 moving joints.`, or
    /// `panda (built-in), 7 moving joints.`
    QString robot;
    /// "Fitted to 1 log, 21000 samples; the consistent fit converged."
    QString logs;
    /// How the determined directions relate to the standard and base parameters: "Of the 91
    /// standard parameters, any data could determine at most 64 combinations (the base
    /// parameters); these logs determine 62 of those 64 directions (condition 35.2), the other 2
    /// stay near the URDF's values."
    QString directions;
    /// Which base parameters these logs leave mostly undetermined (kept near the URDF's values),
    /// by name, or that none is.
    QString undetermined;
    /// Per log the reader dropped rows of: "run1.csv: 1131 stale rows (values repeated under a
    /// new time stamp) treated as missing." (RobotLogCsv.h).
    QStringList readings;
};

/// The robot as the user named it: a built-in robot by its id, a URDF file by its file name with
/// the URDF's own robot name beside it when that differs from the file's base name
/// (`fr3.urdf (URDF robot "panda")`).
QString logRobotName(const LogRobot &robot);

LogIdentificationSummary summarizeLogIdentification(const LogIdentificationResult &result);

} // namespace learnid
