#include "ui/LogIdentificationText.h"

#include "service/LogIdentificationSummary.h"
#include "session/LinkVerdictTable.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(LogIdentificationText)
};

QString number(double v, char format, int precision)
{
    return QString::number(v, format, precision);
}

// The per-link verdict (LinkVerdictTable, the words of the CLI and its report) as an HTML table,
// the rows of links that are not plausible in the consistency paragraph's warning colour.
QString verdictHtml(const LogIdentificationResult &r)
{
    const LinkVerdictTable table = linkVerdictTable(r.model(), r.verdict);
    if (table.rows.isEmpty())
        return {};
    const auto row = [](const QStringList &cells, const QString &tag, const QString &style) {
        QString html = style.isEmpty() ? QStringLiteral("<tr>")
                                       : QStringLiteral("<tr style=\"%1\">").arg(style);
        for (int c = 0; c < cells.size(); ++c)
            html += QStringLiteral("<%1 align=\"%2\">%3</%1>")
                        .arg(tag, c == 0 ? QStringLiteral("left") : QStringLiteral("right"),
                             cells[c].toHtmlEscaped());
        return html + QStringLiteral("</tr>");
    };
    QString html = QStringLiteral("<p>%1</p><table cellspacing=\"0\" cellpadding=\"3\">")
                       .arg(table.title.toHtmlEscaped()) +
                   row(table.header, QStringLiteral("th"), {});
    for (int i = 0; i < table.rows.size(); ++i)
        html += row(table.rows[i], QStringLiteral("td"),
                    table.plausible[i] ? QString() : QStringLiteral("color:#b06000"));
    return html + QStringLiteral("</table>");
}

} // namespace

QString logIdentificationStageText(const LogIdentificationProgress &p)
{
    const QString index = QString::number(p.index + 1), count = QString::number(p.count);
    const QString file = QFileInfo(p.path).fileName();
    switch (p.stage) {
    case LogIdentificationStage::Robot:
        return Text::tr("Reading the robot %1\u2026").arg(p.path);
    case LogIdentificationStage::ReadTraining:
        return Text::tr("Reading training log %1 of %2: %3\u2026").arg(index, count, file);
    case LogIdentificationStage::ReadValidation:
        return Text::tr("Reading validation log %1 of %2: %3\u2026").arg(index, count, file);
    case LogIdentificationStage::Fit:
        return Text::tr("Fitting the parameters to %n log(s)\u2026", nullptr, p.count);
    case LogIdentificationStage::Validate:
        return Text::tr("Predicting validation log %1 of %2: %3\u2026").arg(index, count, file);
    }
    return {};
}

QString logIdentificationSummaryHtml(const LogIdentificationResult &r)
{
    const ChainModel &model = r.model();
    const LogIdentificationSummary s = summarizeLogIdentification(r);
    const auto paragraph = [](const QString &text) {
        return QStringLiteral("<p>%1</p>").arg(text.toHtmlEscaped());
    };
    QStringList residual;
    for (int j = 0; j < model.dof(); ++j)
        residual << QStringLiteral("%1: %2").arg(j + 1).arg(number(r.fit.trainingRms[j], 'f', 4));
    const QString consistency =
        Text::tr("<p><b>Identified parameters:</b> <span style=\"color:%1\">%2</span></p>")
            .arg(r.consistent && r.verdict.plausible ? QStringLiteral("#1e7b34")
                                                     : QStringLiteral("#b06000"),
                 r.consistency.join(QStringLiteral("; ")).toHtmlEscaped());
    const QString training = Text::tr("<p><b>Training residual</b>, RMS per joint [N m]: %1</p>")
                                 .arg(residual.join(QStringLiteral(", ")));
    QString readings;
    for (const QString &reading : s.readings)
        readings += paragraph(reading);
    // The URDF's own values as a real robot's (docs/robots.md §7): used as the prior all the same.
    QString warnings;
    for (const QString &w : r.robot.warnings)
        warnings += Text::tr("<p style=\"color:#8a5300\"><b>Warning:</b> the URDF as a real "
                             "robot: %1</p>")
                        .arg(w.toHtmlEscaped());
    return paragraph(s.robot) + warnings + paragraph(s.logs) + readings + paragraph(s.directions) +
           paragraph(s.undetermined) + consistency + verdictHtml(r) + training;
}

QString logIdentificationMessage(const LogIdentificationResult &r)
{
    if (r.validation.empty())
        return Text::tr("Identified; no validation log. Accept the result to export it.");
    const LogValidation &v = r.validation.front();
    return Text::tr(
               "Identified: on %1 the torque error is %2 % of the measured torque (URDF as given: "
               "%3 %). Accept the result to export it.")
        .arg(QFileInfo(v.source).fileName(), number(100.0 * v.identified.overall, 'f', 3),
             number(100.0 * v.given.overall, 'f', 3));
}

} // namespace learnid
