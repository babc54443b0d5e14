#include "cli/IdentifyReportPdf.h"

#include <QBuffer>
#include <QFontDatabase>
#include <QFontMetrics>
#include <QImage>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

namespace learnid::cli {

namespace {

// row as lines no wider than width on the page: broken at the last space that fits (or, without
// one, at the last character that fits), each continuation indented two spaces more than row.
QStringList fittingLines(const QString &row, const QFontMetrics &metrics, int width)
{
    QStringList lines;
    QString rest = row;
    int indent = 0;
    while (indent < rest.size() && rest[indent] == QLatin1Char(' '))
        ++indent;
    const QString continuation(indent + 2, QLatin1Char(' '));
    while (metrics.horizontalAdvance(rest) > width) {
        int fit = rest.size() - 1;
        while (fit > 1 && metrics.horizontalAdvance(rest.left(fit)) > width)
            --fit;
        const int space = rest.lastIndexOf(QLatin1Char(' '), fit);
        const int cut = space > continuation.size() ? space : fit;
        if (cut <= continuation.size())
            break; // nothing left to break at: draw the rest as it is
        lines << rest.left(cut);
        rest = continuation + rest.mid(cut).trimmed();
    }
    lines << rest;
    return lines;
}

} // namespace

QByteArray identifyReportPdf(const QString &title, const QString &text,
                             const QList<QByteArray> &plots)
{
    QByteArray pdf;
    QBuffer buffer(&pdf);
    buffer.open(QIODevice::WriteOnly);
    QPdfWriter writer(&buffer);
    writer.setPageSize(QPageSize(QPageSize::A4));
    writer.setResolution(150);
    writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    writer.setTitle(title);
    writer.setCreator(QStringLiteral("learnid-cli"));
    QPainter p(&writer);
    const QRect page = p.viewport();

    QFont heading = p.font();
    heading.setPointSize(14);
    heading.setBold(true);
    p.setFont(heading);
    int y = p.fontMetrics().height();
    p.drawText(QRect(0, 0, page.width(), y + 4), Qt::AlignLeft, title);
    y += p.fontMetrics().height() / 2;

    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mono.setPointSizeF(7.5);
    p.setFont(mono);
    const int line = p.fontMetrics().lineSpacing();
    for (const QString &row : text.split(QLatin1Char('\n'))) {
        for (const QString &part : fittingLines(row, p.fontMetrics(), page.width())) {
            if (y + line > page.height()) {
                writer.newPage();
                y = 0;
            }
            y += line;
            p.drawText(0, y, part);
        }
    }
    for (const QByteArray &png : plots) {
        QImage image;
        if (!image.loadFromData(png, "PNG"))
            continue;
        writer.newPage();
        const QSize size = image.size().scaled(page.size(), Qt::KeepAspectRatio);
        p.drawImage(QRect(QPoint(0, 0), size), image);
    }
    p.end();
    return pdf;
}

} // namespace learnid::cli
