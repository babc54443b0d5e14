#pragma once

#include "model/RobotModel.h"
#include "session/ConvergenceFigures.h"

#include <Eigen/Core>
#include <QPointF>
#include <QVector>
#include <QWidget>
#include <optional>

class QChart;
class QChartView;
class QLineSeries;
class QLogValueAxis;
class QValueAxis;

namespace learnid {

/// A small chart beside the convergence table: per parameter, |error against the truth| [%]
/// over the estimate index when the truth is known (simulated robot), else the relative change
/// from the previous estimate [%]; logarithmic, floored at 0.001 %. For more parameters than
/// the table has columns for (an n-joint arm), the path-torque error of each estimate against
/// the truth (simulated robot) and against the newest estimate instead.
class ConvergenceChart : public QWidget
{
    Q_OBJECT

public:
    explicit ConvergenceChart(QWidget *parent = nullptr);

    void setData(const QList<ParameterInfo> &parameters, const QVector<Eigen::VectorXd> &estimates,
                 const std::optional<Eigen::VectorXd> &truth, const EstimateFigures &figures = {});
    QChartView *chartView() const { return m_view; }

private:
    struct Curve
    {
        QString name;
        QList<QPointF> points;
    };
    static QList<Curve> parameterCurves(const QList<ParameterInfo> &parameters,
                                        const QVector<Eigen::VectorXd> &estimates,
                                        const std::optional<Eigen::VectorXd> &truth);
    QList<Curve> pathTorqueCurves(const EstimateFigures &figures);
    QLineSeries *seriesAt(int p);

    QChartView *m_view;
    QChart *m_chart;
    QValueAxis *m_x;
    QLogValueAxis *m_y;
    QList<QLineSeries *> m_series; ///< one per parameter, reused from one update to the next
};

} // namespace learnid
