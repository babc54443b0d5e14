// The tracking-error plot of a serial arm with n joints (here 7, 10 trials): the joint selector
// lists the joints with their names, a selected joint shows only its curves, joints differ in
// colour and trials of a joint in shade (later = darker), the drawn points stay within the
// budget, and the error axis keeps the paper's 0.02 deg grid unless auto-scaled.
#include "service/TrackingErrorData.h"
#include "ui/TrackingErrorPlot.h"

#include <QComboBox>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace learnid;

namespace {

constexpr int kJoints = 7;
constexpr int kTrials = 10;
constexpr int kSamples = 2500;
constexpr double kTs = 0.002;

/// The peak error of joint j in trial k [deg]: unique for every (j, k), so a drawn curve tells
/// which joint and trial it is: 0.01 (j + 1) + 0.0005 k.
double amplitude(int joint, int trial)
{
    return 0.01 * (joint + 1) + 0.0005 * trial;
}

/// A trial with q_d = 0 and q_j = -A_jk sin(2 pi t) (t = 0.25 s is a sample: the peak is hit).
TrialResult trial(int index, int joints = kJoints)
{
    TrialResult t;
    t.index = index;
    t.check.plan.desired.samplePeriod = kTs;
    t.check.plan.desired.q = Eigen::MatrixXd::Zero(joints, kSamples);
    t.record.samplePeriod = kTs;
    t.record.status = TrialStatus::Completed;
    t.record.q.resize(joints, kSamples);
    t.record.tau = Eigen::MatrixXd::Zero(joints, kSamples);
    for (int j = 0; j < joints; ++j)
        for (int k = 0; k < kSamples; ++k)
            t.record.q(j, k) = -amplitude(j, index) * std::sin(2 * M_PI * k * kTs) * M_PI / 180.0;
    return t;
}

QStringList pandaNames()
{
    QStringList names;
    for (int j = 1; j <= kJoints; ++j)
        names << QStringLiteral("panda_joint%1").arg(j);
    return names;
}

QList<QLineSeries *> lineSeries(const TrackingErrorPlot &plot)
{
    QList<QLineSeries *> out;
    for (QAbstractSeries *s : plot.chartView()->chart()->series())
        out << qobject_cast<QLineSeries *>(s);
    return out;
}

double peak(const QLineSeries *s)
{
    double m = 0.0;
    for (const QPointF &p : s->points())
        m = std::max(m, std::abs(p.y()));
    return m;
}

/// The (joint, trial) a drawn curve belongs to, from its peak (see amplitude()).
QPair<int, int> identify(const QLineSeries *s)
{
    const double a = peak(s);
    const int joint = int(std::floor(a / 0.01 + 1e-6)) - 1;
    const int index = int(std::lround((a - 0.01 * (joint + 1)) / 0.0005));
    return {joint, index};
}

double lightness(const QColor &c)
{
    return c.toHsl().lightnessF();
}

} // namespace

class TestTrackingErrorPlot : public QObject
{
    Q_OBJECT

private slots:
    void labels_fitThePlot();
    void jointSelector_listsTheJointsWithTheirNames()
    {
        TrackingErrorPlot plot;
        plot.setJointNames(pandaNames());
        plot.clear(); // the window clears the plot when a session opens: the names stay
        for (int k = 0; k < kTrials; ++k)
            plot.setTrialCurves(k, trackingErrorCurves(trial(k)));
        auto *selector = plot.findChild<QComboBox *>(QStringLiteral("plotJoint"));
        QVERIFY(selector);
        QCOMPARE(plot.jointCount(), kJoints);
        QCOMPARE(selector->count(), kJoints + 1);
        QCOMPARE(selector->itemText(0), QStringLiteral("All joints"));
        for (int j = 0; j < kJoints; ++j)
            QCOMPARE(selector->itemText(j + 1),
                     QStringLiteral("Joint %1 (panda_joint%1)").arg(j + 1));

        // Without names (or with an empty one) a joint is "Joint k"; curves add joints.
        TrackingErrorPlot unnamed;
        unnamed.setJointNames({QStringLiteral("base"), QString()});
        unnamed.setTrialCurves(0, trackingErrorCurves(trial(0)));
        selector = unnamed.findChild<QComboBox *>(QStringLiteral("plotJoint"));
        QCOMPARE(selector->count(), kJoints + 1);
        QCOMPARE(selector->itemText(1), QStringLiteral("Joint 1 (base)"));
        QCOMPARE(selector->itemText(2), QStringLiteral("Joint 2"));
        QCOMPARE(selector->itemText(7), QStringLiteral("Joint 7"));
        unnamed.setJointNames({QStringLiteral("shoulder")}); // fewer names than the curves' joints
        QCOMPARE(selector->count(), kJoints + 1);
        QCOMPARE(selector->itemText(1), QStringLiteral("Joint 1 (shoulder)"));
        QCOMPARE(selector->itemText(2), QStringLiteral("Joint 2"));
    }

