#include "cli/ResultTable.h"

#include "session/ConvergenceFigures.h"

#include <QCoreApplication>
#include <QStringList>
#include <cmath>

namespace learnid::cli {

namespace {

QString cell(const QString &text, int width)
{
    return text.rightJustified(width);
}

QString number(double v, int decimals, int width)
{
    return cell(std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("-"), width);
}

} // namespace

namespace {

// Up to this many parameters the estimates are rows (the paper's Table 1); more, and the
// parameters become rows and the estimates columns, which stays readable for 50 parameters.
constexpr int maxParameterColumns = 4;

// One row per trial: its figures; then one row per parameter: its estimates.
QString transposedTable(const CommissioningSession &session)
{
    const RobotModel &model = session.model();
    const auto truth = session.robot().trueParameters();
    const int n = model.dof();
    const QVector<Eigen::VectorXd> &estimates = session.estimates();

    QStringList header{cell(QCoreApplication::translate("learnid-cli", "trial"), 5),
                       cell(QCoreApplication::translate("learnid-cli", "change %"), 9)};
    for (int j = 0; j < n; ++j)
        header << cell(QCoreApplication::translate("learnid-cli", "max|e|%1 deg").arg(j + 1), 12);
    header << cell(QCoreApplication::translate("learnid-cli", "T s"), 7)
           << cell(QCoreApplication::translate("learnid-cli", "cond"), 9)
           << cell(QCoreApplication::translate("learnid-cli", "rank"), 5);
    if (truth)
        header << cell(QCoreApplication::translate("learnid-cli", "path torque err %"), 17);
    QStringList lines{header.join(QLatin1Char(' '))};
    for (int row = 0; row < estimates.size(); ++row) {
        const Eigen::VectorXd &phi = estimates.at(row);
        const TrialResult *t = session.trialRunWith(row);
        QStringList cells{cell(QString::number(row), 5)};
        cells << (row == 0
                      ? cell(QStringLiteral("-"), 9)
                      : number(largestRelativeDifferencePercent(phi, estimates.at(row - 1)), 3, 9));
        for (int j = 0; j < n; ++j)
            cells << (t && t->maxTrackingErrorDeg.size() == n
                          ? number(t->maxTrackingErrorDeg[j], 5, 12)
                          : cell(QStringLiteral("-"), 12));
        cells << (t ? number(t->check.rule.duration, 3, 7) : cell(QStringLiteral("-"), 7));
        cells << (t && t->update ? number(t->update->condition, 1, 9)
                                 : cell(QStringLiteral("-"), 9));
        cells << (t && t->update ? cell(QString::number(t->update->rank), 5)
                                 : cell(QStringLiteral("-"), 5));
        if (truth) {
            const JointTrajectory &path = session.history().isEmpty()
                                              ? JointTrajectory()
                                              : session.history().constLast().plan().desired;
            cells << (path.samples() > 0
                          ? number(pathTorqueErrorPercent(model, path, phi, *truth), 4, 17)
                          : cell(QStringLiteral("-"), 17));
        }
        QString line = cells.join(QLatin1Char(' '));
        if (t && t->learnedFromPartial())
            line += QStringLiteral("  ") +
                    QCoreApplication::translate("learnid-cli", "learned from a partial trial");
        else if (t && !t->record.completed())
            line += QStringLiteral("  ") + trialStatusName(t->status());
        lines << line;
    }

    lines << QString();
    QStringList paramHeader{cell(QStringLiteral("#"), 3),
                            cell(QCoreApplication::translate("learnid-cli", "unit"), 9)};
    if (truth)
        paramHeader << cell(QCoreApplication::translate("learnid-cli", "truth"), 11);
    for (int row = 0; row < estimates.size(); ++row)
        paramHeader << cell(QCoreApplication::translate("learnid-cli", "est %1").arg(row), 11);
    paramHeader << QCoreApplication::translate("learnid-cli", "  parameter");
    lines << paramHeader.join(QLatin1Char(' '));
    const QList<ParameterInfo> params = model.parameters();
    for (int i = 0; i < params.size(); ++i) {
        QStringList cells{cell(QString::number(i + 1), 3), cell(params[i].unit, 9)};
        if (truth)
            cells << number((*truth)[i], 5, 11);
        for (const Eigen::VectorXd &phi : estimates)
            cells << number(phi[i], 5, 11);
        cells << QStringLiteral("  ") + params[i].name;
        lines << cells.join(QLatin1Char(' '));
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace

QString resultTable(const CommissioningSession &session)
{
    if (session.model().parameterCount() > maxParameterColumns)
        return transposedTable(session);
    const RobotModel &model = session.model();
    const auto truth = session.robot().trueParameters();
    const int n = model.dof();
    const QList<ParameterInfo> params = model.parameters();

    QStringList header{cell(QCoreApplication::translate("learnid-cli", "trial"), 5)};
    for (const ParameterInfo &p : params)
        header << cell(QStringLiteral("%1 [%2]").arg(p.name, p.unit), 12);
    header << cell(QCoreApplication::translate("learnid-cli", "change %"), 9);
    for (int j = 0; j < n; ++j)
        header << cell(QCoreApplication::translate("learnid-cli", "max|e|%1 deg").arg(j + 1), 12);
    header << cell(QCoreApplication::translate("learnid-cli", "T s"), 6)
           << cell(QCoreApplication::translate("learnid-cli", "cond"), 7);
    if (truth)
        header << cell(QCoreApplication::translate("learnid-cli", "vs truth %"), 10);
    QStringList lines{header.join(QLatin1Char(' '))};

    const QVector<Eigen::VectorXd> &estimates = session.estimates();
    for (int row = 0; row < estimates.size(); ++row) {
        const Eigen::VectorXd &phi = estimates.at(row);
        QStringList cells{cell(QString::number(row), 5)};
        for (Eigen::Index i = 0; i < phi.size(); ++i)
            cells << number(phi[i], 4, 12);
        cells << (row == 0
                      ? cell(QStringLiteral("-"), 9)
                      : number(largestRelativeDifferencePercent(phi, estimates.at(row - 1)), 3, 9));
        const TrialResult *t = session.trialRunWith(row); // the trial run with estimate k
        for (int j = 0; j < n; ++j)
            cells << (t && t->maxTrackingErrorDeg.size() == n
                          ? number(t->maxTrackingErrorDeg[j], 5, 12)
                          : cell(QStringLiteral("-"), 12));
        cells << (t ? number(t->check.rule.duration, 3, 6) : cell(QStringLiteral("-"), 6));
        cells << (t && t->update ? number(t->update->condition, 2, 7)
                                 : cell(QStringLiteral("-"), 7));
        if (truth)
            cells << number(largestRelativeDifferencePercent(phi, *truth), 3, 10);
        QString line = cells.join(QLatin1Char(' '));
        if (t && t->learnedFromPartial())
            line += QStringLiteral("  ") +
                    QCoreApplication::translate("learnid-cli", "learned from a partial trial");
        else if (t && !t->record.completed())
            line += QStringLiteral("  ") + trialStatusName(t->status());
        if (t && t->update && t->update->rank < phi.size())
            line += QStringLiteral("  ") +
                    QCoreApplication::translate("learnid-cli", "(rank %1: unobservable kept)")
                        .arg(t->update->rank);
        lines << line;
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QString trialSummary(const TrialResult &result)
{
    // A trial that did not complete ends the series: its reason follows as the error line.
    if (result.status() == TrialStatus::Refused)
        return QCoreApplication::translate("learnid-cli", "trial %1: %2")
            .arg(result.index)
            .arg(trialStatusName(result.status()));
    if (result.record.samples() == 0) {
        return QCoreApplication::translate("learnid-cli",
                                           "trial %1: %2, T = %3 s, no samples recorded")
            .arg(result.index)
            .arg(trialStatusName(result.status()))
            .arg(result.check.rule.duration, 0, 'f', 3);
    }
    QStringList errors;
    for (Eigen::Index j = 0; j < result.maxTrackingErrorDeg.size(); ++j)
        errors << QString::number(result.maxTrackingErrorDeg[j], 'f', 5);
    QString line =
        QCoreApplication::translate("learnid-cli",
                                    "trial %1: %2, T = %3 s, %4 samples, max tracking error %5 deg")
            .arg(result.index)
            .arg(trialStatusName(result.status()))
            .arg(result.check.rule.duration, 0, 'f', 3)
            .arg(result.record.samples())
            .arg(errors.join(QStringLiteral(" / ")));
    if (!result.message.isEmpty() && result.status() == TrialStatus::Completed)
        line += QStringLiteral(": ") + result.message;
    // A trial stopped by the tracking limit, learned from up to the stop or not: why.
    if (result.record.stoppedAtTrackingLimit()) {
        line += QStringLiteral(": ") + result.message;
        if (result.learnedFromPartial())
            line += QCoreApplication::translate("learnid-cli",
                                                "; learned from its first %1 s (a partial trial)")
                        .arg(result.partialSamples * result.record.samplePeriod, 0, 'f', 3);
    }
    for (const QString &note : {result.worseTracking, result.seriesStop})
        if (!note.isEmpty())
            line += QStringLiteral("\n") +
                    QCoreApplication::translate("learnid-cli", "learnid-cli: %1").arg(note);
    return line;
}

} // namespace learnid::cli
