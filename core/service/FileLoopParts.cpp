#include "service/FileLoopParts.h"

#include "io/AtomicFile.h"
#include "io/ControllerLogCsv.h"
#include "io/PlanCsv.h"
#include "model/ChainModel.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <algorithm>

namespace learnid::loop {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(FileLoop)
};

} // namespace

QString native(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

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

QString trialFileName(int k, const QString &what)
{
    return QStringLiteral("trial-%1-%2.csv").arg(k, 3, 10, QLatin1Char('0')).arg(what);
}

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

TrialLogs readTrialLogs(const QStringList &paths)
{
    TrialLogs logs;
    for (const QString &path : paths) {
        logs.bytes << readFile(path);
        const QString id = planIdLine(logs.bytes.constLast(), native(path));
        if (id.isEmpty())
            throw Error(Text::tr("%1: no \"# plan-id:\" comment line; the controller copies the "
                                 "plan's \"# plan-id:\" line into its log")
                            .arg(native(path)));
        if (!logs.planId.isEmpty() && id != logs.planId)
            throw Error(Text::tr("%1 ran plan %2, %3 plan %4: the logs of one learning step are "
                                 "of one plan")
                            .arg(native(paths.constFirst()), logs.planId, native(path), id));
        logs.planId = id;
    }
    return logs;
}

LoopHistory newLoopHistory(const LoopScenario &s)
{
    LoopHistory history;
    history.robotModel = s.model->id();
    history.joints = s.model->dof();
    history.parameters = s.model->parameterCount();
    history.law = s.scenario.law;
    history.estimates << QStringLiteral("estimate-0.json");
    return history;
}

void addPlanFiles(PlannedTrial &planned, const LoopScenario &s, const PlanRequest &request,
                  LoopHistory history, const QByteArray *estimate0)
{
    const QByteArray plan = planCsv(planned.check.plan, s.model->id());
    planned.planId = planIdOf(planned.check.plan);
    const QDir out(request.outDir);
    const QDir dir(request.historyDir);
    LoopFiles &files = planned.files;
    files.folders << request.outDir << request.historyDir;
    files.files.append({out.filePath(QStringLiteral("plan.csv")), plan});
    files.files.append({out.filePath(QStringLiteral("check.txt")), planned.checkText.toUtf8()});
    if (estimate0) {
        // Plans made with another estimate 0 are not the history's any more.
        for (const LoopHistory::PendingPlan &p : std::as_const(history.pendingPlans))
            files.obsolete << dir.filePath(p.plan);
        history.pendingPlans.clear();
        files.files.append({dir.filePath(history.estimates.constFirst()), *estimate0});
    }
    const QString name = QStringLiteral("plan-%1.csv").arg(planned.planId.left(16));
    files.obsolete.removeAll(dir.filePath(name));
    const bool known = std::any_of(history.pendingPlans.cbegin(), history.pendingPlans.cend(),
                                   [&](const auto &p) { return p.planId == planned.planId; });
    if (!known)
        history.pendingPlans.append({planned.planId, name});
    files.files.append({dir.filePath(name), plan});
    files.files.append(
        {dir.filePath(QLatin1String(loopHistoryIndexName)), loopHistoryToJson(history)});
}

LoopHistory requireLoopHistory(const QString &dir)
{
    std::optional<LoopHistory> read = readLoopHistory(dir);
    if (!read)
        throw Error(Text::tr("%1 holds no learning history (no %2): plan the trial with "
                             "`learnid-cli plan` into this history, or give its --history")
                        .arg(native(dir), QLatin1String(loopHistoryIndexName)));
    return *read;
}

} // namespace learnid::loop
