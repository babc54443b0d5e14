// UniformLog: a robot's log put on a uniform grid by linear interpolation.
#include "../io/IoTestSupport.h"
#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "identify/LogSignals.h"
#include "identify/UniformLog.h"
#include "io/RobotLogCsv.h"

#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;
using learnid::test::bitEqual;

class TestUniformLog : public QObject
{
    Q_OBJECT

private slots:
    void jitteredSine_matchesTheFunctionWithinTheInterpolationBound();
    void gridOnTheStamps_takesTheSamplesBitForBit();
    void gap_isRefusedNamingTheLine();
    void defaultGap_isHalfTheFilterTimeConstant_atLeastTwoSteps();
    void gapAtTheBound_costsTheFilteredSignalWhatTheDerivationSays();
    void staleRows_leaveAGap_refusedNamingThem();
    void repeatedRows_droppedByTheReader_resampleCleanly();
    void nominalTimes_takeSampleKAtT0PlusKT();
    void nominalTimes_refusedWhenASampleIsMissing();
    void badLogsAndOptions_areRefused();
    void kukaLog_stampsJitterSamplesDoNot();
    void pendulumLog_missedTicks_stampsAreTheTruth();
};

namespace {

constexpr double step = 0.005; // [s] the KUKA LWR4+'s 200 Hz

// Samples of q = a sin(w t), dq = a w cos(w t), tau = b cos(2 w t) for two joints at times t.
RobotLog sineLog(const Eigen::VectorXd &t, double a, double w, double b)
{
    RobotLog log;
    log.source = QStringLiteral("sine.csv");
    log.t = t;
    log.q.resize(2, t.size());
    log.dq.resize(2, t.size());
    log.tau.resize(2, t.size());
    for (Eigen::Index k = 0; k < t.size(); ++k) {
        for (int j = 0; j < 2; ++j) {
            const double aj = a * (j + 1);
            log.q(j, k) = aj * std::sin(w * t[k]);
            log.dq(j, k) = aj * w * std::cos(w * t[k]);
            log.tau(j, k) = b * std::cos(2 * w * t[k]);
        }
    }
    return log;
}

// Stamps k h, moved in pairs as a jittery clock does: one late by d, the next on time.
Eigen::VectorXd pairedJitter(int samples, std::mt19937 &rng, double maxShift)
{
    std::uniform_real_distribution<double> shift(-maxShift, maxShift);
    Eigen::VectorXd t(samples);
    for (int k = 0; k < samples; ++k)
        t[k] = 1.0 + k * step + (k % 2 == 1 ? shift(rng) : 0.0);
    return t;
}

} // namespace

void TestUniformLog::jitteredSine_matchesTheFunctionWithinTheInterpolationBound()
{
    // Time stamps jittered by up to +-40 % of a step; the interpolant of f between two stamps
    // h apart is off f by at most h^2 / 8 max|f''| (the error of linear interpolation).
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> jitter(-0.4 * step, 0.4 * step);
    Eigen::VectorXd t(3000);
    for (Eigen::Index k = 0; k < t.size(); ++k)
        t[k] = 2.0 + double(k) * step + jitter(rng);
    const double a = 0.8, w = 2 * M_PI * 1.5, b = 3.0;
    const UniformLog uniform = resampleUniform(sineLog(t, a, w, b));

    double hMax = 0.0;
    for (Eigen::Index k = 1; k < t.size(); ++k)
        hMax = std::max(hMax, t[k] - t[k - 1]);
    QVERIFY(hMax > 1.7 * step);
    LEARNID_COMPARE_NEAR(uniform.period, step, 0.05 * step); // the median step
    QCOMPARE(uniform.t0, t[0]);
    QVERIFY(uniform.time(uniform.samples() - 1) <= t[t.size() - 1]);
    QVERIFY(uniform.time(uniform.samples()) > t[t.size() - 1]);
    QCOMPARE(uniform.dof(), 2);

    double qError = 0.0, dqError = 0.0, tauError = 0.0;
    for (Eigen::Index k = 0; k < uniform.samples(); ++k) {
        const double tk = uniform.time(k);
        const Eigen::Vector2d q(a * std::sin(w * tk), 2 * a * std::sin(w * tk));
        const Eigen::Vector2d dq = Eigen::Vector2d(a, 2 * a) * w * std::cos(w * tk);
        qError = std::max(qError, (uniform.q.col(k) - q).cwiseAbs().maxCoeff());
        dqError = std::max(dqError, (uniform.dq.col(k) - dq).cwiseAbs().maxCoeff());
        tauError = std::max(tauError, std::abs(uniform.tau(0, k) - b * std::cos(2 * w * tk)));
    }
    const double bound = hMax * hMax / 8.0;
    QVERIFY2(qError <= bound * 2 * a * w * w, qPrintable(test::formatNumber(qError)));
    QVERIFY2(dqError <= bound * 2 * a * w * w * w, qPrintable(test::formatNumber(dqError)));
    QVERIFY2(tauError <= bound * b * 4 * w * w, qPrintable(test::formatNumber(tauError)));
    // The grid does fall between the stamps: the error is of the size of the bound, not zero.
    QVERIFY(qError > 0.05 * bound * 2 * a * w * w);
    // A delay of a tenth of a step would already break the bound: nothing is shifted in time.
    QVERIFY(0.1 * step * 2 * a * w > bound * 2 * a * w * w);
}

