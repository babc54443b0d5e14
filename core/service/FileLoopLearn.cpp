#include "service/FileLoop.h"

#include "io/AtomicFile.h"
#include "io/ControllerLogCsv.h"
#include "io/ParameterFile.h"
#include "io/PlanCsv.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "service/RecordedTrialRobot.h"
#include "service/SessionReport.h"

#include <QCoreApplication>
#include <QDir>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(FileLoop)
};

QString native(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

// Revolute joints, whose logs in degrees are refused; the paper's arm has only those.
QList<bool> angularJoints(const RobotModel &model)
{
    QList<bool> angular;
    if (const auto *chain = dynamic_cast<const ChainModel *>(&model)) {
        for (const ChainJoint &j : chain->chain().joints)
            angular << (j.type != JointType::Prismatic);
    } else {
        for (int j = 0; j < model.dof(); ++j)
            angular << true;
    }
    return angular;
}

QString trialName(int k, const QString &what)
{
    return QStringLiteral("trial-%1-%2.csv").arg(k, 3, 10, QLatin1Char('0')).arg(what);
}

// The plan the logs ran: a pending plan of the history, made with its newest estimate.
const LoopHistory::PendingPlan &pendingPlan(const LoopHistory &history, const QString &dir,
                                            const QString &planId, const QString &log)
{
    for (int k = 0; k < int(history.trials.size()); ++k) {
        if (history.trials.at(k).planId == planId)
            throw Error(Text::tr("%1 ran plan %2, which the history %3 has learned from already "
                                 "as trial %4: plan the next trial and run that")
                            .arg(native(log), planId, native(dir))
                            .arg(k));
    }
    for (const LoopHistory::PendingPlan &p : history.pendingPlans) {
        if (p.planId == planId)
            return p;
    }
    QStringList pending;
    for (const LoopHistory::PendingPlan &p : history.pendingPlans)
        pending << p.planId;
    throw Error(Text::tr("%1 ran plan %2, which the history %3 does not know; its plans to run "
                         "are: %4")
                    .arg(native(log), planId, native(dir),
                         pending.isEmpty() ? Text::tr("none (plan the next trial first)")
                                           : pending.join(QStringLiteral(", "))));
}

// The logged runs of the history's trials, oldest first, from its own copies.
QList<RecordedTrialRobot::Run> historyRuns(const LoopHistory &history, const QDir &dir,
                                           const QList<bool> &angular)
{
    QList<RecordedTrialRobot::Run> runs;
    for (int k = 0; k < int(history.trials.size()); ++k) {
        const LoopHistory::Trial &trial = history.trials.at(k);
        const PlanCsv plan = readPlanCsvFile(dir.filePath(trial.plan));
        if (plan.planId != trial.planId)
            throw Error(Text::tr("%1: plan %2 is not the plan %3 that trial %4 of the history ran")
                            .arg(native(dir.filePath(trial.plan)), plan.planId, trial.planId)
                            .arg(k));
        for (const QString &name : trial.logs) {
            const QString path = dir.filePath(name);
            const ControllerLog log = readControllerLogFile(path, plan, angular);
            if (!log.record.completed() && !log.record.stoppedAtTrackingLimit())
                throw Error(Text::tr("%1: %2").arg(native(path), log.record.message));
            runs.append({log.planId, log.record, native(path)});
        }
    }
    return runs;
}

} // namespace

LearnedTrial learnFromTrial(const LoopScenario &s, const LearnRequest &request)
{
    const QDir dir(request.historyDir);
    const std::optional<LoopHistory> read = readLoopHistory(request.historyDir);
    if (!read)
        throw Error(Text::tr("%1 holds no learning history (no %2): plan the trial with "
                             "`learnid-cli plan` into this history, or give its --history")
                        .arg(native(request.historyDir), QLatin1String(loopHistoryIndexName)));
    const LoopHistory &history = *read;
    checkHistoryFits(history, request.historyDir, s);
    const QList<bool> angular = angularJoints(*s.model);

    // The new trial: its logs, all of one pending plan, one per repetition.
    QList<QByteArray> logs;
    QString planId;
    for (const QString &path : request.trialLogs) {
        logs << readFile(path);
        const QString id = planIdLine(logs.constLast(), native(path));
        if (id.isEmpty())
            throw Error(Text::tr("%1: no \"# plan-id:\" comment line; the controller copies the "
                                 "plan's \"# plan-id:\" line into its log")
                            .arg(native(path)));
        if (!planId.isEmpty() && id != planId)
            throw Error(Text::tr("%1 ran plan %2, %3 plan %4: the logs of one learning step are "
                                 "of one plan")
                            .arg(native(request.trialLogs.constFirst()), planId, native(path), id));
        planId = id;
    }
    const int repetitions = std::max(1, s.scenario.repetitions);
    if (logs.size() != repetitions)
        throw Error(Text::tr("the scenario runs every trial %1 times (repetitions): give one "
                             "--trial-log per run, %2 given")
                        .arg(repetitions)
                        .arg(logs.size()));
    const LoopHistory::PendingPlan &pending =
        pendingPlan(history, request.historyDir, planId, request.trialLogs.constFirst());
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
    QList<RecordedTrialRobot::Run> runs = historyRuns(history, dir, angular);
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
    trial.plan = trialName(learned.trialIndex, QStringLiteral("plan"));
    for (int r = 0; r < int(logs.size()); ++r)
        trial.logs << trialName(learned.trialIndex, logs.size() == 1
                                                        ? QStringLiteral("log")
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
