#pragma once

#include "io/PlanCsv.h"
#include "types/Trial.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace learnid {

/// How far a logged time stamp may lie from the plan's sample time k Ts, as a share of Ts.
constexpr double controllerLogJitter = 0.25;

/// A trial as a robot's own controller logged it while running a plan file (docs/file-formats.md,
/// "Controller trial log").
struct ControllerLog
{
    QString planId;     ///< the plan it ran, from its `# plan-id:` comment line
    TrialRecord record; ///< q and tau on the plan's grid; samplePeriod the plan's
    /// The CSV line number of each sample, for messages.
    std::vector<int> rows;
};

/// Reads a controller's log of a run of `plan`: a robot log CSV (io/RobotLogCsv.h, default
/// columns `t,q1..qn,tau1..taun`, other columns ignored) whose comment lines include the plan's
/// `# plan-id:` line. Sample k must be logged at t = k Ts within +-controllerLogJitter Ts; a row
/// repeating the values of the row before is a sample like any (StaleRows::Keep). A log
/// with fewer samples than the plan is a trial that ended early: its record is Aborted, with a
/// message saying where it ended, and the stop cause its `# stopped-by:` comment line names
/// (`tracking-limit`, `fault`, `missing-samples`, `operator`, `other`; Other without one). Only
/// `tracking-limit` lets the trial be learned from.
///
/// Throws Error as readRobotLog() does, and "<source>: ..." for a log without a plan-id line or
/// of another plan (naming both ids), "<source>: line <L>: ..." for a sample off the plan's grid
/// and for a sample beyond the plan's last, for an unknown `# stopped-by:` value and for one in a
/// log of all the plan's samples.
/// angular: as readRobotLog() (revolute joints: a log in degrees is refused).
ControllerLog readControllerLog(const QByteArray &csv, const QString &source, const PlanCsv &plan,
                                const QList<bool> &angular = {});

/// readFile() then readControllerLog() with the path as the source.
ControllerLog readControllerLogFile(const QString &path, const PlanCsv &plan,
                                    const QList<bool> &angular = {});

} // namespace learnid