void TestUniformLog::gridOnTheStamps_takesTheSamplesBitForBit()
{
    Eigen::VectorXd t(40);
    for (Eigen::Index k = 0; k < t.size(); ++k)
        t[k] = 0.25 * double(k); // exact in binary
    RobotLog log = sineLog(t, 1.0, 1.0, 1.0);
    log.dq.resize(0, 0);
    const UniformLog uniform = resampleUniform(log);
    QCOMPARE(uniform.period, 0.25);
    QVERIFY(bitEqual(uniform.q, log.q));
    QVERIFY(bitEqual(uniform.tau, log.tau));
    QCOMPARE(uniform.dq.size(), Eigen::Index(0));

    ResampleOptions half;
    half.period = 0.125;
    const UniformLog fine = resampleUniform(log, half);
    QCOMPARE(fine.samples(), Eigen::Index(79));
    QVERIFY(bitEqual(fine.q.col(2), log.q.col(1)));
    QCOMPARE(fine.q(0, 1), 0.5 * (log.q(0, 0) + log.q(0, 1)));
}

void TestUniformLog::gap_isRefusedNamingTheLine()
{
    QByteArray csv = "t,q1,tau1\n";
    for (int k = 0; k < 10; ++k) {
        csv += QByteArray::number(k < 5 ? k * 0.005 : 0.04 + k * 0.005) + ',' +
               QByteArray::number(0.1 * k) + ",1\n";
    }
    const RobotLog log = readRobotLog(csv, QStringLiteral("gap.csv"), 1);
    // The default: half of 1 / (50 rad/s) is 10 ms, less than 2.5 of the log's 5 ms steps.
    LEARNID_VERIFY_ERROR(resampleUniform(log),
                         QStringLiteral("gap.csv: line 7: a gap of 45 ms after the sample at t = "
                                        "0.02 s, more than the 12.5 ms allowed (--max-gap; by "
                                        "default half the time constant 1/rho of the fit's "
                                        "filter, rho = 50 rad/s, and at least 2.5 of the log's "
                                        "steps)"));
    ResampleOptions options;
    options.maxGap = 0.05;
    QCOMPARE(resampleUniform(log, options).samples(), Eigen::Index(18));
    options.maxGap = 0.0;
    options.fitBandwidth = 10.0; // a narrower filter: 50 ms
    QCOMPARE(resampleUniform(log, options).samples(), Eigen::Index(18));
    options.fitBandwidth = 50.0;
    options.period = 0.001; // the default gap does not follow the grid's period
    LEARNID_VERIFY_ERROR(resampleUniform(log, options), QStringLiteral("the 12.5 ms allowed"));
    options.maxGap = 0.01;
    LEARNID_VERIFY_ERROR(resampleUniform(log, options),
                         QStringLiteral("gap.csv: line 7: a gap of 45 ms after the sample at t = "
                                        "0.02 s, more than the 10 ms allowed (--max-gap)"));
    options.maxGap = 0.0;
    options.fitBandwidth = 0.0;
    LEARNID_VERIFY_ERROR(resampleUniform(log, options),
                         QStringLiteral("gap.csv: the fit's filter bandwidth rho (0 rad/s) must "
                                        "be positive"));
}

