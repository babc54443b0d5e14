#include "ui/ReportContent.h"

#include "service/SessionController.h"
#include "ui/ApplyPreview.h"
#include "ui/ConvergenceChart.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/ParameterTableModel.h"
#include "ui/PlotImage.h"
#include "ui/TrackingErrorPlot.h"

#include <QCoreApplication>
#include <QtCharts/QChartView>

namespace learnid {

namespace {

// The texts were the FileController's, and keep its translations.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(learnid::FileController)
};

QString list(const Eigen::VectorXd &v)
{
    QStringList parts;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        parts << QString::number(v[i], 'g', 6);
    return parts.join(QStringLiteral(", "));
}

QString pathText(const Scenario &s)
{
    switch (s.path.kind) {
    case PathKind::Line:
        return Text::tr("Path: from (%1, %2) m, %3 m at %4 deg")
            .arg(s.line.start.x())
            .arg(s.line.start.y())
            .arg(s.line.length)
            .arg(s.line.directionDeg);
    case PathKind::Waypoints:
        return Text::tr("Path: %n joint waypoint(s)", nullptr, int(s.path.waypoints.size()));
    case PathKind::File:
        return Text::tr("Path: %1").arg(s.path.file);
    }
    return {};
}

void copyTable(const QAbstractItemModel &model, QStringList &header, QList<QStringList> &rows)
{
    for (int col = 0; col < model.columnCount(); ++col)
        header << model.headerData(col, Qt::Horizontal, Qt::DisplayRole).toString();
    for (int row = 0; row < model.rowCount(); ++row) {
        QStringList cells;
        for (int col = 0; col < model.columnCount(); ++col)
            cells << model.index(row, col).data().toString();
        rows << cells;
    }
}

} // namespace

ReportContent sessionReportContent(const SessionController &session, const ReportViews &views)
{
    const SessionInfo &info = *session.info();
    const Scenario &s = info.scenario;
    ReportContent c;
    c.created = QDateTime::currentDateTime();
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.robot = info.robotDescription;
    c.scenario = {
        pathText(s),
        Text::tr("Torque limits: %1 N m, planning fraction %2")
            .arg(list(s.torqueLimits))
            .arg(s.planningFraction),
        Text::tr("kp: %1 N m/rad; ki: %2").arg(list(s.controller.kp), list(s.controller.ki)),
        Text::tr("kd: %1 N m s/rad; lambda %2 rad/s")
            .arg(list(s.controller.kd))
            .arg(s.controller.lambda),
        s.controller.feedforwardTime == FeedforwardTime::MidSample
            ? Text::tr("Feedforward: model torque at the middle of each %1 ms sample")
                  .arg(s.controller.samplePeriod * 1e3)
            : Text::tr("Feedforward: model torque at each %1 ms sample's instant")
                  .arg(s.controller.samplePeriod * 1e3),
        Text::tr("Estimator: %1, rho %2 rad/s, %3 trials")
            .arg(s.law)
            .arg(s.estimator.rho)
            .arg(s.iterations),
        Text::tr("Initial parameters: %1").arg(parameterSetText(s.initialParameters)),
    };
    copyTable(*views.table, c.tableHeader, c.tableRows);
    if (info.parameters.size() > ConvergenceTableModel::maxParameterColumns && views.parameters)
        copyTable(*views.parameters, c.parameterHeader, c.parameterRows);
    c.trackingPlot = widgetImage(views.plot->chartView(), QSize(900, 560));
    c.convergencePlot = widgetImage(views.chart->chartView(), QSize(600, 560));
    const int stored = session.appliedEstimateIndex();
    c.appliedSet = session.storedParameters().size() == 0
                       ? Text::tr("none (nothing applied in this session)")
                       : Text::tr("%1 (estimate %2)")
                             .arg(parameterSetText(session.storedParameters()))
                             .arg(stored);
    return c;
}

} // namespace learnid
