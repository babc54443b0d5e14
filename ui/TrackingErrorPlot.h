#pragma once

#include "service/TrackingErrorData.h"

#include <QPair>
#include <QStringList>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;

namespace learnid {

/// Tracking error in degrees over time like the paper's Fig. 4-6, for any number of joints: one
/// trial (selectable) or all trials overlaid, all joints or one (selectable). Each joint has its
/// own colour (TrackingErrorStyle.h); in the overlay, later trials are darker shades of it. The
/// legend names the joints (in the overlay by the latest trial's shade) or, for one joint in the
/// overlay, its first and latest trial. The error axis has a 0.02 deg grid by default; auto-scale
/// fits the data instead. Whatever is shown is thinned to a fixed budget of drawn points. The view
/// only draws what it is given.
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
    /// Names for the joint selector and legend ("Joint 3 (panda_joint3)"); kept by clear().
    /// Joints beyond the names, or with an empty name, are "Joint k".
    void setJointNames(const QStringList &names);
    /// 0-based; -1 shows all joints.
    void setSelectedJoint(int joint);
    int selectedJoint() const;
    /// Joints the selector offers: the names given, or more when curves have more joints.
    int jointCount() const { return m_jointCount; }
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
    /// Rebuilds the joint selector for `count` joints, keeping the selected joint if it remains.
    void setJointCount(int count);
    /// Shortens the error axis's title and the joints' legend entries to what the chart's size
    /// shows in full (fittedErrorAxisTitle, fittedJointLabels).
    void fitLabels();

    QComboBox *m_selection;
    QComboBox *m_joint;
    QCheckBox *m_autoScale;
    QChartView *m_view;
    QChart *m_chart;
    QValueAxis *m_time;
    QValueAxis *m_error;
    QList<QList<TrackingErrorCurve>> m_trials;       ///< by trial index
    QList<QLineSeries *> m_series;                   ///< in the chart, in drawing order
    QList<QPair<QLineSeries *, int>> m_jointEntries; ///< legend entries named by joint
    QStringList m_jointNames;
    int m_jointCount = 0;
    bool m_followNewest = true;
};

} // namespace learnid
