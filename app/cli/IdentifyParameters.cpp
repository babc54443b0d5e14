#include "cli/IdentifyParameters.h"

#include "cli/IdentifyTable.h"

#include "model/ChainModel.h"
#include "service/StandardExport.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <limits>

namespace learnid::cli {

namespace {

QString cell(double v, int width)
{
    return (std::isfinite(v) ? QString::number(v, 'g', 5) : QStringLiteral("-"))
        .rightJustified(width);
}

} // namespace

QString parameterTable(const ChainModel &model, const LogFit &fit)
{
    const QList<ParameterInfo> info = model.standardParameters();
    int groupWidth = 0, nameWidth = 0;
    for (const ParameterInfo &p : info) {
        groupWidth = std::max(groupWidth, int(p.group.size()));
        nameWidth = std::max(nameWidth, int(p.name.size() + p.unit.size() + 3));
    }
    QString title = wrapText(QCoreApplication::translate(
        "learnid-cli",
        "standard parameters: the URDF's, the identified, and what the data determined (share of "
        "the parameter's direction; at least 0.5: the data's, below: undetermined, kept near the "
        "prior, which the data still move a little)"));
    title.chop(1);
    QStringList lines{
        title,
        QCoreApplication::translate("learnid-cli", "link or joint").leftJustified(groupWidth) +
            QLatin1Char(' ') +
            QCoreApplication::translate("learnid-cli", "parameter").leftJustified(nameWidth) +
            QLatin1Char(' ') +
            QCoreApplication::translate("learnid-cli", "URDF").rightJustified(12) +
            QLatin1Char(' ') +
            QCoreApplication::translate("learnid-cli", "identified").rightJustified(12) +
            QLatin1Char(' ') +
            QCoreApplication::translate("learnid-cli", "determined").rightJustified(10) +
            QLatin1Char(' ') + QCoreApplication::translate("learnid-cli", "source")};
    for (int i = 0; i < int(info.size()); ++i) {
        const ParameterInfo &p = info.at(i);
        const double share = size_t(i) < fit.standardDetermined.size()
                                 ? fit.standardDetermined[size_t(i)]
                                 : std::numeric_limits<double>::quiet_NaN();
        lines << p.group.leftJustified(groupWidth) + QLatin1Char(' ') +
                     QStringLiteral("%1 [%2]").arg(p.name, p.unit).leftJustified(nameWidth) +
                     QLatin1Char(' ') + cell(model.cadStandard()[i], 12) + QLatin1Char(' ') +
                     cell(fit.standard[i], 12) + QLatin1Char(' ') +
                     (std::isfinite(share) ? QString::number(share, 'f', 2) : QStringLiteral("-"))
                         .rightJustified(10) +
                     QLatin1Char(' ') +
                     parameterOriginText(parameterOrigin(fit.standardDetermined, i));
    }
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

QString modelWarningText(const QStringList &warnings, int width)
{
    QString text;
    for (const QString &w : warnings)
        text += wrapText(
            QCoreApplication::translate("learnid-cli", "warning: the URDF as a real robot: %1")
                .arg(w),
            width);
    return text;
}

} // namespace learnid::cli
