#include "cli/IdentifyReportPdf.h"

#include <QBuffer>
#include <QFontDatabase>
#include <QImage>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

namespace learnid::cli {

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
        if (y + line > page.height()) {
            writer.newPage();
            y = 0;
        }
        y += line;
        p.drawText(0, y, row);
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