void TestUniformLog::defaultGap_isHalfTheFilterTimeConstant_atLeastTwoSteps()
{
    QCOMPARE(defaultMaxGap(50.0, 0.001), 0.01);     // 1 kHz: 10 ms
    QCOMPARE(defaultMaxGap(200.0, 0.0005), 0.0025); // a wider filter tolerates less
    QCOMPARE(defaultMaxGap(50.0, 0.005), 0.0125);   // 200 Hz: one lost sample, jittered
    QCOMPARE(defaultMaxGap(50.0, 0.0), 0.01);
}

void TestUniformLog::gapAtTheBound_costsTheFilteredSignalWhatTheDerivationSays()
{
    // x(t) = cos(w (t - tc)) at 1 kHz, the samples within a gap g around its peak tc lost, put
    // back on the grid and filtered by F(s)F(-s) (rho = 50 rad/s) as the fit filters every
    // signal. UniformLog.h: the filtered error is at most rho g^3 w^2 / 64 (the integral of the
    // interpolation error, w^2 g^3 / 12, times the filter's peak 3 rho / 16), and nearly that
    // at the peak of x, where x'' is largest.
    const double rho = 50.0, period = 0.001, tc = 1.0;
    const auto filteredError = [&](double w, int lostTicks) {
        const int ticks = 2001;
        RobotLog clean;
        clean.source = QStringLiteral("cos.csv");
        clean.t = Eigen::VectorXd::LinSpaced(ticks, 0.0, 2.0);
        clean.q = (w * (clean.t.array() - tc)).cos().matrix().transpose();
        clean.tau = clean.q;
        RobotLog gapped = clean;
        const int centre = 1000, first = centre - lostTicks / 2;
        std::vector<Eigen::Index> kept;
        for (Eigen::Index k = 0; k < ticks; ++k)
            if (k < first || k >= first + lostTicks)
                kept.push_back(k);
        gapped.t = clean.t(kept);
        gapped.q = clean.q(Eigen::all, kept);
        gapped.tau = gapped.q;
        ResampleOptions loose;
        loose.maxGap = 1.0;
        FilteredLog filter;
        filter.rho = rho;
        filter.period = period;
        filter.q.resize(1, ticks); // keptSamples(): every sample, none cut
        const UniformLog a = resampleUniform(clean, loose), b = resampleUniform(gapped, loose);
        if (a.samples() != ticks || b.samples() != ticks)
            return -1.0;
        return (filter.rows(b.q.transpose()) - filter.rows(a.q.transpose())).cwiseAbs().maxCoeff();
    };
    // At the bound, g = 1 / (2 rho) = 10 ms (9 ticks lost), for a component at w = rho: the
    // derivation's (rho g)^3 / 64 = 0.2 % of its amplitude.
    const double g = 0.5 / rho, bound = rho * g * g * g * rho * rho / 64.0;
    const double atTheCorner = filteredError(rho, 9);
    QVERIFY2(atTheCorner <= bound && atTheCorner > 0.8 * bound,
             qPrintable(QStringLiteral("%1 against %2").arg(atTheCorner).arg(bound)));
    // A robot's motion at 1 Hz across the 8.5 ms gaps of a Panda's logger (8 ticks lost, 9 ms
    // here): 2.4e-5 of its amplitude.
    const double w1 = 2.0 * M_PI, g1 = 0.009, bound1 = rho * g1 * g1 * g1 * w1 * w1 / 64.0;
    const double slow = filteredError(w1, 8);
    QVERIFY2(slow <= bound1 && slow > 0.8 * bound1,
             qPrintable(QStringLiteral("%1 against %2").arg(slow).arg(bound1)));
    QVERIFY(bound1 < 3e-5);
}

