#include "ui/PlotImage.h"

#include <QBuffer>
#include <QPainter>
#include <QWidget>
#ifdef LEARNID_HAVE_SVG
#include <QSvgGenerator>
#endif

namespace learnid {

bool svgExportAvailable()
{
#ifdef LEARNID_HAVE_SVG
    return true;
#else
    return false;
#endif
}

namespace {

// Renders at a fixed size without disturbing the window: resize, render, restore.
template <typename Paint> void renderAt(QWidget *widget, QSize size, Paint paint)
{
    const QSize old = widget->size();
    if (size.isValid() && size != old)
        widget->resize(size);
    paint(widget->size());
    if (widget->size() != old)
        widget->resize(old);
}

} // namespace

QImage widgetImage(QWidget *widget, QSize size)
{
    QImage image;
    renderAt(widget, size, [&](QSize s) {
        image = QImage(s * 2, QImage::Format_ARGB32_Premultiplied);
        image.setDevicePixelRatio(2.0);
        image.fill(Qt::white);
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        widget->render(&painter, QPoint(), QRegion(), QWidget::DrawChildren);
    });
    return image;
}

QByteArray widgetPng(QWidget *widget, QSize size)
{
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    widgetImage(widget, size).save(&buffer, "PNG");
    return bytes;
}

QByteArray widgetSvg(QWidget *widget, const QString &title, QSize size)
{
#ifdef LEARNID_HAVE_SVG
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    renderAt(widget, size, [&](QSize s) {
        QSvgGenerator generator;
        generator.setOutputDevice(&buffer);
        generator.setSize(s);
        generator.setViewBox(QRect(QPoint(), s));
        generator.setTitle(title);
        QPainter painter(&generator);
        widget->render(&painter, QPoint(), QRegion(), QWidget::DrawChildren);
    });
    return bytes;
#else
    Q_UNUSED(widget)
    Q_UNUSED(title)
    Q_UNUSED(size)
    return {};
#endif
}

} // namespace learnid
