#include "ui/ConvergenceChart.h"

#include "ui/ConvergenceTableModel.h"

#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>
#include <cmath>

namespace learnid {

namespace {
const QColor kColors[] = {QColor(0x1f, 0x5f, 0xbf), QColor(0xc0, 0x39, 0x2b),
                          QColor(0x2e, 0x8b, 0x57), QColor(0x8e, 0x44, 0xad),
                          QColor(0xd3, 0x8b, 0x00)};
constexpr double kFloorPercent = 1e-3;
} // namespace

ConvergenceChart::ConvergenceChart(QWidget *parent)
    : QWidget(parent)
    , m_view(new QChartView(this))
    , m_chart(new QChart)
    , m_x(new QValueAxis(m_chart))
    , m_y(new QLogValueAxis(m_chart))
{
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_chart->setMargins(QMargins(2, 2, 2, 2));
    m_x->setTitleText(tr("Estimate k"));
    m_x->setLabelFormat(QStringLiteral("%d"));
    m_x->setTickType(QValueAxis::TicksDynamic);
    m_x->setTickAnchor(0);
    m_x->setTickInterval(1);
    m_y->setBase(10);
    m_y->setLabelFormat(QStringLiteral("%g"));
    m_chart->addAxis(m_x, Qt::AlignBottom);
    m_chart->addAxis(m_y, Qt::AlignLeft);
    // QChartView(QWidget *) makes a chart of its own, and setChart() only releases it.
    QChart *placeholder = m_view->chart();
    m_view->setChart(m_chart);
    delete placeholder;
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setMinimumSize(260, 200);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view);
    setData({}, {}, std::nullopt);
}

QLineSeries *ConvergenceChart::seriesAt(int p)
{
    // Reused, not re-created: re-creating series and axes re-lays the chart out every trial.
    while (m_series.size() <= p) {
        auto *series = new QLineSeries;
        QPen pen(kColors[m_series.size() % 5]);
        pen.setWidthF(1.6);
        series->setPen(pen);
        series->setPointsVisible(true);
        m_chart->addSeries(series);
        series->attachAxis(m_x);
        series->attachAxis(m_y);
        m_series.append(series);
    }
    return m_series.at(p);
}

void ConvergenceChart::setData(const QList<ParameterInfo> &parameters,
                               const QVector<Eigen::VectorXd> &estimates,
                               const std::optional<Eigen::VectorXd> &truth,
                               const EstimateFigures &figures)
{
    m_x->setRange(0, std::max<int>(1, int(estimates.size()) - 1));
    QList<Curve> curves = parameters.size() > ConvergenceTableModel::maxParameterColumns
                              ? pathTorqueCurves(figures)
                              : parameterCurves(parameters, estimates, truth);
    const bool many = parameters.size() > ConvergenceTableModel::maxParameterColumns;
    m_y->setTitleText(many ? tr("path torque [%]") : truth ? tr("|error| [%]") : tr("change [%]"));
    m_chart->setTitle(truth ? tr("Convergence to the truth") : tr("Convergence"));
    double lo = 1.0, hi = 100.0;
    for (int c = 0; c < curves.size(); ++c) {
        for (QPointF &point : curves[c].points) {
            point.setY(std::max(kFloorPercent, point.y()));
            lo = std::min(lo, point.y());
            hi = std::max(hi, point.y());
        }
        QLineSeries *series = seriesAt(c);
        series->setName(curves[c].name);
        series->replace(curves[c].points);
    }
    while (m_series.size() > curves.size()) {
        QLineSeries *series = m_series.takeLast();
        m_chart->removeSeries(series);
        delete series;
    }
    m_y->setRange(std::pow(10.0, std::floor(std::log10(lo))),
                  std::pow(10.0, std::ceil(std::log10(hi))));
}

QList<ConvergenceChart::Curve>
ConvergenceChart::parameterCurves(const QList<ParameterInfo> &parameters,
                                  const QVector<Eigen::VectorXd> &estimates,
                                  const std::optional<Eigen::VectorXd> &truth)
{
    QList<Curve> curves;
    for (int p = 0; p < parameters.size(); ++p) {
        Curve curve{parameters.at(p).name, {}};
        for (int k = 0; k < estimates.size(); ++k) {
            const Eigen::VectorXd &phi = estimates.at(k);
            if (p >= phi.size())
                continue;
            double percent = 0.0;
            if (truth && p < truth->size() && (*truth)[p] != 0.0)
                percent = 100.0 * std::abs(phi[p] - (*truth)[p]) / std::abs((*truth)[p]);
            else if (!truth && k > 0 && estimates.at(k - 1)[p] != 0.0)
                percent = 100.0 * std::abs(phi[p] - estimates.at(k - 1)[p]) /
                          std::abs(estimates.at(k - 1)[p]);
            else if (!truth)
                continue;
            curve.points.append(QPointF(k, percent));
        }
        curves.append(curve);
    }
    return curves;
}

// An n-joint arm: what the torques on the path say, not 50 parameter curves. Against the truth
// on a simulated robot; and against the newest estimate (how much each estimate still differs
// from where the trials arrived; the newest itself is 0 and left out).
QList<ConvergenceChart::Curve> ConvergenceChart::pathTorqueCurves(const EstimateFigures &figures)
{
    QList<Curve> curves;
    auto curve = [](const QString &name, const QVector<double> &values, int count) {
        Curve c{name, {}};
        for (int k = 0; k < count; ++k)
            if (std::isfinite(values.at(k)))
                c.points.append(QPointF(k, values.at(k)));
        return c;
    };
    if (!figures.vsTruth.isEmpty())
        curves << curve(tr("vs truth"), figures.vsTruth, int(figures.vsTruth.size()));
    if (figures.vsNewest.size() > 1)
        curves << curve(tr("vs newest estimate"), figures.vsNewest,
                        int(figures.vsNewest.size()) - 1);
    return curves;
}

} // namespace learnid
