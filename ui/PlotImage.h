#pragma once

#include <QByteArray>
#include <QImage>
#include <QSize>

class QWidget;

namespace learnid {

/// Whether this build can write SVG (Qt6::Svg was found at configure time).
bool svgExportAvailable();

/// The widget drawn at `size` (its own size when empty), e.g. a chart view for the report.
QImage widgetImage(QWidget *widget, QSize size = {});
/// The widget as PNG file content.
QByteArray widgetPng(QWidget *widget, QSize size = {});
/// The widget as SVG file content (vector), or empty when SVG is not available.
QByteArray widgetSvg(QWidget *widget, const QString &title, QSize size = {});

} // namespace learnid
