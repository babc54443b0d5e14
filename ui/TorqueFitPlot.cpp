#include "ui/TorqueFitPlot.h"

#include <QComboBox>
#include <QFontMetricsF>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QScopedValueRollback>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

// By Curve: measured dark grey, identified blue (on top), the URDF as given orange, dashed.
QPen curvePen(TorqueFitPlot::Curve curve)
{
    switch (curve) {
    case TorqueFitPlot::Curve::Measured:
        return QPen(QColor(0x4d, 0x4d, 0x4d), 1.0);
    case TorqueFitPlot::Curve::Identified:
        return QPen(QColor(0x1f, 0x5f, 0xbf), 1.6);
    case TorqueFitPlot::Curve::Given: {
        QPen pen(QColor(0xd3, 0x6b, 0x00), 1.3);
        pen.setStyle(Qt::DashLine);
        return pen;
    }
    }
    return {};
}

// A tick step of 1, 2 or 5 times a power of ten giving about `ticks` intervals over span.
double niceStep(double span, int ticks)
{
    const double raw = span / ticks;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0})
        if (m * power >= raw)
            return m * power;
    return 10.0 * power;
}

// A printf format that tells ticks `step` apart: as many decimals as the step needs (0.005:
// 3), or, for steps below 1e-4, as many significant digits as the largest value needs.
QString tickFormat(double step, double largest)
{
    const int decimals = std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
    if (decimals <= 4)
        return QStringLiteral("%.%1f").arg(decimals);
    const int digits = int(std::floor(std::log10(std::max(largest, step)) + 1e-9)) -
                       int(std::floor(std::log10(step) + 1e-9)) + 1;
    return QStringLiteral("%.%1g").arg(std::max(digits, 1));
}

constexpr TorqueFitPlot::Curve kDrawOrder[] = {
    TorqueFitPlot::Curve::Measured, TorqueFitPlot::Curve::Given, TorqueFitPlot::Curve::Identified};

// One legend entry: a short line in the curve's pen, then its name.
QWidget *legendEntry(TorqueFitPlot::Curve curve, const QString &text, QWidget *parent)
{
    QPixmap sample(28, 12);
    sample.fill(Qt::transparent);
    QPainter painter(&sample);
    painter.setRenderHint(QPainter::Antialiasing);
    QPen pen = curvePen(curve);
    pen.setWidthF(pen.widthF() + 0.8);
    painter.setPen(pen);
    painter.drawLine(QPointF(1, 6), QPointF(27, 6));
    painter.end();
    auto *entry = new QWidget(parent);
    auto *layout = new QHBoxLayout(entry);
    layout->setContentsMargins(0, 0, 8, 0);
    auto *icon = new QLabel(entry);
    icon->setPixmap(sample);
    layout->addWidget(icon);
    layout->addWidget(new QLabel(text, entry));
    return entry;
}

} // namespace

TorqueFitPlot::TorqueFitPlot(QWidget *parent)
    : QWidget(parent)
    , m_selection(new QComboBox(this))
    , m_empty(new QLabel(tr("Identify to see the predicted against the measured torque."), this))
    , m_grid(new QGridLayout)
    , m_legend(new QWidget(this))
    , m_timeTitle(new QLabel(tr("Time [s]"), this))
{
    m_selection->setObjectName(QStringLiteral("torquePlotJoint"));
    m_empty->setAlignment(Qt::AlignCenter);
    auto *legend = new QHBoxLayout(m_legend);
    legend->setContentsMargins(0, 0, 0, 0);
    legend->addWidget(legendEntry(Curve::Measured, tr("measured"), m_legend));
    legend->addWidget(legendEntry(Curve::Identified, tr("identified"), m_legend));
    legend->addWidget(legendEntry(Curve::Given, tr("URDF as given"), m_legend));
    legend->addStretch(1);
    auto *top = new QHBoxLayout;
    top->addWidget(m_legend, 1);
    top->addWidget(m_selection);
    m_grid->setSpacing(2);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(m_empty, 1);
    layout->addLayout(m_grid, 1);
    // One time axis for all charts: named once, under them, so that every chart has the same
    // height and their axes line up.
    m_timeTitle->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_timeTitle);
    connect(m_selection, &QComboBox::activated, this, &TorqueFitPlot::relayout);
    clear();
}

