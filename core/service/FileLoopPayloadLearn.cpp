// `learnid-cli learn` with a payload section (FileLoop.h, docs/cli.md): a PayloadSession replayed
// over the history's trials and the new log, the logs answering in place of the robot.
#include "io/AtomicFile.h"
#include "io/ControllerLogCsv.h"
#include "io/PlanCsv.h"
#include "model/Error.h"
#include "service/FileLoopParts.h"
#include "service/FileLoopPayload.h"

#include <QCoreApplication>

namespace learnid::loop {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(FileLoop)
};

} // namespace

LearnedTrial learnPayloadTrial(const LoopScenario &s, const LearnRequest &request)
{
    const QDir dir(request.historyDir);
    const LoopHistory history = requireLoopHistory(request.historyDir);
    checkHistoryFits(history, request.historyDir, s);
    const QList<bool> angular = angularJoints(*s.model);

    // The new trial: one log (a payload session runs every trial once) of a pending plan.
    const TrialLogs logs = readTrialLogs(request.trialLogs);
    if (logs.bytes.size() != 1)
        throw Error(Text::tr("a payload's learning loop runs every trial once "
                             "(estimator.repetitions does not apply to it): give one "
                             "--trial-log, %1 given")
                        .arg(logs.bytes.size()));
    const QString source = native(request.trialLogs.constFirst());
    const LoopHistory::PendingPlan &pending =
        pendingPlan(history, request.historyDir, logs.planId, source);
    const QString planPath = dir.filePath(pending.plan);
    const QByteArray planBytes = readFile(planPath);
    const PlanCsv plan = readPlanCsv(planBytes, native(planPath));
    const ControllerLog log = readControllerLog(logs.bytes.constFirst(), source, plan, angular);
    QList<RecordedTrialRobot::Run> runs = historyRuns(history, dir, angular);
    runs.append({log.planId, log.record, source});

    // The session that ran these trials, replayed: its payload estimates are the loop's.
    LearnedTrial learned;
    learned.trialIndex = int(history.trials.size());
    learned.planId = logs.planId;
    PayloadReplay replay = payloadReplay(s, &history, request.historyDir, runs);
    const int newest = int(history.estimates.size()) - 1;
    for (int k = 0; k <= newest; ++k) {
        if (k > 0) // estimate k: once trial k - 1 is replayed
            replayHistoryTrials(replay, 1, request.historyDir);
        const QString differs =
            payloadEstimateDiffers(dir.filePath(history.estimates.at(k)), s, *replay.session, k);
        if (!differs.isEmpty())
            throw Error(differs);
    }
    const PayloadTrial &t = replay.session->runTrial();
    if (!replay.robot->mismatch().isEmpty())
        throw Error(replay.robot->mismatch());
    learned.payloadSession = std::move(replay.session);
    if (!t.usable()) {
        learned.failure = t.message;
        return learned;
    }

    // The new trial joins the history; plans made with the old estimate leave it.
    LoopHistory next = history;
    LoopHistory::Trial trial;
    trial.planId = logs.planId;
    trial.plan = trialFileName(learned.trialIndex, QStringLiteral("plan"));
    trial.logs << trialFileName(learned.trialIndex, QStringLiteral("log"));
    trial.maxTrackingErrorDeg = t.maxTrackingErrorDeg;
    trial.rmsTrackingErrorDeg = t.rmsTrackingErrorDeg;
    next.trials.append(trial);
    next.estimates.append(QStringLiteral("estimate-%1.json").arg(newest + 1));
    next.pendingPlans.clear();
    LoopFiles &files = learned.files;
    files.folders << request.historyDir;
    files.files.append({dir.filePath(trial.plan), planBytes});
    files.files.append({dir.filePath(trial.logs.constFirst()), logs.bytes.constFirst()});
    files.files.append({dir.filePath(next.estimates.constLast()),
                        payloadEstimateFile(s, *learned.payloadSession, newest + 1)});
    files.files.append(
        {dir.filePath(QLatin1String(loopHistoryIndexName)), loopHistoryToJson(next)});
    for (const LoopHistory::PendingPlan &p : history.pendingPlans)
        files.obsolete << dir.filePath(p.plan);
    return learned;
}

} // namespace learnid::loop
