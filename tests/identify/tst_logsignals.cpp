// filterLog: the zero-phase filter F(s)F(-s) on a recorded log. A sine passes with the filter's
// real gain and no phase: q, its derivatives and tau come out as the sine's own, scaled by
// G = |F(j W)|^2 at Tustin's frequency W = (2 / T) tan(w T / 2), in step with each other.
#include "identify/LogSignals.h"
#include "model/Error.h"

#include "../support/ErrorOf.h"

#include <QTest>
#include <cmath>

using namespace learnid;

namespace {

constexpr double period = 0.005;

// A 2-joint log of sines: joint j moves as a_j sin(w_j t), its torque b_j cos(w_j t), its
// measured velocity the exact derivative.
UniformLog sineLog(double seconds)
{
    const Eigen::Index samples = Eigen::Index(std::lround(seconds / period)) + 1;
    UniformLog log;
    log.source = QStringLiteral("sine.csv");
    log.period = period;
    log.t0 = 1.0;
    log.q.resize(2, samples);
    log.dq.resize(2, samples);
    log.tau.resize(2, samples);
    for (Eigen::Index k = 0; k < samples; ++k) {
        const double t = log.time(k);
        log.q.col(k) << 0.5 * std::sin(2.0 * t), 0.2 * std::sin(5.0 * t);
        log.dq.col(k) << 1.0 * std::cos(2.0 * t), 1.0 * std::cos(5.0 * t);
        log.tau.col(k) << 3.0 * std::cos(2.0 * t), -1.0 * std::cos(5.0 * t);
    }
    return log;
}

double gain(double w, double rho)
{
    const double warped = 2.0 / period * std::tan(0.5 * w * period);
    return std::pow(1.0 + warped * warped / (rho * rho), -3.0);
}

} // namespace

class TestLogSignals : public QObject
{
    Q_OBJECT

private slots:
    void sine_passesWithTheFilterGainAndNoPhase_data();
    void sine_passesWithTheFilterGainAndNoPhase();
    void edges_areCutBySettlingTime();
    void stride_keepsEveryKthSample();
    void shortLog_isRefusedNamingIt();
    void measuredVelocity_withoutColumns_isRefused();
};

void TestLogSignals::sine_passesWithTheFilterGainAndNoPhase_data()
{
    QTest::addColumn<int>("velocity");
    QTest::newRow("from q") << int(LogFilterSettings::Velocity::FromPositions);
    QTest::newRow("measured") << int(LogFilterSettings::Velocity::Measured);
}

void TestLogSignals::sine_passesWithTheFilterGainAndNoPhase()
{
    QFETCH(int, velocity);
    LogFilterSettings s;
    s.velocity = LogFilterSettings::Velocity(velocity);
    const UniformLog log = sineLog(20.0);
    const FilteredLog f = filterLog(log, s);
    const Eigen::MatrixXd tau = f.rows(f.tau.transpose()); // kept x n
    QCOMPARE(tau.rows(), f.keptSamples());
    const double w[2] = {2.0, 5.0};
    const double a[2] = {0.5, 0.2};
    const double b[2] = {3.0, -1.0};
    double worst = 0.0;
    for (Eigen::Index k = 0; k < f.keptSamples(); ++k) {
        const double t = f.keptTime(k);
        const Eigen::Index at = f.cut + k;
        QCOMPARE(t, log.time(at));
        for (int j = 0; j < 2; ++j) {
            const double g = gain(w[j], s.derivativeRho);
            const double sn = std::sin(w[j] * t);
            const double cs = std::cos(w[j] * t);
            worst = std::max(
                {worst, std::abs(f.q(j, at) - g * a[j] * sn) / a[j],
                 std::abs(f.qd(j, at) - g * a[j] * w[j] * cs) / (a[j] * w[j]),
                 std::abs(f.qdd(j, at) + g * a[j] * w[j] * w[j] * sn) / (a[j] * w[j] * w[j]),
                 std::abs(tau(k, j) - gain(w[j], s.rho) * b[j] * cs) / std::abs(b[j])});
        }
    }
    // The edges' start-up has decayed below 1e-3 of the signal (the settling rule) and the
    // measured velocity's derivative is Tustin's, off by (W / w - 1) < 1e-4 here.
    QVERIFY2(worst < 2e-3, qPrintable(QString::number(worst)));
    QVERIFY(gain(5.0, s.rho) < 0.99); // the test sees the gain, not 1
}

void TestLogSignals::edges_areCutBySettlingTime()
{
    const UniformLog log = sineLog(10.0);
    LogFilterSettings s;
    const FilteredLog f = filterLog(log, s);
    const double slower = std::min(s.rho, s.derivativeRho);
    const Eigen::Index cut = Eigen::Index(std::ceil(filterSettlingTime(slower) / period));
    QCOMPARE(f.cut, cut);
    QCOMPARE(f.keptTime(0), log.time(cut));
    QCOMPARE(f.keptSamples(), log.samples() - 2 * cut);
    QCOMPARE(f.q.cols(), log.samples());
}

void TestLogSignals::stride_keepsEveryKthSample()
{
    const UniformLog log = sineLog(10.0);
    LogFilterSettings one;
    LogFilterSettings three;
    three.stride = 3;
    const FilteredLog a = filterLog(log, one);
    const FilteredLog b = filterLog(log, three);
    QCOMPARE(b.keptSamples(), (a.keptSamples() - 1) / 3 + 1);
    const Eigen::MatrixXd ra = a.rows(a.tau.transpose());
    const Eigen::MatrixXd rb = b.rows(b.tau.transpose());
    for (Eigen::Index k = 0; k < b.keptSamples(); ++k) {
        QCOMPARE(b.keptTime(k), a.keptTime(3 * k));
        QCOMPARE(rb.row(k), ra.row(3 * k));
    }
}

void TestLogSignals::shortLog_isRefusedNamingIt()
{
    const QString message = test::errorOf([] { filterLog(sineLog(0.4), LogFilterSettings{}); });
    QVERIFY2(message.startsWith(QStringLiteral("sine.csv: 0.405 s of data is too short")),
             qPrintable(message));
}

void TestLogSignals::measuredVelocity_withoutColumns_isRefused()
{
    UniformLog log = sineLog(5.0);
    log.dq.resize(0, 0);
    LogFilterSettings s;
    s.velocity = LogFilterSettings::Velocity::Measured;
    const QString message = test::errorOf([&] { filterLog(log, s); });
    QVERIFY2(message.startsWith(QStringLiteral("sine.csv: the log has no measured velocities")),
             qPrintable(message));
    s.velocity = LogFilterSettings::Velocity::Auto; // falls back to q
    QCOMPARE(filterLog(log, s).qd, filterLog(sineLog(5.0),
                                             [] {
                                                 LogFilterSettings q;
                                                 q.velocity =
                                                     LogFilterSettings::Velocity::FromPositions;
                                                 return q;
                                             }())
                                       .qd);
}

QTEST_APPLESS_MAIN(TestLogSignals)
#include "tst_logsignals.moc"
