#include "cli/IdentifyTable.h"

#include "model/ChainModel.h"

#include <QCoreApplication>
#include <QDir>
#include <algorithm>
#include <cmath>

namespace learnid::cli {

namespace {

QString number(double v, int decimals, int width)
{
    return (std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("-"))
        .rightJustified(width);
}

// The joint column: its number and the URDF joint's name, left-aligned to the longest name.
int nameWidth(const ChainModel &model)
{
    int width = int(QCoreApplication::translate("learnid-cli", "name").size());
    for (const ChainJoint &j : model.chain().joints)
        width = std::max(width, int(j.name.size()));
    return width;
}

QString jointCells(const ChainModel &model, int j, int width)
{
    return QString::number(j + 1).rightJustified(5) + QLatin1Char(' ') +
           model.chain().joints[size_t(j)].name.leftJustified(width);
}

QString jointHeader(int width)
{
    return QCoreApplication::translate("learnid-cli", "joint").rightJustified(5) +
           QLatin1Char(' ') +
           QCoreApplication::translate("learnid-cli", "name").leftJustified(width);
}

} // namespace

QString identifySummary(const ChainModel &model, const LogFit &fit, int logs,
                        const QStringList &consistency)
{
    QString text =
        QCoreApplication::translate(
            "learnid-cli",
            "fit: %1 logs, %2 samples; %3 of %4 standard-parameter directions determined "
            "(condition %5)\n"
            "fit: %6 of %7 base parameters undetermined (kept near the URDF's values); %8\n")
            .arg(logs)
            .arg(fit.samples)
            .arg(fit.rank)
            .arg(model.standardCount())
            .arg(fit.condition, 0, 'g', 3)
            .arg(fit.undetermined().size())
            .arg(fit.baseCount)
            .arg(fit.converged
                     ? QCoreApplication::translate("learnid-cli", "consistent fit converged")
                     : QCoreApplication::translate("learnid-cli",
                                                   "consistent fit stopped at its step limit"));
    text += QCoreApplication::translate("learnid-cli", "identified parameters: %1\n")
                .arg(consistency.join(QStringLiteral("; ")));
    return text;
}

QString trainingTable(const ChainModel &model, const LogFit &fit)
{
    const int width = nameWidth(model);
    QStringList lines{
        QCoreApplication::translate("learnid-cli", "training logs: residual of the fit"),
        jointHeader(width) + QLatin1Char(' ') +
            QCoreApplication::translate("learnid-cli", "RMS residual [N m]").rightJustified(18)};
    for (int j = 0; j < model.dof(); ++j)
        lines << jointCells(model, j, width) + QLatin1Char(' ') + number(fit.trainingRms[j], 4, 18);
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QString validationTable(const ChainModel &model, const QString &source, long long samples,
                        const TorqueFigures &given, const TorqueFigures &identified)
{
    const int width = nameWidth(model);
    const QString ratio = QCoreApplication::translate("learnid-cli", "ratio %");
    const QString error = QCoreApplication::translate("learnid-cli", "RMS error [N m]");
    const QString indent(6 + width + 1 + 18, QLatin1Char(' '));
    QStringList lines{
        QCoreApplication::translate("learnid-cli", "validation on %1 (%2 samples)")
            .arg(QDir::toNativeSeparators(source))
            .arg(samples),
        indent + QLatin1Char(' ') +
            QCoreApplication::translate("learnid-cli", "URDF as given").leftJustified(25) +
            QLatin1Char(' ') + QCoreApplication::translate("learnid-cli", "identified"),
        jointHeader(width) + QLatin1Char(' ') +
            QCoreApplication::translate("learnid-cli", "RMS measured [N m]").rightJustified(18) +
            QLatin1Char(' ') + error.rightJustified(16) + ratio.rightJustified(9) +
            QLatin1Char(' ') + error.rightJustified(16) + ratio.rightJustified(9)};
    for (int j = 0; j < model.dof(); ++j) {
        lines << jointCells(model, j, width) + QLatin1Char(' ') +
                     number(given.rmsMeasured[j], 4, 18) + QLatin1Char(' ') +
                     number(given.rmsError[j], 4, 16) + number(100.0 * given.ratio(j), 1, 9) +
                     QLatin1Char(' ') + number(identified.rmsError[j], 4, 16) +
                     number(100.0 * identified.ratio(j), 1, 9);
    }
    // The figure columns line up under the ratio columns.
    const int label = 6 + width + 1 + 18 + 1 + 16;
    lines << QCoreApplication::translate("learnid-cli", "overall sqrt(sum e^2 / sum tau^2) %")
                     .leftJustified(label) +
                 number(100.0 * given.overall, 3, 9) + QString(17, QLatin1Char(' ')) +
                 number(100.0 * identified.overall, 3, 9);
    lines << QCoreApplication::translate("learnid-cli", "mean of the joint ratios %")
                     .leftJustified(label) +
                 number(100.0 * given.meanRatio, 1, 9) + QString(17, QLatin1Char(' ')) +
                 number(100.0 * identified.meanRatio, 1, 9);
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace learnid::cli
