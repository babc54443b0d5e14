#include "ui/TrackingErrorPlot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

namespace learnid {

namespace {

// The overlay draws at most this many points in all (10 trials of 2 joints at 800 points): with
// more trials each curve is thinned further by min/max buckets, which keep the peaks, so adding
// the 100th trial costs about what adding the 10th did.
constexpr int kOverlayPoints = 16000;

const QColor kJointColors[] = {QColor(0x1f, 0x5f, 0xbf), QColor(0xc0, 0x39, 0x2b),
                               QColor(0x2e, 0x8b, 0x57), QColor(0x8e, 0x44, 0xad)};

QColor trialColor(int i, int count)
{
    // From light to dark blue-violet: later trials are darker, as their errors are smaller.
    const double f = count > 1 ? double(i) / (count - 1) : 1.0;
    return QColor::fromHsvF(0.62 - 0.25 * f, 0.55 + 0.4 * f, 0.9 - 0.45 * f);
}

} // namespace

TrackingErrorPlot::TrackingErrorPlot(QWidget *parent)
    : QWidget(parent)
    , m_selection(new QComboBox(this))
    , m_autoScale(new QCheckBox(tr("Auto-scale"), this))
    , m_view(new QChartView(this))
    , m_chart(new QChart)
    , m_time(new QValueAxis(m_chart))
    , m_error(new QValueAxis(m_chart))
{
    m_selection->setObjectName(QStringLiteral("plotTrial"));
    m_autoScale->setObjectName(QStringLiteral("plotAutoScale"));
    m_autoScale->setToolTip(tr("Off: symmetric axis on a 0.02 deg grid, as in the paper"));
    m_chart->legend()->setAlignment(Qt::AlignBottom);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    m_time->setTitleText(tr("Time [s]"));
    m_error->setTitleText(tr("Tracking error [deg]"));
    m_time->setLabelFormat(QStringLiteral("%.1f"));
    m_error->setLabelFormat(QStringLiteral("%.2f"));
    m_chart->addAxis(m_time, Qt::AlignBottom);
    m_chart->addAxis(m_error, Qt::AlignLeft);
    // QChartView(QWidget *) makes a chart of its own, and setChart() only releases it.
    QChart *placeholder = m_view->chart();
    m_view->setChart(m_chart);
    delete placeholder;
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setMinimumSize(360, 240);

    auto *controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Show:"), this));
    controls->addWidget(m_selection, 1);
    controls->addWidget(m_autoScale);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(controls);
    layout->addWidget(m_view, 1);

    connect(m_selection, &QComboBox::activated, this, [this] {
        m_followNewest = m_selection->currentIndex() == m_selection->count() - 1;
        redraw();
    });
    connect(m_autoScale, &QCheckBox::toggled, this, [this](bool on) {
        redraw();
        emit autoScaleChanged(on);
    });
    clear();
}

void TrackingErrorPlot::clear()
{
    m_trials.clear();
    m_followNewest = true;
    m_selection->clear();
    m_selection->addItem(tr("All trials (overlay)"), -1);
    redraw();
}

QString TrackingErrorPlot::trialLabel(int trial) const
{
    const QList<TrackingErrorCurve> &curves = m_trials.at(trial);
    const TrialStatus status = curves.isEmpty() ? TrialStatus::Refused : curves.first().status;
    if (status == TrialStatus::Completed)
        return tr("Trial %1").arg(trial);
    return tr("Trial %1 (%2)").arg(trial).arg(trialStatusName(status));
}

void TrackingErrorPlot::setTrialCurves(int trial, const QList<TrackingErrorCurve> &curves)
{
    while (m_trials.size() <= trial)
        m_trials.append(QList<TrackingErrorCurve>());
    m_trials[trial] = curves;
    m_selection->clear();
    m_selection->addItem(tr("All trials (overlay)"), -1);
    for (int i = 0; i < m_trials.size(); ++i)
        m_selection->addItem(trialLabel(i), i);
    if (m_followNewest)
        m_selection->setCurrentIndex(m_selection->count() - 1);
    redraw();
}

void TrackingErrorPlot::setSelectedTrial(int trial)
{
    const int i = m_selection->findData(trial);
    if (i < 0)
        return;
    m_selection->setCurrentIndex(i);
    m_followNewest = trial >= 0 && i == m_selection->count() - 1;
    redraw();
}

int TrackingErrorPlot::selectedTrial() const
{
    return m_selection->currentData().toInt();
}

void TrackingErrorPlot::setAutoScale(bool on)
{
    m_autoScale->setChecked(on);
}

bool TrackingErrorPlot::autoScale() const
{
    return m_autoScale->isChecked();
}

int TrackingErrorPlot::seriesCount() const
{
    return int(m_chart->series().size());
}

int TrackingErrorPlot::pointCount() const
{
    int points = 0;
    for (const QLineSeries *series : m_series)
        points += series->count();
    return points;
}

double TrackingErrorPlot::axisLimit() const
{
    return m_error->max();
}

double TrackingErrorPlot::axisMinimum() const
{
    return m_error->min();
}

double TrackingErrorPlot::axisInterval() const
{
    return m_error->tickInterval();
}

QLineSeries *TrackingErrorPlot::seriesAt(int i)
{
    // Series are reused from one redraw to the next: re-creating them made QtCharts lay the
    // chart out again for every trial, the largest part of an update.
    while (m_series.size() <= i) {
        auto *series = new QLineSeries;
        m_chart->addSeries(series);
        series->attachAxis(m_time);
        series->attachAxis(m_error);
        m_series.append(series);
    }
    return m_series.at(i);
}

void TrackingErrorPlot::redraw()
{
    const int selected = selectedTrial();
    QList<int> shown;
    if (selected < 0) {
        for (int i = 0; i < m_trials.size(); ++i)
            shown.append(i);
        m_chart->setTitle(
            tr("Tracking error, all trials (solid: joint 1, dashed: joint 2; darker: later)"));
    } else {
        shown.append(selected);
        m_chart->setTitle(tr("Tracking error, %1").arg(trialLabel(selected)));
    }
    double maxAbs = 0.0, tMax = 0.0, yMin = 0.0, yMax = 0.0;
    int curves = 0;
    for (const int trial : shown)
        curves += int(m_trials.at(trial).size());
    const int perCurve = std::max(64, kOverlayPoints / std::max(1, curves));
    int used = 0;
    for (int order = 0; order < shown.size(); ++order) {
        for (const TrackingErrorCurve &curve : m_trials.at(shown.at(order))) {
            QLineSeries *series = seriesAt(used++);
            series->replace(curve.points.size() > perCurve ? decimateMinMax(curve.points, perCurve)
                                                           : curve.points);
            QPen pen(selected < 0 ? trialColor(order, int(shown.size()))
                                  : kJointColors[curve.joint % 4]);
            pen.setWidthF(1.4);
            if (selected < 0 && curve.joint > 0)
                pen.setStyle(Qt::DashLine);
            series->setPen(pen);
            series->setName(selected < 0
                                ? tr("trial %1, joint %2").arg(curve.trial).arg(curve.joint + 1)
                                : tr("joint %1").arg(curve.joint + 1));
            maxAbs = std::max(maxAbs, curve.maxAbsDeg);
            for (const QPointF &p : curve.points) {
                yMin = std::min(yMin, p.y());
                yMax = std::max(yMax, p.y());
            }
            if (!curve.points.isEmpty())
                tMax = std::max(tMax, curve.points.constLast().x());
        }
    }
    while (m_series.size() > used) {
        QLineSeries *series = m_series.takeLast();
        m_chart->removeSeries(series);
        delete series;
    }
    // Many overlaid trials make an unreadable legend: name joints by line style instead.
    m_chart->legend()->setVisible(selected >= 0 || shown.size() <= 4);
    const double span = tMax > 0 ? tMax : 1.0;
    m_time->setRange(0.0, span);
    m_time->setTickType(QValueAxis::TicksDynamic);
    m_time->setTickAnchor(0.0);
    m_time->setTickInterval(span > 8 ? 2.0 : span > 3 ? 0.5 : 0.25);
    m_time->setLabelFormat(span > 3 ? QStringLiteral("%.1f") : QStringLiteral("%.2f"));
    if (m_autoScale->isChecked()) {
        m_error->setTickType(QValueAxis::TicksFixed);
        const double pad = std::max(1e-6, 0.05 * (yMax - yMin));
        m_error->setRange(yMin - pad, yMax + pad);
        m_error->applyNiceNumbers();
        m_error->setLabelFormat(QStringLiteral("%.3g"));
    } else {
        const ErrorAxisRange r = errorAxisRange(maxAbs);
        m_error->setRange(-r.limit, r.limit);
        m_error->setTickType(QValueAxis::TicksDynamic);
        m_error->setTickAnchor(0.0);
        m_error->setTickInterval(r.interval);
        m_error->setLabelFormat(QStringLiteral("%.2f"));
    }
}

} // namespace learnid
