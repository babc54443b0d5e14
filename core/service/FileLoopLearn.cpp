#include "service/FileLoop.h"

#include "io/AtomicFile.h"
#include "io/ControllerLogCsv.h"
#include "io/ParameterFile.h"
#include "io/PlanCsv.h"
#include "model/Error.h"
#include "service/FileLoopParts.h"
#include "service/SessionReport.h"

#include <QCoreApplication>
#include <QDir>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(FileLoop)
};

} // namespace

using loop::native;

LearnedTrial learnFromTrial(const LoopScenario &s, const LearnRequest &request)
{
    if (s.scenario.payload.enabled)
        return loop::learnPayloadTrial(s, request);
    const QDir dir(request.historyDir);
    const LoopHistory history = loop::requireLoopHistory(request.historyDir);
    checkHistoryFits(history, request.historyDir, s);
    const QList<bool> angular = loop::angularJoints(*s.model);

    // The new trial: its logs, all of one pending plan, one per repetition.
    const loop::TrialLogs trialLogs = loop::readTrialLogs(request.trialLogs);
    const QList<QByteArray> &logs = trialLogs.bytes;
    const QString &planId = trialLogs.planId;
    const int repetitions = std::max(1, s.scenario.repetitions);
    if (logs.size() != repetitions)
        throw Error(Text::tr("the scenario runs every trial %1 times (repetitions): give one "
                             "--trial-log per run, %2 given")
                        .arg(repetitions)
                        .arg(logs.size()));
    const LoopHistory::PendingPlan &pending =
        loop::pendingPlan(history, request.historyDir, planId, request.trialLogs.constFirst());
    const QString planPath = dir.filePath(pending.plan);
    const QByteArray planBytes = readFile(planPath);
    const PlanCsv plan = readPlanCsv(planBytes, native(planPath));
    const int newest = int(history.estimates.size()) - 1;
    const Eigen::VectorXd phiNewest = readEstimateFile(dir.filePath(history.estimates.constLast()),
                                                       *s.model, native(request.historyDir));
    if (plan.estimate.size() != phiNewest.size() || plan.estimate != phiNewest)
        throw Error(Text::tr("%1 was made with another estimate than the history's newest "
                             "(estimate %2): plan the next trial again")
                        .arg(native(planPath))
                        .arg(newest));

    LearnedTrial learned;
    learned.trialIndex = int(history.trials.size());
    learned.planId = planId;
    QList<RecordedTrialRobot::Run> runs = loop::historyRuns(history, dir, angular);
    for (int r = 0; r < int(logs.size()); ++r) {
        const QString source = native(request.trialLogs.at(r));
        const ControllerLog log = readControllerLog(logs.at(r), source, plan, angular);
        // A log that ended early is learned from only when it says the controller stopped the
        // trial at its tracking limit ("# stopped-by: tracking-limit"), as a session does.
        if (!log.record.completed() && !log.record.stoppedAtTrackingLimit()) {
            learned.failure =
                Text::tr("%1: %2; nothing learned").arg(source, asClause(log.record.message));
            return learned;
        }
        runs.append({log.planId, log.record, source});
    }

    // The session that ran these trials, replayed: its estimates are the loop's.
    Scenario scenario = s.scenario;
    scenario.initialParameters = readEstimateFile(dir.filePath(history.estimates.constFirst()),
                                                  *s.model, native(request.historyDir));
    auto robot = std::make_shared<RecordedTrialRobot>(runs);
    learned.session = std::make_unique<CommissioningSession>(scenario, s.model, robot);
    // Trial by trial (not runTrials): the loop's technician decides whether to go on after a
    // partial trial, so no series rule applies to the replay.
    for (int k = 0; k <= learned.trialIndex; ++k) {
        const TrialResult &t = learned.session->runTrial();
        if (!robot->mismatch().isEmpty())
            throw Error(robot->mismatch());
        if (t.learned())
            continue;
        if (k < learned.trialIndex)
            throw Error(Text::tr("the history %1 does not replay: trial %2: %3")
                            .arg(native(request.historyDir))
                            .arg(k)
                            .arg(t.message));
        learned.failure = t.message;
        return learned;
    }
    const TrialResult &last = learned.session->history().constLast();
    const QVector<Eigen::VectorXd> &estimates = learned.session->estimates();
    for (int k = 1; k <= newest; ++k) {
        const QString path = dir.filePath(history.estimates.at(k));
        if (readEstimateFile(path, *s.model, native(request.historyDir)) != estimates.at(k))
            throw Error(Text::tr("%1 is not the estimate %2 that the history's trials give with "
                                 "this scenario: is its estimator the history's?")
                            .arg(native(path))
                            .arg(k));
    }

    // The new trial joins the history; plans made with the old estimate leave it.
    LoopHistory next = history;
    LoopHistory::Trial trial;
    trial.planId = planId;
    trial.plan = loop::trialFileName(learned.trialIndex, QStringLiteral("plan"));
    for (int r = 0; r < int(logs.size()); ++r)
        trial.logs << loop::trialFileName(learned.trialIndex,
                                          logs.size() == 1 ? QStringLiteral("log")
                                                           : QStringLiteral("log-%1").arg(r + 1));
    trial.maxTrackingErrorDeg = last.maxTrackingErrorDeg;
    trial.rmsTrackingErrorDeg = last.rmsTrackingErrorDeg;
    next.trials.append(trial);
    next.estimates.append(QStringLiteral("estimate-%1.json").arg(newest + 1));
    next.pendingPlans.clear();
    LoopFiles &files = learned.files;
    files.folders << request.historyDir;
    files.files.append({dir.filePath(trial.plan), planBytes});
    for (int r = 0; r < int(logs.size()); ++r)
        files.files.append({dir.filePath(trial.logs.at(r)), logs.at(r)});
    files.files.append({dir.filePath(next.estimates.constLast()),
                        parameterFileToJson(parameterFileContent(*learned.session, newest + 1))});
    files.files.append(
        {dir.filePath(QLatin1String(loopHistoryIndexName)), loopHistoryToJson(next)});
    for (const LoopHistory::PendingPlan &p : history.pendingPlans)
        files.obsolete << dir.filePath(p.plan);
    return learned;
}

} // namespace learnid
