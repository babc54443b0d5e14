#pragma once

// The parts of the file loop (FileLoop.h) that the arm's loop (FileLoopPlan.cpp,
// FileLoopLearn.cpp) and the payload's (FileLoopPayload*.cpp) share. Internal to service.

#include "io/LoopHistory.h"
#include "model/RobotModel.h"
#include "service/FileLoop.h"
#include "service/RecordedTrialRobot.h"

#include <QByteArray>
#include <QDir>
#include <QList>
#include <QString>

namespace learnid::loop {

/// Revolute joints, whose logs in degrees are refused; the paper's arm has only those.
QList<bool> angularJoints(const RobotModel &model);

/// The history's name of a file of trial k: trial-000-plan.csv, trial-000-log.csv, ...
QString trialFileName(int k, const QString &what);

/// The plan the logs ran: a pending plan of the history. Throws Error naming the log when the
/// history has learned from that plan already or does not know it.
const LoopHistory::PendingPlan &pendingPlan(const LoopHistory &history, const QString &dir,
                                            const QString &planId, const QString &log);

/// The logged runs of the history's trials, oldest first, from its own copies. Throws Error
/// naming the file for a plan or log that does not read or is not the trial's.
QList<RecordedTrialRobot::Run> historyRuns(const LoopHistory &history, const QDir &dir,
                                           const QList<bool> &angular);

/// The new trial's logs as given: their bytes and the one plan-id they all name.
struct TrialLogs
{
    QList<QByteArray> bytes;
    QString planId;
};

/// Reads the logs and their `# plan-id:` lines. Throws Error naming the file for a log that
/// cannot be read, has no plan-id or names another plan than the first.
TrialLogs readTrialLogs(const QStringList &paths);

/// A new history of the scenario's robot and law, estimate 0 in estimate-0.json; the payload's
/// loop sets its payloadLink.
LoopHistory newLoopHistory(const LoopScenario &s);

/// The files of a plan that passed its check (planned.files): plan.csv and check.txt in the out
/// folder, the plan as pending in the history and the history's index; with estimate0 (a new
/// estimate 0) that file too, and the plans pending so far leave the history. Sets
/// planned.planId.
void addPlanFiles(PlannedTrial &planned, const LoopScenario &s, const PlanRequest &request,
                  LoopHistory history, const QByteArray *estimate0);

/// The history read for `learn`: throws Error when dir holds none.
LoopHistory requireLoopHistory(const QString &dir);

QString native(const QString &path);

/// planNextTrial() and learnFromTrial() for a scenario with a payload section
/// (FileLoopPayloadPlan.cpp, FileLoopPayloadLearn.cpp).
PlannedTrial planPayloadTrial(const LoopScenario &s, const PlanRequest &request);
LearnedTrial learnPayloadTrial(const LoopScenario &s, const LearnRequest &request);

} // namespace learnid::loop