TorqueFitPlot::JointChart TorqueFitPlot::makeChart()
{
    JointChart c;
    c.view = new QChartView(this);
    c.chart = new QChart;
    // QChartView(QWidget *) makes a chart of its own, and setChart() only releases it.
    QChart *placeholder = c.view->chart();
    c.view->setChart(c.chart);
    delete placeholder;
    c.view->setRenderHint(QPainter::Antialiasing);
    c.view->setMinimumSize(220, 130);
    c.chart->legend()->hide();
    c.chart->setMargins(QMargins(2, 2, 2, 2));
    c.chart->setBackgroundRoundness(0);
    QFont title = c.chart->titleFont();
    title.setPointSizeF(title.pointSizeF() * 0.9);
    c.chart->setTitleFont(title);
    c.time = new QValueAxis(c.chart);
    c.torque = new QValueAxis(c.chart);
    QFont labels = c.time->labelsFont();
    labels.setPointSizeF(labels.pointSizeF() * 0.85);
    c.time->setLabelsFont(labels);
    c.torque->setLabelsFont(labels);
    c.time->setTickType(QValueAxis::TicksDynamic);
    c.torque->setTickType(QValueAxis::TicksDynamic);
    c.torque->setTickAnchor(0.0);
    c.chart->addAxis(c.time, Qt::AlignBottom);
    c.chart->addAxis(c.torque, Qt::AlignLeft);
    for (int i = 0; i < 3; ++i)
        c.series << nullptr;
    for (const Curve curve : kDrawOrder) {
        auto *series = new QLineSeries(c.chart);
        series->setPen(curvePen(curve));
        c.chart->addSeries(series);
        series->attachAxis(c.time);
        series->attachAxis(c.torque);
        c.series[int(curve)] = series;
    }
    return c;
}

void TorqueFitPlot::clear()
{
    for (const JointChart &c : m_joints)
        delete c.view; // deletes its chart, axes and series
    m_joints.clear();
    m_selection->clear();
    relayout();
}

void TorqueFitPlot::setData(const QStringList &jointNames, const Eigen::VectorXd &time,
                            const Eigen::MatrixXd &measured, const Eigen::MatrixXd &identified,
                            const Eigen::MatrixXd &given)
{
    const int n = int(jointNames.size());
    const Eigen::Index samples = time.size();
    if (measured.rows() != n || identified.rows() != n || given.rows() != n ||
        measured.cols() != samples || identified.cols() != samples || given.cols() != samples) {
        qWarning("TorqueFitPlot::setData: %d joints and %lld samples, torques %lld x %lld", n,
                 static_cast<long long>(samples), static_cast<long long>(measured.rows()),
                 static_cast<long long>(measured.cols()));
        return clear();
    }
    clear();
    m_selection->addItem(tr("All joints"), -1);
    const double t0 = samples > 0 ? time[0] : 0.0, t1 = samples > 0 ? time[samples - 1] : 1.0;
    for (int j = 0; j < n; ++j) {
        JointChart c = makeChart();
        const QString name = QStringLiteral("%1 %2").arg(j + 1).arg(jointNames.at(j));
        c.chart->setTitle(tr("Joint %1 [N m]").arg(name));
        m_selection->addItem(tr("Joint %1").arg(name), j);
        // The joint's own torques, not zero too: a small torque beside an offset (a wrist joint,
        // a friction offset) would be a flat line at the edge of a range from zero.
        double low = samples > 0 ? measured(j, 0) : 0.0, high = low;
        for (const auto &[curve, torque] :
             {std::pair{Curve::Measured, &measured}, std::pair{Curve::Identified, &identified},
              std::pair{Curve::Given, &given}}) {
            QList<QPointF> points;
            points.reserve(samples);
            for (Eigen::Index k = 0; k < samples; ++k)
                points.append(QPointF(time[k], (*torque)(j, k)));
            c.series[int(curve)]->replace(points);
            if (samples > 0) {
                low = std::min(low, torque->row(j).minCoeff());
                high = std::max(high, torque->row(j).maxCoeff());
            }
        }
        const double pad = 0.05 * std::max(high - low, 1e-6);
        low -= pad;
        high += pad;
        // The same time axis in every chart.
        const double span = t1 > t0 ? t1 - t0 : 1.0, step = niceStep(span, 6);
        c.time->setRange(t0, t0 + span);
        c.time->setTickAnchor(std::ceil(t0 / step) * step);
        c.time->setTickInterval(step);
        c.time->setLabelFormat(step >= 1.0 ? QStringLiteral("%.0f") : QStringLiteral("%.2g"));
        QChart *chart = c.chart;
        QValueAxis *axis = c.torque;
        connect(chart, &QChart::plotAreaChanged, axis, [axis, low, high](const QRectF &area) {
            fitTorqueTicks(axis, low, high, area.height());
        });
        fitTorqueTicks(axis, low, high, chart->plotArea().height());
        m_joints.append(c);
    }
    relayout();
}

