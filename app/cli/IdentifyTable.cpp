#include "cli/IdentifyTable.h"

#include "model/ChainModel.h"
#include "service/LogIdentificationSummary.h"
#include "session/LinkVerdictTable.h"

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

QString wrapText(const QString &text, int width)
{
    QStringList lines;
    QString line;
    for (const QString &word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        if (line.isEmpty()) {
            line = word;
        } else if (line.size() + 1 + word.size() > width) {
            lines << line;
            line = QStringLiteral("  ") + word;
        } else {
            line += QLatin1Char(' ') + word;
        }
    }
    lines << line;
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QString identifySummary(const LogIdentificationResult &result, int width)
{
    const LogIdentificationSummary s = summarizeLogIdentification(result);
    const QStringList sentences =
        QStringList{s.robot, s.logs} + s.readings +
        QStringList{s.directions, s.undetermined,
                    QCoreApplication::translate("learnid-cli", "Identified parameters: %1.")
                        .arg(result.consistency.join(QStringLiteral("; ")))};
    QString text;
    for (const QString &sentence : sentences)
        text += wrapText(sentence, width);
    return text;
}

QString verdictTable(const LogIdentificationResult &result, int width)
{
    const LinkVerdictTable table = linkVerdictTable(result.model(), result.verdict);
    return wrapText(table.title, width) + linkVerdictText(table);
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
