#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QImage>
#include <QList>
#include <QString>
#include <QStringList>

namespace learnid {

/// The content of the one-page commissioning report, as text and images.
struct ReportContent
{
    QDateTime created;
    QString toolVersion;
    QString robot;
    QStringList scenario;    ///< "key: value" lines
    QStringList tableHeader; ///< the convergence table
    QList<QStringList> tableRows;
    QImage trackingPlot;
    QImage convergencePlot;
    QString appliedSet; ///< what the robot holds, in words
};

/// The report as PDF file content (A4 portrait, one page; QPdfWriter).
QByteArray commissioningReportPdf(const ReportContent &content);

} // namespace learnid