void TorqueFitPlot::fitTorqueTicks(QValueAxis *axis, double low, double high, double height)
{
    // Qt Charts gives each label the height between two ticks and cuts a taller label to "…";
    // the ticks Qt's nice numbers chose left a short chart (seven joints on a laptop's screen)
    // with its labels cut, all but "0". So: as many ticks as there is room for, the step the
    // smallest of 1, 2 or 5 times a power of ten that needs no more, the range widened to whole
    // steps so that both ends carry a label.
    // A range set while the chart lays itself out lays it out again: once is enough.
    static bool fitting = false;
    if (fitting)
        return;
    const QScopedValueRollback<bool> guard(fitting, true);
    const double room = QFontMetricsF(axis->labelsFont()).height() + 8.0;
    const int ticks = std::max(3, int(height / room));
    const double span = std::max(high - low, 1e-12);
    double step = std::pow(10.0, std::floor(std::log10(span / ticks)) - 1.0);
    const auto count = [&](double s) {
        return std::ceil(high / s - 1e-9) - std::floor(low / s + 1e-9) + 1.0;
    };
    for (int i = 0; count(step) > ticks && i < 12; ++i)
        step *= i % 3 == 1 ? 2.5 : 2.0; // 1, 2, 5, 10, 20, 50, ...
    const double min = std::floor(low / step + 1e-9) * step;
    const double max = std::ceil(high / step - 1e-9) * step;
    if (step == axis->tickInterval() && min == axis->min() && max == axis->max())
        return; // plotAreaChanged comes for widths too: change nothing unchanged
    axis->setRange(min, max);
    axis->setTickInterval(step);
    axis->setLabelFormat(tickFormat(step, std::max(std::abs(min), std::abs(max))));
}

void TorqueFitPlot::relayout()
{
    const int n = jointCount();
    const int shown = shownJoint();
    m_empty->setVisible(n == 0);
    m_legend->setVisible(n > 0);
    m_selection->setVisible(n > 2); // one or two joints are all seen at a glance
    const int columns = shown >= 0 || n <= 3 ? 1 : 2;
    int cell = 0;
    for (int j = 0; j < n; ++j) {
        const JointChart &c = m_joints.at(j);
        m_grid->removeWidget(c.view);
        c.view->setVisible(shown < 0 || shown == j);
        if (!c.view->isVisibleTo(this))
            continue;
        m_grid->addWidget(c.view, cell / columns, cell % columns);
        ++cell;
    }
    m_timeTitle->setVisible(n > 0);
}

int TorqueFitPlot::pointCount(int joint, Curve curve) const
{
    if (joint < 0 || joint >= jointCount())
        return 0;
    return int(m_joints.at(joint).series.at(int(curve))->count());
}

void TorqueFitPlot::setShownJoint(int joint)
{
    const int i = m_selection->findData(joint);
    if (i >= 0) {
        m_selection->setCurrentIndex(i);
        relayout();
    }
}

int TorqueFitPlot::shownJoint() const
{
    return m_selection->count() > 0 ? m_selection->currentData().toInt() : -1;
}

bool TorqueFitPlot::isJointShown(int joint) const
{
    return joint >= 0 && joint < jointCount() && m_joints.at(joint).view->isVisibleTo(this);
}

QPair<double, double> TorqueFitPlot::timeRange(int joint) const
{
    if (joint < 0 || joint >= jointCount())
        return {};
    const QValueAxis *axis = m_joints.at(joint).time;
    return {axis->min(), axis->max()};
}

QChartView *TorqueFitPlot::chartView(int joint) const
{
    return joint >= 0 && joint < jointCount() ? m_joints.at(joint).view : nullptr;
}

} // namespace learnid
