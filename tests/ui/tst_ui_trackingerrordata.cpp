#include "service/TrackingErrorData.h"
#include "ui/TrackingErrorPlot.h"

#include <QtTest>
#include <cmath>

using namespace learnid;

namespace {

// A trial whose error is known: q_d = 0, q = -sin(2 pi t) * 0.01 deg for joint 1 and a spike
// in joint 2, so e = q_d - q is known everywhere.
TrialResult syntheticTrial(int index, int samples, TrialStatus status = TrialStatus::Completed)
{
    TrialResult t;
    t.index = index;
    const double ts = 0.002;
    t.check.plan.desired.samplePeriod = ts;
    t.check.plan.desired.q = Eigen::MatrixXd::Zero(2, samples);
    t.record.samplePeriod = ts;
    t.record.status = status;
    t.record.q.resize(2, samples);
    t.record.tau = Eigen::MatrixXd::Zero(2, samples);
    for (int k = 0; k < samples; ++k) {
        t.record.q(0, k) = -std::sin(2 * M_PI * k * ts) * 0.01 * M_PI / 180.0;
        t.record.q(1, k) = 0.0;
    }
    t.record.q(1, samples / 3) = -0.05 * M_PI / 180.0; // +0.05 deg spike
    return t;
}

} // namespace

class TestTrackingErrorData : public QObject
{
    Q_OBJECT

private slots:
    void curves_areDesiredMinusMeasuredInDegrees()
    {
        const TrialResult t = syntheticTrial(2, 500);
        const QList<TrackingErrorCurve> curves = trackingErrorCurves(t, 0);
        QCOMPARE(curves.size(), 2);
        QCOMPARE(curves[0].trial, 2);
        QCOMPARE(curves[0].points.size(), 500);
        for (int k = 0; k < 500; k += 37) {
            QCOMPARE(curves[0].points[k].x(), k * 0.002);
            QVERIFY(std::abs(curves[0].points[k].y() - std::sin(2 * M_PI * k * 0.002) * 0.01) <
                    1e-12);
        }
        QVERIFY(std::abs(curves[1].maxAbsDeg - 0.05) < 1e-12);
    }

    void decimation_boundsPointsAndKeepsPeaks()
    {
        const TrialResult t = syntheticTrial(0, 20001);
        const QList<TrackingErrorCurve> curves = trackingErrorCurves(t, 1000);
        for (const TrackingErrorCurve &c : curves) {
            QVERIFY(c.points.size() <= 1000);
            double maxAbs = 0;
            for (int i = 1; i < c.points.size(); ++i)
                QVERIFY(c.points[i].x() > c.points[i - 1].x()); // time order kept
            for (const QPointF &p : c.points)
                maxAbs = std::max(maxAbs, std::abs(p.y()));
            QVERIFY(std::abs(maxAbs - c.maxAbsDeg) < 1e-12); // the peak survives
        }
    }

    void partialRecord_givesCurvesOfTheRecordedSamples()
    {
        TrialResult t = syntheticTrial(3, 400, TrialStatus::Cancelled);
        t.record.q.conservativeResize(2, 120);
        const QList<TrackingErrorCurve> curves = trackingErrorCurves(t, 0);
        QCOMPARE(curves[0].points.size(), 120);
        QCOMPARE(curves[0].status, TrialStatus::Cancelled);
    }

    void axis_isOnThe002DegreeGrid()
    {
        ErrorAxisRange r = errorAxisRange(0.039);
        QCOMPARE(r.limit, 0.04);
        QCOMPARE(r.interval, 0.02);
        r = errorAxisRange(0.001);
        QCOMPARE(r.limit, 0.02);
        r = errorAxisRange(1.3); // 66 grid steps each way: coarser, still multiples of 0.02
        QVERIFY(r.limit >= 1.3);
        QVERIFY(2 * r.limit / r.interval <= 12.0 + 1e-9);
        QVERIFY(std::abs(std::remainder(r.interval, 0.02)) < 1e-12);
    }

    void plot_showsOneTrialOrAllOverlaid()
    {
        TrackingErrorPlot plot;
        plot.setTrialCurves(0, trackingErrorCurves(syntheticTrial(0, 300)));
        plot.setTrialCurves(1, trackingErrorCurves(syntheticTrial(1, 300)));
        QCOMPARE(plot.selectedTrial(), 1); // follows the newest
        QCOMPARE(plot.seriesCount(), 2);
        plot.setSelectedTrial(-1);
        QCOMPARE(plot.seriesCount(), 4);
        QCOMPARE(plot.axisInterval(), 0.02);
        QCOMPARE(plot.axisLimit(), 0.06);
        plot.setAutoScale(true);
        QVERIFY(plot.axisMinimum() > -0.06); // fitted to the data, no longer symmetric
        QVERIFY(plot.axisMinimum() != -plot.axisLimit());
        plot.setTrialCurves(2, trackingErrorCurves(syntheticTrial(2, 300)));
        QCOMPARE(plot.selectedTrial(), -1); // the technician's choice is kept
        QCOMPARE(plot.trialCount(), 3);
    }

    void overlayOfManyTrials_drawsABoundedNumberOfPointsAndKeepsThePeaks()
    {
        TrackingErrorPlot plot;
        plot.setSelectedTrial(-1);
        const QList<TrackingErrorCurve> one = trackingErrorCurves(syntheticTrial(0, 2500));
        const int perTrial = int(one[0].points.size() + one[1].points.size());
        for (int k = 0; k < 100; ++k)
            plot.setTrialCurves(k, trackingErrorCurves(syntheticTrial(k, 2500)));
        plot.setSelectedTrial(-1);
        QCOMPARE(plot.seriesCount(), 200);
        QVERIFY2(plot.pointCount() <= 16000, qPrintable(QString::number(plot.pointCount())));
        QVERIFY(plot.pointCount() < 100 * perTrial / 4); // thinned
        plot.setAutoScale(true); // the axis follows the drawn points: the +0.05 deg spike is kept
        QVERIFY2(plot.axisLimit() >= 0.05, qPrintable(QString::number(plot.axisLimit())));
        plot.setSelectedTrial(99); // one trial alone: drawn as computed
        QCOMPARE(plot.pointCount(), perTrial);
    }
};

QTEST_MAIN(TestTrackingErrorData)
#include "tst_ui_trackingerrordata.moc"
