#include "io/ControllerLogCsv.h"

#include "io/AtomicFile.h"
#include "io/CsvPlace.h"
#include "io/RobotLogCsv.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QStringList>
#include <cmath>

namespace learnid {

namespace {

using csv::throwAtLine;

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ControllerLogCsv)
};

// A time for messages: 3 * 0.01 shows as 0.03, not 0.030000000000000002.
QString seconds(double t)
{
    return QString::number(t, 'g', 10);
}

// What the log's `# stopped-by:` line says stopped the trial (docs/file-formats.md,
// "Controller trial log"), and the line it is on; Other and 0 without one.
std::pair<TrialStopCause, int> stoppedBy(const QByteArray &csv, const QString &source)
{
    static const std::pair<const char *, TrialStopCause> known[] = {
        {"tracking-limit", TrialStopCause::TrackingLimit},
        {"fault", TrialStopCause::RobotFault},
        {"missing-samples", TrialStopCause::MissingSamples},
        {"operator", TrialStopCause::Operator},
        {"other", TrialStopCause::Other}};
    const QList<QByteArray> lines = csv.split('\n');
    for (int i = 0; i < int(lines.size()); ++i) {
        const QByteArray line = lines.at(i).trimmed();
        if (!line.startsWith('#'))
            continue;
        const QByteArray body = line.mid(1).trimmed();
        if (!body.startsWith("stopped-by:"))
            continue;
        const QByteArray value = body.mid(int(qstrlen("stopped-by:"))).trimmed();
        QStringList names;
        for (const auto &[name, cause] : known) {
            if (value == name)
                return {cause, i + 1};
            names << QLatin1String(name);
        }
        throwAtLine(source, i + 1,
                    Text::tr("\"# stopped-by:\" says %1; known: %2")
                        .arg(QString::fromUtf8(value).isEmpty() ? Text::tr("nothing")
                                                                : QString::fromUtf8(value),
                             names.join(QStringLiteral(", "))));
    }
    return {TrialStopCause::Other, 0};
}

} // namespace

ControllerLog readControllerLog(const QByteArray &csv, const QString &source, const PlanCsv &plan,
                                const QList<bool> &angular)
{
    ControllerLog log;
    log.planId = planIdLine(csv, source);
    if (log.planId.isEmpty())
        throw Error(Text::tr("%1: no \"# plan-id:\" comment line; the controller copies the "
                             "plan's line \"# plan-id: %2\" into its log")
                        .arg(source, plan.planId));
    if (log.planId != plan.planId)
        throw Error(Text::tr("%1: the log is of plan %2, not of plan %3")
                        .arg(source, log.planId, plan.planId));

    // Every sample of the plan's grid, as the controller took it: at rest a noise-free
    // simulation repeats its values exactly, and those rows are samples, not stale.
    const RobotLog robotLog =
        readRobotLog(csv, source, plan.joints(), LogColumns{}, angular, StaleRows::Keep);
    const double ts = plan.samplePeriod;
    const int planned = plan.samples();
    const int samples = int(robotLog.samples());
    for (int k = 0; k < samples; ++k) {
        const double t = robotLog.t[k];
        if (k >= planned)
            throwAtLine(source, robotLog.rows.at(size_t(k)),
                        Text::tr("sample %1 (t = %2 s) is beyond the plan's %3 samples, the last "
                                 "at t = %4 s")
                            .arg(k)
                            .arg(seconds(t))
                            .arg(planned)
                            .arg(seconds((planned - 1) * ts)));
        if (std::abs(t - k * ts) > controllerLogJitter * ts)
            throwAtLine(
                source, robotLog.rows.at(size_t(k)),
                Text::tr("t = %1 s is off the plan's grid: sample %2 is planned at t = %3 s "
                         "(+-%4 s); a log holds every sample of the plan, at the plan's "
                         "times")
                    .arg(seconds(t))
                    .arg(k)
                    .arg(seconds(k * ts), seconds(controllerLogJitter * ts)));
    }
    log.rows = robotLog.rows;
    log.record.samplePeriod = ts;
    log.record.q = robotLog.q;
    log.record.tau = robotLog.tau;
    const auto [cause, causeLine] = stoppedBy(csv, source);
    if (samples < planned) {
        log.record.status = TrialStatus::Aborted;
        log.record.stopCause = cause;
        log.record.message =
            cause == TrialStopCause::TrackingLimit
                ? Text::tr("the log ends after %1 of the plan's %2 samples (t = %3 s of %4 s): "
                           "the controller stopped the trial at its tracking limit")
                      .arg(samples)
                      .arg(planned)
                      .arg(seconds(robotLog.t[samples - 1]), seconds((planned - 1) * ts))
                : Text::tr("the log ends after %1 of the plan's %2 samples (t = %3 s "
                           "of %4 s): the trial ended early")
                      .arg(samples)
                      .arg(planned)
                      .arg(seconds(robotLog.t[samples - 1]), seconds((planned - 1) * ts));
    } else if (causeLine > 0) {
        throwAtLine(source, causeLine,
                    Text::tr("\"# stopped-by:\" in a log of all the plan's %1 samples: a trial "
                             "that ran to its end was not stopped")
                        .arg(planned));
    }
    return log;
}

ControllerLog readControllerLogFile(const QString &path, const PlanCsv &plan,
                                    const QList<bool> &angular)
{
    return readControllerLog(readFile(path), QDir::toNativeSeparators(path), plan, angular);
}

} // namespace learnid