void TestUniformLog::staleRows_leaveAGap_refusedNamingThem()
{
    // Lines 5 to 14 repeat line 4's values: the gap from t = 0.002 to 0.013 s is 11 ms.
    QByteArray csv = "t,q1,tau1\n";
    for (int k = 0; k < 20; ++k) {
        const int value = k < 3 || k > 12 ? k : 2;
        csv += QByteArray::number(k * 0.001) + ',' + QByteArray::number(0.01 * value) + ',' +
               QByteArray::number(value) + '\n';
    }
    const RobotLog log = readRobotLog(csv, QStringLiteral("stale.csv"), 1);
    QCOMPARE(log.staleSamples(), 10);
    ResampleOptions options;
    options.maxGap = 0.005;
    LEARNID_VERIFY_ERROR(resampleUniform(log, options),
                         QStringLiteral("stale.csv: line 15: a gap of 11 ms after the sample at "
                                        "t = 0.002 s (lines 5 to 14 are stale: 10 rows that "
                                        "repeated the values of line 4 under new time stamps and "
                                        "count as missing), more than the 5 ms allowed "
                                        "(--max-gap)"));
    // Across the gap the grid interpolates: the values a steady motion would have had.
    options.maxGap = 0.012;
    const UniformLog uniform = resampleUniform(log, options);
    QCOMPARE(uniform.samples(), Eigen::Index(20));
    LEARNID_COMPARE_MATRIX(uniform.q, Eigen::RowVectorXd::LinSpaced(20, 0.0, 0.19), 1e-15);
    // One stale row is named alone.
    QByteArray one = "t,q1,tau1\n0,0,0\n0.001,0.01,1\n0.002,0.01,1\n0.003,0.03,3\n0.004,0.04,4\n";
    options.maxGap = 0.0015;
    LEARNID_VERIFY_ERROR(resampleUniform(readRobotLog(one, QStringLiteral("one.csv"), 1), options),
                         QStringLiteral("one.csv: line 5: a gap of 2 ms after the sample at t = "
                                        "0.001 s (line 4 is stale: it repeated the values of line "
                                        "3 under a new time stamp and counts as missing), more "
                                        "than the 1.5 ms allowed (--max-gap)"));
}

void TestUniformLog::repeatedRows_droppedByTheReader_resampleCleanly()
{
    const QByteArray csv = "t,q1,dq1,tau1\n0,0,1,5\n0.01,0.01,1,5\n0.01,0.01,1,5\n"
                           "0.02,0.02,1,5\n0.02,0.02,1,5\n0.03,0.03,1,5\n0.04,0.04,1,5\n";
    const RobotLog log = readRobotLog(csv, QStringLiteral("twice.csv"), 1);
    QCOMPARE(log.repeatedSamples, 2);
    const UniformLog uniform = resampleUniform(log);
    QCOMPARE(uniform.samples(), Eigen::Index(5));
    LEARNID_COMPARE_MATRIX(uniform.q, Eigen::RowVectorXd::LinSpaced(5, 0.0, 0.04), 1e-15);
}

void TestUniformLog::nominalTimes_takeSampleKAtT0PlusKT()
{
    std::mt19937 rng(7);
    const Eigen::VectorXd t = pairedJitter(1001, rng, 0.2 * step);
    const RobotLog log = sineLog(t, 0.5, 2 * M_PI, 1.0);
    ResampleOptions nominal;
    nominal.useNominalTimes = true;
    const UniformLog uniform = resampleUniform(log, nominal);
    QCOMPARE(uniform.period, (t[1000] - t[0]) / 1000.0); // the mean step
    QCOMPARE(uniform.samples(), Eigen::Index(1001));
    QVERIFY(bitEqual(uniform.q, log.q));
    QVERIFY(bitEqual(uniform.dq, log.dq));
    QVERIFY(bitEqual(uniform.tau, log.tau));
    // By the stamps, the late samples' values are moved to the grid: they differ.
    QVERIFY(!bitEqual(resampleUniform(log).q, log.q));
}

void TestUniformLog::nominalTimes_refusedWhenASampleIsMissing()
{
    Eigen::VectorXd t(400);
    for (Eigen::Index k = 0; k < t.size(); ++k)
        t[k] = double(k < 200 ? k : k + 1) * step; // sample 200 lost
    RobotLog log = sineLog(t, 0.5, 1.0, 1.0);
    for (Eigen::Index k = 0; k < t.size(); ++k)
        log.rows.push_back(int(k) + 2);
    ResampleOptions nominal;
    nominal.useNominalTimes = true;
    LEARNID_VERIFY_ERROR(resampleUniform(log, nominal),
                         QStringLiteral("sine.csv: the time stamps are off the nominal times t0 + "
                                        "k T (T = 5.013 ms) by -2.494 ms at line 201 (t = 0.995 s) "
                                        "and by 2.494 ms at line 202 (t = 1.005 s), more than half "
                                        "a step apart"));
    QCOMPARE(resampleUniform(log).samples(), Eigen::Index(401)); // by the stamps it is fine
}

