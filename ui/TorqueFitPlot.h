#pragma once

#include <Eigen/Core>
#include <QList>
#include <QStringList>
#include <QWidget>

class QChart;
class QChartView;
class QComboBox;
class QGridLayout;
class QLabel;
class QLineSeries;
class QValueAxis;

namespace learnid {

/// Predicted against measured torque on one validation log: one small chart per joint, all on
/// the same time axis, each with the measured torque, the torque the identified parameters
/// predict and the torque of the URDF as given (filtered alike, as the validation figures count
/// them). A selector shows all joints or one of them. The view only draws what it is given.
class TorqueFitPlot : public QWidget
{
    Q_OBJECT

public:
    enum class Curve { Measured, Identified, Given };

    explicit TorqueFitPlot(QWidget *parent = nullptr);

    /// time: K sample times [s]; measured, identified, given: n x K torques [N m] (or [N]).
    void setData(const QStringList &jointNames, const Eigen::VectorXd &time,
                 const Eigen::MatrixXd &measured, const Eigen::MatrixXd &identified,
                 const Eigen::MatrixXd &given);
    void clear();

    int jointCount() const { return int(m_joints.size()); }
    /// Points of a curve as drawn (every sample: the plot does not thin).
    int pointCount(int joint, Curve curve) const;
    /// -1 shows every joint.
    void setShownJoint(int joint);
    int shownJoint() const;
    bool isJointShown(int joint) const;
    /// The time axis' range [s] of a joint's chart.
    QPair<double, double> timeRange(int joint) const;
    QChartView *chartView(int joint) const;

private:
    struct JointChart
    {
        QChartView *view = nullptr;
        QChart *chart = nullptr;
        QValueAxis *time = nullptr;
        QValueAxis *torque = nullptr;
        QList<QLineSeries *> series; ///< by Curve
    };

    JointChart makeChart();
    void relayout();
    /// The torque axis over [low, high] for a plot area `height` px high: as many ticks as its
    /// labels have room for (3 at least), at a step of 1, 2 or 5 times a power of ten, labelled
    /// with the digits the step needs.
    static void fitTorqueTicks(QValueAxis *axis, double low, double high, double height);

    QComboBox *m_selection;
    QLabel *m_empty;
    QGridLayout *m_grid;
    QWidget *m_legend;
    QLabel *m_timeTitle;
    QList<JointChart> m_joints;
};

} // namespace learnid
