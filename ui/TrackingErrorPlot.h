#pragma once

#include "service/TrackingErrorData.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;

namespace learnid {

/// Tracking error in degrees over time like the paper's Fig. 4-6: one curve per joint, one trial
/// (selectable) or all trials overlaid. The error axis has a 0.02 deg grid by default;
/// auto-scale fits the data instead. The view only draws what it is given.
class TrackingErrorPlot : public QWidget
{
    Q_OBJECT

public:
    explicit TrackingErrorPlot(QWidget *parent = nullptr);

    void clear();
    /// Adds (or replaces) a trial's curves; the selection follows the newest trial unless the
    /// technician chose another.
    void setTrialCurves(int trial, const QList<TrackingErrorCurve> &curves);
    /// -1 shows all trials overlaid.
    void setSelectedTrial(int trial);
    int selectedTrial() const;
    void setAutoScale(bool on);
    bool autoScale() const;
    int trialCount() const { return int(m_trials.size()); }

    /// The plotted curves as currently shown (for tests and export).
    int seriesCount() const;
    /// Points drawn in all series (the overlay of many trials is thinned to a fixed budget).
    int pointCount() const;
    double axisLimit() const;
    double axisMinimum() const;
    double axisInterval() const;
    QChartView *chartView() const { return m_view; }

signals:
    void autoScaleChanged(bool on);

private:
    void redraw();
    QLineSeries *seriesAt(int i);
    QString trialLabel(int trial) const;

    QComboBox *m_selection;
    QCheckBox *m_autoScale;
    QChartView *m_view;
    QChart *m_chart;
    QValueAxis *m_time;
    QValueAxis *m_error;
    QList<QList<TrackingErrorCurve>> m_trials; ///< by trial index
    QList<QLineSeries *> m_series;             ///< in the chart, in drawing order
    bool m_followNewest = true;
};

} // namespace learnid