    void selectingAJoint_showsOnlyItsCurves()
    {
        TrackingErrorPlot plot;
        plot.setJointNames(pandaNames());
        plot.show();
        for (int k = 0; k < kTrials; ++k)
            plot.setTrialCurves(k, trackingErrorCurves(trial(k)));
        QCOMPARE(plot.selectedTrial(), kTrials - 1);
        QCOMPARE(plot.seriesCount(), kJoints); // the newest trial, all joints

        // The technician picks joint 3 with the keyboard: down from "Joint 2".
        auto *selector = plot.findChild<QComboBox *>(QStringLiteral("plotJoint"));
        plot.setSelectedJoint(1);
        selector->setFocus();
        QTest::keyClick(selector, Qt::Key_Down);
        QCOMPARE(plot.selectedJoint(), 2);
        QCOMPARE(plot.seriesCount(), 1);
        QCOMPARE(identify(lineSeries(plot)[0]), qMakePair(2, kTrials - 1));
        QVERIFY(plot.chartView()->chart()->title().contains(QStringLiteral("panda_joint3")));

        plot.setSelectedTrial(-1); // the overlay: one curve per trial, all of joint 3
        QCOMPARE(plot.seriesCount(), kTrials);
        QList<int> trials;
        for (const QLineSeries *s : lineSeries(plot)) {
            QCOMPARE(identify(s).first, 2);
            trials << identify(s).second;
        }
        std::sort(trials.begin(), trials.end());
        for (int k = 0; k < kTrials; ++k)
            QCOMPARE(trials[k], k);
        QCoreApplication::processEvents();
        QStringList legend; // the shades' range: the first and the latest trial
        for (const QLegendMarker *m : plot.chartView()->chart()->legend()->markers())
            if (m->isVisible())
                legend << m->label();
        QCOMPARE(legend, QStringList({QStringLiteral("Trial 0"), QStringLiteral("Trial 9")}));

        plot.setSelectedTrial(4);
        QCOMPARE(plot.seriesCount(), 1);
        QCOMPARE(identify(lineSeries(plot)[0]), qMakePair(2, 4));
        plot.setSelectedJoint(-1);
        QCOMPARE(plot.seriesCount(), kJoints);
    }