void TestUniformLog::badLogsAndOptions_areRefused()
{
    Eigen::VectorXd t(10);
    for (Eigen::Index k = 0; k < t.size(); ++k)
        t[k] = double(k) * step;
    const RobotLog good = sineLog(t, 1.0, 1.0, 1.0);

    RobotLog sizes = good;
    sizes.tau.resize(2, 9);
    LEARNID_VERIFY_ERROR(resampleUniform(sizes),
                         QStringLiteral("sine.csv: a log of 10 times, 2 x 10 positions, 2 x 10 "
                                        "velocities, 2 x 9 torques"));
    RobotLog back = good;
    back.t[4] = back.t[3];
    LEARNID_VERIFY_ERROR(resampleUniform(back),
                         QStringLiteral("sine.csv: sample 5: the times must increase"));
    RobotLog nan = good;
    nan.dq(1, 6) = NAN;
    LEARNID_VERIFY_ERROR(resampleUniform(nan),
                         QStringLiteral("sine.csv: sample 7: a value is not a finite number"));

    ResampleOptions options;
    options.period = -1.0;
    LEARNID_VERIFY_ERROR(resampleUniform(good, options),
                         QStringLiteral("must be zero (the default) or positive"));
    options.period = 0.0;
    options.maxGap = NAN;
    LEARNID_VERIFY_ERROR(resampleUniform(good, options),
                         QStringLiteral("must be zero (the default) or positive"));
    options.maxGap = 1.0;
    options.period = 1e-6;
    LEARNID_VERIFY_ERROR(resampleUniform(good, options),
                         QStringLiteral("sine.csv: a period of 0.001 ms over the log's 0.045 s "
                                        "gives 45001 samples; expected 2 to 1000"));
    options.period = 1.0;
    options.maxGap = 1.0;
    LEARNID_VERIFY_ERROR(resampleUniform(good, options), QStringLiteral("gives 1 samples"));
}

void TestUniformLog::kukaLog_stampsJitterSamplesDoNot()
{
    const QString path = test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_2.csv"));
    if (path.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const RobotLog log = readRobotLogFile(path, 7, {}, QList<bool>(7, true));
    const UniformLog byStamps = resampleUniform(log);
    LEARNID_COMPARE_NEAR(byStamps.period, step, 2e-6); // median 4.9989 ms
    QVERIFY(byStamps.q.allFinite() && byStamps.dq.allFinite() && byStamps.tau.allFinite());
    QCOMPARE(byStamps.samples(), Eigen::Index(5028)); // 25.13 s at the median step

    // The stamps stay within half a step of t0 + k T: the nominal times apply, and give the
    // samples unchanged at T = 25.13 s / 5026 = 5.0000 ms.
    ResampleOptions nominal;
    nominal.useNominalTimes = true;
    const UniformLog byTick = resampleUniform(log, nominal);
    LEARNID_COMPARE_NEAR(byTick.period, 0.005, 1e-7);
    QCOMPARE(byTick.samples(), log.samples());
    QVERIFY(bitEqual(byTick.q, log.q));
    QVERIFY(bitEqual(byTick.tau, log.tau));
}

void TestUniformLog::pendulumLog_missedTicks_stampsAreTheTruth()
{
    const QString path = test::sharedDataFile(QStringLiteral("double-pendulum/trajectory_01.csv"));
    if (path.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const LogColumns columns =
        parseLogColumns(QStringLiteral("t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1"));
    const RobotLog log = readRobotLogFile(path, 2, columns, {true, true});
    const UniformLog uniform = resampleUniform(log); // the longest step, 8.4 ms, is < 5 x 2 ms
    LEARNID_COMPARE_NEAR(uniform.period, 0.002, 1e-6);
    QVERIFY(uniform.samples() > log.samples()); // the missed ticks are filled in
    QVERIFY(uniform.q.allFinite() && uniform.dq.allFinite() && uniform.tau.allFinite());
    ResampleOptions nominal;
    nominal.useNominalTimes = true;
    LEARNID_VERIFY_ERROR(resampleUniform(log, nominal),
                         QStringLiteral("trajectory_01.csv: the time stamps are off the nominal "
                                        "times t0 + k T (T = 2.011 ms) by 0 ms at line 2 (t = 0 s) "
                                        "and by 33.82 ms at line 125"));
}

QTEST_GUILESS_MAIN(TestUniformLog)
#include "tst_uniformlog.moc"
