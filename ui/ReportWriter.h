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
    /// The parameters as rows (an n-joint arm), on pages after the first; empty: none.
    QStringList parameterHeader;
    QList<QStringList> parameterRows;
};

/// The report as PDF file content (A4 portrait, one page and the parameter pages; QPdfWriter).
QByteArray commissioningReportPdf(const ReportContent &content);

} // namespace learnid