    void joints_differInColour_trialsInShade()
    {
        TrackingErrorPlot plot;
        for (int k = 0; k < kTrials; ++k)
            plot.setTrialCurves(k, trackingErrorCurves(trial(k)));
        // One trial: one colour per joint, all different.
        QList<QColor> colours(kJoints);
        for (const QLineSeries *s : lineSeries(plot))
            colours[identify(s).first] = s->pen().color();
        for (int a = 0; a < kJoints; ++a)
            for (int b = a + 1; b < kJoints; ++b)
                QVERIFY2(colours[a] != colours[b],
                         qPrintable(QStringLiteral("joints %1 and %2").arg(a + 1).arg(b + 1)));

        // The overlay: per joint, later trials are darker shades of the joint's colour.
        plot.setSelectedTrial(-1);
        QCOMPARE(plot.seriesCount(), kJoints * kTrials);
        QVector<QVector<QColor>> shade(kJoints, QVector<QColor>(kTrials));
        for (const QLineSeries *s : lineSeries(plot)) {
            const auto [joint, index] = identify(s);
            shade[joint][index] = s->pen().color();
        }
        for (int j = 0; j < kJoints; ++j) {
            for (int k = 1; k < kTrials; ++k)
                QVERIFY(lightness(shade[j][k]) < lightness(shade[j][k - 1]));
            // A shade of the joint's colour: the hue stays (grey has none).
            if (colours[j].hslHue() >= 0)
                QVERIFY(std::abs(shade[j][0].hslHue() - colours[j].hslHue()) <= 6);
        }
        // The legend names the 7 joints, by the latest trial's series.
        plot.resize(1400, 500); // room for every "Joint k" (fitLabelsToThePlot: shorter ones)
        plot.show();            // the legend's items are visible once the chart is
        QCoreApplication::processEvents();
        QStringList legend;
        for (const QLegendMarker *m : plot.chartView()->chart()->legend()->markers())
            if (m->isVisible())
                legend << m->label();
        QCOMPARE(legend.size(), kJoints);
        for (int j = 0; j < kJoints; ++j)
            QVERIFY(legend.contains(QStringLiteral("Joint %1").arg(j + 1)));
    }

    void overlayOfManyTrialsAndJoints_staysWithinThePointBudget()
    {
        TrackingErrorPlot plot;
        plot.setSelectedTrial(-1);
        const int perCurve = int(trackingErrorCurves(trial(0))[0].points.size()); // 800
        for (int trials : {kTrials, 60}) {
            for (int k = plot.trialCount(); k < trials; ++k)
                plot.setTrialCurves(k, trackingErrorCurves(trial(k)));
            QCOMPARE(plot.seriesCount(), kJoints * trials);
            // Each curve thinned to 16000 / curves points, min/max buckets of 2 points each.
            const int budget = 2 * ((16000 / (kJoints * trials)) / 2) * kJoints * trials;
            QVERIFY2(plot.pointCount() <= budget, qPrintable(QString::number(plot.pointCount())));
            QVERIFY(plot.pointCount() < kJoints * trials * perCurve);
            for (const QLineSeries *s : lineSeries(plot)) { // the peaks survive the thinning
                const auto [joint, index] = identify(s);
                QVERIFY(std::abs(peak(s) - amplitude(joint, index)) < 1e-9);
            }
        }
        plot.setSelectedTrial(59); // one trial, 7 joints: drawn as computed
        QCOMPARE(plot.pointCount(), kJoints * perCurve);
    }

    void errorAxis_keepsThe002DegreeGridUnlessAutoScaled()
    {
        TrackingErrorPlot plot;
        for (int k = 0; k < kTrials; ++k)
            plot.setTrialCurves(k, trackingErrorCurves(trial(k)));
        plot.setSelectedTrial(-1);
        // All joints: the largest peak is joint 7's in trial 9, 0.07 + 0.0045 deg.
        const double largest = amplitude(kJoints - 1, kTrials - 1);
        QCOMPARE(plot.axisInterval(), 0.02);
        QCOMPARE(plot.axisLimit(), std::ceil(largest / 0.02) * 0.02); // 0.08
        QCOMPARE(plot.axisMinimum(), -plot.axisLimit());
        plot.setSelectedJoint(2); // joint 3 alone: 0.03 + 0.0045 deg -> +-0.04
        QCOMPARE(plot.axisInterval(), 0.02);
        QCOMPARE(plot.axisLimit(), std::ceil(amplitude(2, kTrials - 1) / 0.02) * 0.02);

        // A trial of a tenth of that error (joint 1: 0.00105 deg, as after learning): the grid
        // keeps +-0.02, auto-scale fits it.
        TrialResult small = trial(kTrials);
        small.record.q *= 0.1;
        plot.setTrialCurves(kTrials, trackingErrorCurves(small));
        plot.setSelectedJoint(0);
        QCOMPARE(plot.selectedTrial(), -1); // the overlay stays chosen
        plot.setSelectedTrial(kTrials);
        const double a = 0.1 * amplitude(0, kTrials);
        QCOMPARE(plot.axisLimit(), 0.02);
        QCOMPARE(plot.axisInterval(), 0.02);
        plot.setAutoScale(true);
        QVERIFY(plot.axisLimit() >= a);
        QVERIFY2(plot.axisLimit() < 5 * a, qPrintable(QString::number(plot.axisLimit())));
        QVERIFY(plot.axisMinimum() <= -a);
        QVERIFY(plot.axisMinimum() > -5 * a);
        plot.setAutoScale(false);
        QCOMPARE(plot.axisLimit(), 0.02);
        QCOMPARE(plot.axisInterval(), 0.02);
    }
};

