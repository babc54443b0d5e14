#pragma once

#include <QByteArray>
#include <QList>
#include <QString>

namespace learnid::cli {

/// The report of `learnid-cli identify --report FILE` as PDF file content: the title, the text
/// the command printed (fit, consistency, validation tables; monospace, so the columns stay
/// aligned; a line wider than the page broken at a space, its continuation indented), then each
/// plot (PNG content, torquePlotPng()) scaled to the page's width, on pages of its own. A4
/// portrait. Needs a QGuiApplication (imagesWanted()).
QByteArray identifyReportPdf(const QString &title, const QString &text,
                             const QList<QByteArray> &plots);

} // namespace learnid::cli
