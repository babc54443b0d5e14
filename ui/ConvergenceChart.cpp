#include "ui/ConvergenceChart.h"

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
                               const std::optional<Eigen::VectorXd> &truth)
{
    m_x->setRange(0, std::max<int>(1, int(estimates.size()) - 1));
    m_y->setTitleText(truth ? tr("|error| [%]") : tr("change [%]"));
    m_chart->setTitle(truth ? tr("Convergence to the truth") : tr("Convergence"));
    double lo = 1.0, hi = 100.0;
    for (int p = 0; p < parameters.size(); ++p) {
        QList<QPointF> points;
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
            percent = std::max(kFloorPercent, percent);
            lo = std::min(lo, percent);
            hi = std::max(hi, percent);
            points.append(QPointF(k, percent));
        }
        QLineSeries *series = seriesAt(p);
        series->setName(parameters.at(p).name);
        series->replace(points);
    }
    while (m_series.size() > parameters.size()) {
        QLineSeries *series = m_series.takeLast();
        m_chart->removeSeries(series);
        delete series;
    }
    m_y->setRange(std::pow(10.0, std::floor(std::log10(lo))),
                  std::pow(10.0, std::ceil(std::log10(hi))));
}

} // namespace learnid