// The 7-axis session's plot (issue 23): the legend's joint entries and the error axis's title are
// shortened to what the plot shows in full, never cut by QtCharts ("Joint 1 (panda_join...",
// "Tracking error ..."): wide, "Joint 1 (panda_joint1)"; narrower, the joint's name
// "panda_joint1"; then "Joint 1"; then "1". Held against the legend's own width and the plot
// area's height, measured with the fonts they are drawn in.
void TestTrackingErrorPlot::labels_fitThePlot()
{
    TrackingErrorPlot plot;
    plot.setJointNames(pandaNames());
    for (int k = 0; k < kTrials; ++k)
        plot.setTrialCurves(k, trackingErrorCurves(trial(k)));
    plot.setSelectedTrial(-1);
    QChart *chart = plot.chartView()->chart();
    const QFontMetricsF legendFont(chart->legend()->font());
    const auto *axis = qobject_cast<QValueAxis *>(chart->axes(Qt::Vertical).constFirst());
    QVERIFY(axis);
    const QFontMetricsF titleFont(axis->titleFont());
    const auto forms = [](int j) {
        return QStringList{QStringLiteral("Joint %1 (panda_joint%1)").arg(j + 1),
                           QStringLiteral("panda_joint%1").arg(j + 1),
                           QStringLiteral("Joint %1").arg(j + 1), QString::number(j + 1)};
    };
    QList<int> used;
    for (const QSize size :
         {QSize(2400, 600), QSize(1100, 260), QSize(800, 240), QSize(420, 240)}) {
        plot.resize(size);
        plot.show();
        for (int i = 0; i < 5; ++i) // the layout, then the queued fitting after it
            QCoreApplication::processEvents();
        const qreal share = chart->legend()->geometry().width() / kJoints;
        int form = -1;
        int shown = 0;
        for (const QLegendMarker *m : chart->legend()->markers()) {
            if (!m->isVisible())
                continue;
            const int j = shown++;
            const int f = int(forms(j).indexOf(m->label()));
            QVERIFY2(f >= 0, qPrintable(m->label()));
            QVERIFY2(form < 0 || f == form, "one form for all joints");
            form = f;
            // The label and its marker (a square of the font's height) within the entry's share.
            QVERIFY2(legendFont.horizontalAdvance(m->label()) + legendFont.height() <= share,
                     qPrintable(QStringLiteral("%1 in %2 px").arg(m->label()).arg(share)));
        }
        QCOMPARE(shown, kJoints);
        used.append(form);
        const QString title = axis->titleText();
        QVERIFY2(QStringList({QStringLiteral("Tracking error [deg]"), QStringLiteral("Error [deg]"),
                              QStringLiteral("[deg]")})
                     .contains(title),
                 qPrintable(title));
        QVERIFY2(
            titleFont.horizontalAdvance(title) <= chart->plotArea().height(),
            qPrintable(QStringLiteral("%1 in %2 px").arg(title).arg(chart->plotArea().height())));
        if (size.height() >= 600)
            QCOMPARE(title, QStringLiteral("Tracking error [deg]"));
    }
    // Wide, the full label; narrower, shorter ones, never longer again.
    QCOMPARE(used.constFirst(), 0);
    QVERIFY2(used.constLast() > 0, qPrintable(QString::number(used.constLast())));
    QVERIFY(std::is_sorted(used.begin(), used.end()));
}

QTEST_MAIN(TestTrackingErrorPlot)
#include "tst_ui_trackingerrorplot.moc"
