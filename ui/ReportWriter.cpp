#include "ui/ReportWriter.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

namespace learnid {

namespace {

// Draws the table into rect's width from rect.top(); returns the y below it.
int drawTable(QPainter &p, const QRect &rect, const QStringList &header,
              const QList<QStringList> &rows)
{
    if (header.isEmpty())
        return rect.top();
    const int columns = int(header.size());
    const int lineHeight = p.fontMetrics().height() * 13 / 10;
    const int columnWidth = rect.width() / columns;
    int y = rect.top();
    auto drawRow = [&](const QStringList &cells, bool bold) {
        QFont f = p.font();
        f.setBold(bold);
        p.setFont(f);
        for (int c = 0; c < columns && c < cells.size(); ++c) {
            const QRect cell(rect.left() + c * columnWidth, y, columnWidth - 20, lineHeight);
            p.drawText(cell, Qt::AlignRight | Qt::AlignVCenter | Qt::TextSingleLine, cells.at(c));
        }
        y += lineHeight;
    };
    drawRow(header, true);
    p.drawLine(rect.left(), y, rect.right(), y);
    for (const QStringList &row : rows)
        drawRow(row, false);
    return y;
}

// The parameters as rows, as many pages as they need, the header repeated on each.
void drawParameterPages(QPdfWriter &writer, QPainter &p, const ReportContent &c, int titleLine)
{
    const QRect page = p.viewport();
    QFont font = p.font();
    font.setPointSizeF(6.5);
    p.setFont(font);
    const int lineHeight = p.fontMetrics().height() * 13 / 10;
    const int perPage = std::max(1, (page.height() - 4 * titleLine) / lineHeight - 2);
    for (qsizetype first = 0; first < c.parameterRows.size(); first += perPage) {
        writer.newPage();
        QFont bold = font;
        bold.setPointSizeF(8.5);
        bold.setBold(true);
        p.setFont(bold);
        p.drawText(QRect(0, 0, page.width(), titleLine),
                   QCoreApplication::translate("learnid::ReportWriter", "Parameters"));
        p.setFont(font);
        drawTable(p, QRect(0, 2 * titleLine, page.width(), page.height() - 2 * titleLine),
                  c.parameterHeader, c.parameterRows.mid(first, perPage));
    }
}

} // namespace

QByteArray commissioningReportPdf(const ReportContent &c)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QPdfWriter writer(&buffer);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setResolution(300);
    writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    writer.setTitle(
        QCoreApplication::translate("learnid::ReportWriter", "learnid commissioning report"));
    writer.setCreator(QStringLiteral("learnid %1").arg(c.toolVersion));

    QPainter p(&writer);
    const QRect page = p.viewport();
    const int w = page.width();
    QFont font(QStringLiteral("Sans Serif"));
    font.setPointSizeF(14);
    font.setBold(true);
    p.setFont(font);
    int y = 0;
    const int titleHeight = p.fontMetrics().height();
    p.drawText(QRect(0, y, w, titleHeight), Qt::AlignLeft,
               QCoreApplication::translate("learnid::ReportWriter", "Commissioning report"));
    font.setPointSizeF(8.5);
    font.setBold(false);
    p.setFont(font);
    p.drawText(QRect(0, y, w, titleHeight), Qt::AlignRight | Qt::AlignBottom,
               c.created.toString(Qt::ISODate));
    y += titleHeight + 20;
    const int line = p.fontMetrics().height();
    p.drawText(QRect(0, y, w, line),
               QCoreApplication::translate("learnid::ReportWriter", "Robot: %1").arg(c.robot));
    y += line * 3 / 2;

    // Scenario in two columns.
    font.setBold(true);
    p.setFont(font);
    p.drawText(QRect(0, y, w, line),
               QCoreApplication::translate("learnid::ReportWriter", "Scenario"));
    font.setBold(false);
    p.setFont(font);
    y += line;
    const int half = int((c.scenario.size() + 1) / 2);
    for (int i = 0; i < c.scenario.size(); ++i) {
        const int x = i < half ? 0 : w / 2;
        const int row = i < half ? i : i - half;
        p.drawText(QRect(x, y + row * line, w / 2, line), Qt::TextSingleLine, c.scenario.at(i));
    }
    y += half * line + line / 2;

    font.setBold(true);
    p.setFont(font);
    p.drawText(QRect(0, y, w, line),
               QCoreApplication::translate("learnid::ReportWriter", "Parameter convergence"));
    y += line;
    font.setBold(false);
    font.setPointSizeF(c.tableHeader.size() > 10 ? 6.5 : 7.5);
    p.setFont(font);
    y = drawTable(p, QRect(0, y, w, page.height() - y), c.tableHeader, c.tableRows) + line;

    const int plotHeight = std::min(page.height() - y - 4 * line, w * 9 / 20);
    if (!c.trackingPlot.isNull() && plotHeight > 0) {
        const QRect left(0, y, w * 3 / 5 - 10, plotHeight);
        const QRect right(w * 3 / 5 + 10, y, w * 2 / 5 - 10, plotHeight);
        p.drawImage(left, c.trackingPlot);
        if (!c.convergencePlot.isNull())
            p.drawImage(right, c.convergencePlot);
        y += plotHeight + line;
    }
    font.setPointSizeF(8.5);
    p.setFont(font);
    p.drawText(
        QRect(0, y, w, 2 * line), Qt::TextWordWrap,
        QCoreApplication::translate("learnid::ReportWriter", "Applied set: %1").arg(c.appliedSet));
    p.drawText(
        QRect(0, page.height() - line, w, line), Qt::AlignRight,
        QCoreApplication::translate("learnid::ReportWriter", "learnid %1").arg(c.toolVersion));
    drawParameterPages(writer, p, c, line);
    p.end();
    return bytes;
}

} // namespace learnid
