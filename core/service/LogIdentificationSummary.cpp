#include "service/LogIdentificationSummary.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <algorithm>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(LogIdentificationSummary)
};

QString directionsText(int standard, int base, int rank, double condition)
{
    const QString cond = QString::number(condition, 'g', 3);
    if (rank >= base) {
        return Text::tr("Of the %1 standard parameters, any data could determine at most %2 "
                        "combinations (the base parameters); these logs determine all %2 "
                        "(condition %3).")
            .arg(QString::number(standard), QString::number(base), cond);
    }
    return Text::tr("Of the %1 standard parameters, any data could determine at most %2 "
                    "combinations (the base parameters); these logs determine %3 of those %2 "
                    "directions (condition %4), the other %n stay near the URDF's values.",
                    nullptr, base - rank)
        .arg(QString::number(standard), QString::number(base), QString::number(rank), cond);
}

QString undeterminedText(const LogIdentificationResult &r)
{
    const int base = r.fit.baseCount;
    const int missed = std::max(0, base - r.fit.rank);
    if (!r.undetermined.isEmpty()) {
        return Text::tr("%n of the %1 base parameters are mostly undetermined by these logs (less "
                        "than half determined) and kept near the URDF's values: %2.",
                        nullptr, int(r.undetermined.size()))
            .arg(QString::number(base), r.undetermined.join(QStringLiteral(", ")));
    }
    if (missed == 0) {
        return Text::tr("None of the %1 base parameters is mostly undetermined by these logs.")
            .arg(base);
    }
    return Text::tr("None of the %1 base parameters is mostly undetermined by these logs: the %n "
                    "direction(s) they miss are shared among several.",
                    nullptr, missed)
        .arg(base);
}

QString readingText(const LogReading &reading)
{
    QStringList parts;
    if (reading.stale > 0) {
        parts << Text::tr("%n stale row(s) (values repeated under a new time stamp) treated as "
                          "missing",
                          nullptr, reading.stale);
    }
    if (reading.repeated > 0) {
        parts << Text::tr("%n row(s) written twice (the same time stamp and values) dropped",
                          nullptr, reading.repeated);
    }
    return Text::tr("%1: %2.").arg(QFileInfo(reading.source).fileName(),
                                   parts.join(QStringLiteral("; ")));
}

} // namespace

QString logRobotName(const LogRobot &robot)
{
    if (robot.modelId != QLatin1String("urdf"))
        return robot.modelId;
    const QFileInfo file(robot.source);
    if (robot.chain.name.isEmpty() || robot.chain.name == file.completeBaseName())
        return file.fileName();
    return Text::tr("%1 (URDF robot \"%2\")").arg(file.fileName(), robot.chain.name);
}

LogIdentificationSummary summarizeLogIdentification(const LogIdentificationResult &r)
{
    const ChainModel &model = r.model();
    LogIdentificationSummary s;
    s.robot = r.robot.modelId == QLatin1String("urdf")
                  ? Text::tr("%1 in %2, %n moving joint(s).", nullptr, model.dof())
                        .arg(logRobotName(r.robot),
                             QDir::toNativeSeparators(QFileInfo(r.robot.source).absolutePath()))
                  : Text::tr("%1 (built-in), %n moving joint(s).", nullptr, model.dof())
                        .arg(logRobotName(r.robot));
    s.logs = Text::tr("Fitted to %n log(s), %1 samples; %2.", nullptr, int(r.trainingLogs.size()))
                 .arg(QString::number(r.fit.samples),
                      r.fit.converged ? Text::tr("the consistent fit converged")
                                      : Text::tr("the consistent fit stopped at its step limit"));
    s.directions =
        directionsText(model.standardCount(), r.fit.baseCount, r.fit.rank, r.fit.condition);
    s.undetermined = undeterminedText(r);
    for (const LogReading &reading : r.readings)
        if (reading.stale > 0 || reading.repeated > 0)
            s.readings << readingText(reading);
    return s;
}

} // namespace learnid
