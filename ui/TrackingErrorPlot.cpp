#include "ui/TrackingErrorPlot.h"
#include "ui/TrackingErrorStyle.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFontMetricsF>
#include <QHBoxLayout>
#include <QLabel>
#include <QSet>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <algorithm>
#include <utility>

namespace learnid {

// Whatever is shown draws at most this many points in all (10 trials of 2 joints at 800 points):
// with more curves (trials, joints) each is thinned further by min/max buckets, which keep the
// peaks, so adding the 100th trial costs what adding the 10th did. A curve keeps at least 4
// points (2 buckets): the budget holds up to 4000 curves.
constexpr int kPointBudget = 16000;

TrackingErrorPlot::TrackingErrorPlot(QWidget *parent)
    : QWidget(parent)
    , m_selection(new QComboBox(this))
    , m_joint(new QComboBox(this))
    , m_autoScale(new QCheckBox(tr("Auto-scale"), this))
    , m_view(new QChartView(this))
    , m_chart(new QChart)
    , m_time(new QValueAxis(m_chart))
    , m_error(new QValueAxis(m_chart))
{
    m_selection->setObjectName(QStringLiteral("plotTrial"));
    m_joint->setObjectName(QStringLiteral("plotJoint"));
    m_joint->setToolTip(tr("The joint whose tracking error is shown"));
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
    // After the layout: what fits depends on the plot's size.
    connect(m_chart, &QChart::plotAreaChanged, this, &TrackingErrorPlot::fitLabels,
            Qt::QueuedConnection);

    auto *controls = new QHBoxLayout;
    controls->addWidget(new QLabel(tr("Show:"), this));
    controls->addWidget(m_selection, 1);
    controls->addWidget(m_joint, 1);
    controls->addWidget(m_autoScale);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(controls);
    layout->addWidget(m_view, 1);

    connect(m_selection, &QComboBox::activated, this, [this] {
        m_followNewest = m_selection->currentIndex() == m_selection->count() - 1;
        redraw();
    });
    connect(m_joint, &QComboBox::activated, this, [this] { redraw(); });
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
    setJointCount(int(m_jointNames.size()));
    redraw();
}

void TrackingErrorPlot::setJointNames(const QStringList &names)
{
    m_jointNames = names;
    int joints = int(names.size()); // and the joints of the curves already shown
    for (const QList<TrackingErrorCurve> &curves : std::as_const(m_trials))
        for (const TrackingErrorCurve &curve : curves)
            joints = std::max(joints, curve.joint + 1);
    m_jointCount = -1; // relabel even when the count stays
    setJointCount(joints);
    redraw();
}

void TrackingErrorPlot::setJointCount(int count)
{
    if (count == m_jointCount)
        return;
    const int selected = m_joint->count() > 0 ? selectedJoint() : -1;
    m_jointCount = count;
    m_joint->clear();
    m_joint->addItem(tr("All joints"), -1);
    for (int j = 0; j < count; ++j)
        m_joint->addItem(jointLabel(j, m_jointNames), j);
    m_joint->setCurrentIndex(std::max(0, m_joint->findData(selected)));
}

void TrackingErrorPlot::setSelectedJoint(int joint)
{
    const int i = m_joint->findData(joint);
    if (i < 0)
        return;
    m_joint->setCurrentIndex(i);
    redraw();
}

int TrackingErrorPlot::selectedJoint() const
{
    return m_joint->currentData().toInt();
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
    int joints = std::max(m_jointCount, int(m_jointNames.size()));
    for (const TrackingErrorCurve &curve : curves)
        joints = std::max(joints, curve.joint + 1);
    setJointCount(joints);
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
    const int joint = selectedJoint();
    const bool overlay = selected < 0;
    QList<int> shown; // trial indices, earliest first
    for (int i = overlay ? 0 : selected; i < (overlay ? int(m_trials.size()) : selected + 1); ++i)
        shown.append(i);
    const QString what = joint < 0
                             ? tr("Tracking error")
                             : tr("Tracking error of %1").arg(jointLabel(joint, m_jointNames));
    m_chart->setTitle(overlay ? tr("%1, all trials (darker: later)").arg(what)
                              : tr("%1, %2").arg(what, trialLabel(selected)));
    auto drawn = [joint](const TrackingErrorCurve &c) {
        return joint < 0 || c.joint == joint;
    };
    int curves = 0;
    for (const int trial : shown)
        curves += int(std::count_if(m_trials.at(trial).begin(), m_trials.at(trial).end(), drawn));
    const int perCurve = std::max(4, kPointBudget / std::max(1, curves));
    double maxAbs = 0.0, tMax = 0.0, yMin = 0.0, yMax = 0.0;
    int used = 0;
    QSet<QAbstractSeries *> inLegend;
    m_jointEntries.clear();
    for (int order = 0; order < shown.size(); ++order) {
        for (const TrackingErrorCurve &curve : m_trials.at(shown.at(order))) {
            if (!drawn(curve))
                continue;
            QLineSeries *series = seriesAt(used++);
            series->replace(curve.points.size() > perCurve ? decimateMinMax(curve.points, perCurve)
                                                           : curve.points);
            const QColor base = jointColor(curve.joint);
            const QColor color = overlay ? trialShade(base, order, int(shown.size())) : base;
            series->setPen(QPen(QBrush(color), 1.4, jointPenStyle(curve.joint)));
            const bool last = order == shown.size() - 1;
            if (!overlay || joint < 0) {
                series->setName(jointLabel(curve.joint, m_jointNames));
                if (!overlay || last) {
                    inLegend.insert(series);
                    m_jointEntries.append({series, curve.joint});
                }
            } else {
                series->setName(trialLabel(shown.at(order)));
                if (order == 0 || last)
                    inLegend.insert(series);
            }
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
    for (QLegendMarker *marker : m_chart->legend()->markers())
        marker->setVisible(inLegend.contains(marker->series()));
    setTimeAxis(m_time, tMax);
    // About one grid label per 30 px of the plot's height (the chart's frame takes ~40 %).
    // (A plot not on screen has no height yet: the full grid.)
    const int ticks =
        m_view->isVisible() ? std::clamp(int(0.6 * m_view->height() / 30.0), 4, 12) : 12;
    setErrorAxis(m_error, m_autoScale->isChecked(), maxAbs, yMin, yMax, ticks);
    fitLabels();
}

void TrackingErrorPlot::fitLabels()
{
    const QRectF plot = m_chart->plotArea();
    const QString title =
        fittedErrorAxisTitle(QFontMetricsF(m_error->titleFont()),
                             plot.height() > 0 ? plot.height() : m_chart->size().height());
    if (m_error->titleText() != title)
        m_error->setTitleText(title);
    QList<int> joints;
    for (const auto &entry : std::as_const(m_jointEntries))
        joints.append(entry.second);
    const QRectF legend = m_chart->legend()->geometry();
    const qreal width = legend.width() > 0 ? legend.width() : m_chart->size().width();
    const QStringList labels =
        fittedJointLabels(joints, m_jointNames, QFontMetricsF(m_chart->legend()->font()), width);
    for (int i = 0; i < m_jointEntries.size(); ++i)
        if (m_jointEntries.at(i).first->name() != labels.at(i))
            m_jointEntries.at(i).first->setName(labels.at(i));
}

} // namespace learnid
