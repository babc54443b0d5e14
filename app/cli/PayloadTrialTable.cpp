#include "cli/PayloadTrialTable.h"

#include "cli/PayloadCommand.h"

#include <QCoreApplication>

namespace learnid::cli {

namespace {

// The body values the trials identified, by name: "all", "none" or a list.
QString identifiedValues(const PayloadEstimate &e)
{
    QStringList names;
    const QStringList all = PayloadEstimate::bodyNames();
    for (int i = 0; i < 10; ++i)
        if (e.bodyIdentified[size_t(i)])
            names << all.at(i);
    if (names.size() == 10)
        return QCoreApplication::translate("learnid-cli", "all");
    return names.isEmpty() ? QCoreApplication::translate("learnid-cli", "none")
                           : names.join(QStringLiteral(", "));
}

} // namespace

QString payloadTrialHeader()
{
    return QCoreApplication::translate(
               "learnid-cli",
               "trial  max error  RMS error  mass [kg]  centre of mass [mm]    update  "
               "identified") +
           QLatin1Char('\n') +
           QCoreApplication::translate(
               "learnid-cli",
               "          [deg]      [deg]                                       [ms]") +
           QLatin1Char('\n');
}

QString payloadTrialRow(const PayloadTrial &t)
{
    QString row = QString::number(t.index).rightJustified(5);
    if (t.maxTrackingErrorDeg.size() > 0) {
        row += QString::number(t.maxTrackingErrorDeg.maxCoeff(), 'f', 4).rightJustified(12) +
               QString::number(t.rmsTrackingErrorDeg.maxCoeff(), 'f', 4).rightJustified(12);
    } else {
        row += QStringLiteral("-").rightJustified(12) + QStringLiteral("-").rightJustified(12);
    }
    if (t.baselineKept) {
        return row + QStringLiteral("  ") +
               QCoreApplication::translate("learnid-cli",
                                           "baseline: the same path without the payload");
    }
    if (!t.learned())
        return row + QStringLiteral("  ") + t.message;
    const PayloadBody &b = t.fit->estimate.body;
    const Eigen::Vector3d mm = 1000.0 * b.com;
    return row + QString::number(b.mass, 'f', 4).rightJustified(11) +
           QStringLiteral("  (%1, %2, %3)")
               .arg(mm.x(), 0, 'f', 1)
               .arg(mm.y(), 0, 'f', 1)
               .arg(mm.z(), 0, 'f', 1)
               .leftJustified(24) +
           QString::number(1000.0 * t.updateCpuSeconds, 'f', 1).rightJustified(8) +
           QStringLiteral("  ") + identifiedValues(t.fit->estimate) +
           (t.partial ? QCoreApplication::translate(
                            "learnid-cli", " (stopped at the limit: learned up to the stop)")
                      : QString());
}

QString payloadResult(const PayloadSession &session)
{
    const PayloadTrial *learned = nullptr;
    for (const PayloadTrial &t : session.history())
        if (t.learned())
            learned = &t;
    if (!learned)
        return {};
    return QCoreApplication::translate("learnid-cli", "The payload after trial %1 (bound: %2):")
               .arg(learned->index)
               .arg(session.prior().bound.describe()) +
           QLatin1Char('\n') +
           payloadTable(learned->fit->estimate,
                        QCoreApplication::translate("learnid-cli", "the trials"));
}

} // namespace learnid::cli
