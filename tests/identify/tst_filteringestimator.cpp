#include "../support/NumericAssert.h"
#include "identify/FilteringEstimator.h"

#include <Eigen/Dense>
#include <QTest>
#include <complex>
#include <functional>
#include <random>

using namespace learnid;

namespace {

using Complex = std::complex<double>;

constexpr double rho = 40.0; // docs/design.md §2
constexpr double ts = 0.002;

Eigen::MatrixXcd transferAt(const StateSpace &sys, Complex s)
{
    const int n = sys.states();
    const Eigen::MatrixXcd sIminusA = s * Eigen::MatrixXcd::Identity(n, n) - sys.a.cast<Complex>();
    return sys.c.cast<Complex>() * sIminusA.partialPivLu().solve(sys.b.cast<Complex>()) +
           sys.d.cast<Complex>();
}

// (j w')^i F(j w') at the prewarped frequency w' = (2/Ts) tan(w Ts/2): output i of the exact
// Tustin response at w.
Complex prewarpedOutput(int i, double w, double r, double period)
{
    const Complex s(0.0, 2.0 / period * std::tan(w * period / 2.0));
    return std::pow(s, i) * std::pow(r / (s + r), 3);
}

// Continuous unit-step responses of F, F s, F s^2: 1 - e^{-rt}(1 + rt + (rt)^2/2),
// its derivative (the impulse response of F) r^3 t^2 e^{-rt}/2, and r^3 e^{-rt}(t - r t^2/2).
Eigen::Vector3d stepResponse(double t, double r)
{
    if (t <= 0.0)
        return Eigen::Vector3d::Zero();
    const double x = r * t;
    const double e = std::exp(-x);
    return {1.0 - e * (1.0 + x + x * x / 2.0), r * r * r * t * t * e / 2.0,
            r * r * r * e * (t - r * t * t / 2.0)};
}

// Per output, the worst |causal - continuous| of a unit step over 1 s, each divided by the
// output's natural scale rho^i (see causalStep_matchesContinuousStepResponse).
Eigen::Vector3d stepResponseError(double period)
{
    const FilteringEstimator f(rho, period);
    const int n = int(std::lround(1.0 / period));
    Eigen::RowVectorXd x = Eigen::RowVectorXd::Ones(n);
    x[0] = 0.0;
    const Eigen::MatrixXd y = f.causal(x);
    Eigen::Vector3d worst = Eigen::Vector3d::Zero();
    for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d expected = stepResponse((k - 0.5) * period, rho);
        for (int i = 0; i < 3; ++i)
            worst[i] = std::max(worst[i], std::abs(y(i, k) - expected[i]) / std::pow(rho, i));
    }
    return worst;
}

Eigen::RowVectorXd sampled(int n, const std::function<double(double)> &signal)
{
    Eigen::RowVectorXd x(n);
    for (int k = 0; k < n; ++k)
        x[k] = signal(k * ts);
    return x;
}

} // namespace

class TestFilteringEstimator : public QObject
{
    Q_OBJECT

private slots:
    void discreteFilter_hasExactPrewarpedResponseForAllOutputs();
    void causalSinusoid_settlesToExactFrequencyResponse();
    void causalStep_matchesContinuousStepResponse();
    void causalStepError_isSecondOrderInSamplePeriod();
    void constantInput_staysConstantFromFirstToLastSample();
    void zeroPhaseSinusoid_hasZeroPhaseSquaredGainAndItsDerivatives();
    void zeroPhase_commutesWithTimeReversalAwayFromEdges();
    void zeroPhaseEdges_haveNoStartTransient();
    void singleOutputVariants_equalFirstRow();
    void causal_equalsTheDiscreteStateSpaceRunFromRest();
    void noiseGains_equalParsevalIntegralOfExactResponse();
    void anticausalLowPass_isAdjointOfLowPass();
    void emptyAndSingleSampleInputs_areHandled();
    void columnsInPlace_equalOneSignalAtATimeToTheBit();
};

// Tustin maps z = e^{j w Ts} to s = j w' exactly; each output must be (j w')^i F(j w').
// Near Nyquist F is ~1e-8 and C (zI - A)^-1 B + D cancels terms of order rho^i, so the
// tolerance adds 1e-14 rho^i of rounding to the 1e-9 relative one.
void TestFilteringEstimator::discreteFilter_hasExactPrewarpedResponseForAllOutputs()
{
    const FilteringEstimator f(rho, ts);
    QCOMPARE(f.rho(), rho);
    QCOMPARE(f.discrete().states(), 3);
    QCOMPARE(f.discrete().c.rows(), 3);
    for (double w : {0.01, 1.0, 10.0, 40.0, 100.0, 500.0, 1500.0}) {
        const Eigen::MatrixXcd h = transferAt(f.discrete(), std::polar(1.0, w * ts));
        for (int i = 0; i < 3; ++i) {
            const Complex expected = prewarpedOutput(i, w, rho, ts);
            QVERIFY2(std::abs(h(i, 0) - expected) <=
                         1e-9 * std::abs(expected) + 1e-14 * std::pow(rho, i),
                     qPrintable(QStringLiteral("output %1 at w = %2").arg(i).arg(w)));
        }
    }
}

// The filter actually run by causal() is that discrete system: after the start transient
// (e^{-rho t}, gone after 2 s) a sinusoid comes out with gain |H_i| and phase arg H_i.
void TestFilteringEstimator::causalSinusoid_settlesToExactFrequencyResponse()
{
    const FilteringEstimator f(rho, ts);
    const int n = 2000;
    for (double w : {3.0, 30.0, 200.0}) {
        const Eigen::MatrixXd y = f.causal(sampled(n, [w](double t) { return std::sin(w * t); }));
        for (int k = n / 2; k < n; ++k) {
            for (int i = 0; i < 3; ++i) {
                const Complex h = prewarpedOutput(i, w, rho, ts);
                const double expected = std::abs(h) * std::sin(w * k * ts + std::arg(h));
                LEARNID_COMPARE_NEAR(y(i, k), expected, 1e-9 * std::pow(rho, i));
            }
        }
    }
}

// The sampled step x[0] = 0, x[k>=1] = 1 is, to the trapezoidal rule Tustin implements, a ramp
// over [0, Ts]: a step at Ts/2, so sample k is compared with the continuous response at
// t_k - Ts/2. What remains is O((rho Ts)^2) relative to each output's scale rho^i: the
// trapezoidal rule's local error Ts^3/12 x''' summed over ~1/(rho Ts) steps of the response,
// plus the ramp's smoothing Ts^2/24 y''. Measured at rho Ts = 0.08: 0.03, 0.4 and 1.5 times
// (rho Ts)^2 for F, F s, F s^2 (the last one sees the step's near-impulse); tolerance
// 2 (rho Ts)^2, whose second-order scaling the next test checks.
void TestFilteringEstimator::causalStep_matchesContinuousStepResponse()
{
    const Eigen::Vector3d error = stepResponseError(ts);
    const double tolerance = 2.0 * std::pow(rho * ts, 2);
    for (int i = 0; i < 3; ++i)
        LEARNID_COMPARE_NEAR(error[i], 0.0, tolerance);
}

void TestFilteringEstimator::causalStepError_isSecondOrderInSamplePeriod()
{
    const Eigen::Vector3d coarse = stepResponseError(ts);
    const Eigen::Vector3d fine = stepResponseError(ts / 2.0);
    for (int i = 0; i < 3; ++i) {
        const double ratio = coarse[i] / fine[i];
        QVERIFY2(ratio > 3.5 && ratio < 4.5,
                 qPrintable(QStringLiteral("output %1: error ratio %2").arg(i).arg(ratio)));
    }
}

// The filter starts at rest at the first sample (and the backward pass at the last), so a
// constant has no start transient: F c = c, F s c = F s^2 c = 0 at every sample.
void TestFilteringEstimator::constantInput_staysConstantFromFirstToLastSample()
{
    const FilteringEstimator f(rho, ts);
    const double c = -3.7;
    const Eigen::RowVectorXd x = Eigen::RowVectorXd::Constant(500, c);
    Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(3, 500);
    expected.row(0).setConstant(c);
    LEARNID_COMPARE_MATRIX(f.causal(x), expected, 1e-12);
    LEARNID_COMPARE_MATRIX(f.zeroPhase(x), expected, 1e-12);
}

// Forward then backward: F(s) F(-s), response |F(j w')|^2 = (rho^2 / (rho^2 + w'^2))^3, real.
// Derivative rows: j w' |F|^2 and -w'^2 |F|^2, i.e. exactly the time derivatives of row 0 at the
// prewarped frequency (w'/w - 1 = (w Ts)^2/12 + ... = 3e-5 at 10 rad/s).
void TestFilteringEstimator::zeroPhaseSinusoid_hasZeroPhaseSquaredGainAndItsDerivatives()
{
    const FilteringEstimator f(rho, ts);
    const int n = 20000; // 40 s; transients at both ends die within 2 s
    const double w = 10.0, phase = 0.3;
    const Eigen::MatrixXd y =
        f.zeroPhase(sampled(n, [&](double t) { return std::sin(w * t + phase); }));
    const double wp = 2.0 / ts * std::tan(w * ts / 2.0);
    const double gain = std::pow(rho * rho / (rho * rho + wp * wp), 3);
    QVERIFY(gain < 0.95); // a visible attenuation: a gain error would show
    for (int k = n / 8; k < n - n / 8; ++k) {
        const double arg = w * k * ts + phase;
        LEARNID_COMPARE_NEAR(y(0, k), gain * std::sin(arg), 1e-10);
        LEARNID_COMPARE_NEAR(y(1, k), wp * gain * std::cos(arg), 1e-9);
        LEARNID_COMPARE_NEAR(y(2, k), -wp * wp * gain * std::sin(arg), 1e-8);
    }
}

// F(s) F(-s) is symmetric in time: filtering the reversed record gives the reversed result
// (derivative row negated), up to the edge transients at the ends.
void TestFilteringEstimator::zeroPhase_commutesWithTimeReversalAwayFromEdges()
{
    const FilteringEstimator f(rho, ts);
    std::mt19937 rng(307);
    std::normal_distribution<double> normal(0.0, 1.0);
    const int n = 6000;
    Eigen::RowVectorXd x(n);
    for (int k = 0; k < n; ++k)
        x[k] = normal(rng);
    const Eigen::MatrixXd y = f.zeroPhase(x);
    const Eigen::MatrixXd yReversed = f.zeroPhase(x.reverse());
    const int edge = 1500; // 3 s: the transient has decayed by e^{-120}
    for (int k = edge; k < n - edge; ++k) {
        LEARNID_COMPARE_NEAR(yReversed(0, n - 1 - k), y(0, k), 1e-11);
        LEARNID_COMPARE_NEAR(yReversed(1, n - 1 - k), -y(1, k), 1e-9);
        LEARNID_COMPARE_NEAR(yReversed(2, n - 1 - k), y(2, k), 1e-7);
    }
    // The zero-phase smoothing really acts (not an identity or a delay).
    QVERIFY(y.row(0).segment(edge, n - 2 * edge).cwiseAbs().maxCoeff() < 0.5);
}

// A record at rest at different levels at both ends with motion in the middle: the zero-phase
// output starts and ends exactly at those levels with zero derivatives (no start-up transient
// from the forward pass at the start, none from the backward pass at the end).
void TestFilteringEstimator::zeroPhaseEdges_haveNoStartTransient()
{
    const FilteringEstimator f(rho, ts);
    const int n = 5000; // 10 s
    const Eigen::RowVectorXd x = sampled(n, [](double t) {
        if (t < 3.0)
            return 1.5;
        if (t > 7.0)
            return -0.5;
        const double u = (t - 3.0) / 4.0;
        return 1.5 - 2.0 * u + 0.3 * std::sin(2.0 * M_PI * 3.0 * u);
    });
    const Eigen::MatrixXd y = f.zeroPhase(x);
    for (int k : {0, 1, 2, 50}) {
        LEARNID_COMPARE_MATRIX(y.col(k), Eigen::Vector3d(1.5, 0.0, 0.0), 1e-12);
        LEARNID_COMPARE_MATRIX(y.col(n - 1 - k), Eigen::Vector3d(-0.5, 0.0, 0.0), 1e-12);
    }
    const Eigen::MatrixXd c = f.causal(x);
    for (int k : {0, 1, 2, 50})
        LEARNID_COMPARE_MATRIX(c.col(k), Eigen::Vector3d(1.5, 0.0, 0.0), 1e-12);
}

void TestFilteringEstimator::singleOutputVariants_equalFirstRow()
{
    const FilteringEstimator f(rho, ts);
    std::mt19937 rng(311);
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::RowVectorXd x(777);
    for (int k = 0; k < x.size(); ++k)
        x[k] = normal(rng);
    LEARNID_COMPARE_MATRIX(f.lowPass(x), f.causal(x).row(0), 1e-15);
    LEARNID_COMPARE_MATRIX(f.zeroPhaseLowPass(x), f.zeroPhase(x).row(0), 1e-15);
    // Inputs given as a strided view (a row of a matrix) give the same result.
    Eigen::MatrixXd stacked(2, x.size());
    stacked.row(0).setZero();
    stacked.row(1) = x;
    LEARNID_COMPARE_MATRIX(f.causal(stacked.row(1)), f.causal(x), 0.0);
    LEARNID_COMPARE_MATRIX(f.zeroPhase(stacked.row(1)), f.zeroPhase(x), 0.0);
    // In place, one signal or several (filtered two at a time, the third alone): the same
    // numbers, to the bit.
    const Eigen::RowVectorXd expected = f.zeroPhaseLowPass(x);
    Eigen::RowVectorXd single = x;
    f.zeroPhaseLowPassInPlace(single.data(), single.size());
    LEARNID_COMPARE_MATRIX(single, expected, 0.0);
    Eigen::MatrixXd columns(x.size(), 3);
    for (int c = 0; c < 3; ++c)
        columns.col(c) = (c + 1.0) * x.transpose();
    f.zeroPhaseLowPassInPlace({columns.col(0).data(), columns.col(1).data(), columns.col(2).data()},
                              x.size());
    for (int c = 0; c < 3; ++c)
        LEARNID_COMPARE_MATRIX(columns.col(c).transpose(), f.zeroPhaseLowPass((c + 1.0) * x), 0.0);
}

// causal() runs first-order sections; the discrete state space it realises, stepped directly
// from its rest state (I - A)^-1 B x[0], gives the same three outputs to rounding.
void TestFilteringEstimator::causal_equalsTheDiscreteStateSpaceRunFromRest()
{
    const FilteringEstimator f(rho, ts);
    const StateSpace &d = f.discrete();
    std::mt19937 rng(317);
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::RowVectorXd x(1500);
    for (int k = 0; k < x.size(); ++k)
        x[k] = std::sin(0.01 * k) + 0.1 * normal(rng);
    Eigen::VectorXd state = steadyState(d, Eigen::VectorXd::Constant(1, x[0]));
    Eigen::MatrixXd expected(3, x.size());
    for (int k = 0; k < x.size(); ++k) {
        expected.col(k) = d.c * state + d.d * x[k];
        state = d.a * state + d.b * x[k];
    }
    const Eigen::MatrixXd actual = f.causal(x);
    for (int i = 0; i < 3; ++i) {
        const double scale = expected.row(i).cwiseAbs().maxCoeff();
        LEARNID_COMPARE_MATRIX(actual.row(i), expected.row(i), 1e-12 * scale);
    }
}

// Parseval: the sum of the squared impulse response of a discrete filter is
// (1/pi) int_0^pi |H(e^{j theta})|^2 d theta; with Tustin's exact response |F(j w')|^2 =
// (rho^2/(rho^2 + w'^2))^3, w' = (2/Ts) tan(theta/2). The integrand is smooth and periodic, so
// the midpoint rule with 20000 points is exact to rounding. White noise of variance s^2 leaves
// lowPass() with variance gain * s^2 (and zeroPhaseLowPass() with the integral of |F|^4).
void TestFilteringEstimator::noiseGains_equalParsevalIntegralOfExactResponse()
{
    for (double period : {0.002, 0.0005}) {
        const FilteringEstimator f(rho, period);
        const int points = 20000;
        double lowPass = 0.0, zeroPhase = 0.0;
        for (int i = 0; i < points; ++i) {
            const double theta = (i + 0.5) * M_PI / points;
            const double wp = 2.0 / period * std::tan(theta / 2.0);
            const double g = std::pow(rho * rho / (rho * rho + wp * wp), 3);
            lowPass += g / points;
            zeroPhase += g * g / points;
        }
        LEARNID_COMPARE_NEAR(f.lowPassNoiseGain(), lowPass, 1e-9 * lowPass);
        LEARNID_COMPARE_NEAR(f.zeroPhaseNoiseGain(), zeroPhase, 1e-9 * zeroPhase);
        // Continuous limit: Ts int h^2 dt = Ts 3 rho / 16 for h = rho^3 t^2 e^{-rho t} / 2.
        LEARNID_COMPARE_NEAR(f.lowPassNoiseGain(), period * 3.0 * rho / 16.0,
                             0.05 * period * 3.0 * rho / 16.0);
    }
}

// anticausalLowPass() is the adjoint of lowPass(): <F x, y> = <x, F^T y> for records that are
// at rest at zero at both ends (the steady start at the first sample adds edge terms otherwise).
void TestFilteringEstimator::anticausalLowPass_isAdjointOfLowPass()
{
    const FilteringEstimator f(rho, ts);
    std::mt19937 rng(313);
    std::normal_distribution<double> normal(0.0, 1.0);
    const int n = 3000;
    const int margin = 1000; // 2 s of zeros at each end: the responses die out within them
    Eigen::RowVectorXd x = Eigen::RowVectorXd::Zero(n), y = Eigen::RowVectorXd::Zero(n);
    for (int k = margin; k < n - margin; ++k) {
        x[k] = normal(rng);
        y[k] = normal(rng);
    }
    const double lhs = f.lowPass(x).dot(y);
    const double rhs = x.dot(f.anticausalLowPass(y));
    LEARNID_COMPARE_NEAR(lhs, rhs, 1e-12 * x.norm() * y.norm());
    // And it is F run backward in time: reversing, filtering and reversing back.
    LEARNID_COMPARE_MATRIX(f.anticausalLowPass(y), f.lowPass(y.reverse()).reverse(), 1e-15);
}

void TestFilteringEstimator::emptyAndSingleSampleInputs_areHandled()
{
    const FilteringEstimator f(rho, ts);
    const Eigen::RowVectorXd empty;
    QCOMPARE(f.causal(empty).cols(), Eigen::Index(0));
    QCOMPARE(f.zeroPhase(empty).cols(), Eigen::Index(0));
    QCOMPARE(f.lowPass(empty).size(), Eigen::Index(0));
    QCOMPARE(f.zeroPhaseLowPass(empty).size(), Eigen::Index(0));
    const Eigen::RowVectorXd one = Eigen::RowVectorXd::Constant(1, 2.5);
    LEARNID_COMPARE_MATRIX(f.causal(one), Eigen::Vector3d(2.5, 0.0, 0.0), 1e-13);
    LEARNID_COMPARE_MATRIX(f.zeroPhase(one), Eigen::Vector3d(2.5, 0.0, 0.0), 1e-13);
}

// The columns of a matrix filtered several at a time in SIMD lanes, whatever their count (full
// groups of lanes and the rest): each column as zeroPhaseLowPass() of it alone, to the bit, on a
// view with an outer stride too; a column that is identically zero stays exactly zero.
void TestFilteringEstimator::columnsInPlace_equalOneSignalAtATimeToTheBit()
{
    const FilteringEstimator f(rho, ts);
    std::mt19937 rng(29);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (const int count : {1, 2, 3, 4, 5, 7, 8, 9, 13}) {
        Eigen::MatrixXd x(700, count + 2);
        for (Eigen::Index k = 0; k < x.rows(); ++k)
            for (Eigen::Index c = 0; c < x.cols(); ++c)
                x(k, c) = std::sin(0.003 * double(k * (c + 1))) + 0.2 * normal(rng);
        x.col(count / 2).setZero();
        const Eigen::MatrixXd before = x;
        f.zeroPhaseLowPassColumnsInPlace(x.middleRows(0, 699).middleCols(1, count));
        for (Eigen::Index c = 0; c < x.cols(); ++c) {
            if (c < 1 || c > count) {
                LEARNID_COMPARE_MATRIX(x.col(c), before.col(c), 0.0);
                continue;
            }
            const Eigen::RowVectorXd one = before.col(c).head(699).transpose();
            LEARNID_COMPARE_MATRIX(x.col(c).head(699).transpose(), f.zeroPhaseLowPass(one), 0.0);
            QCOMPARE(x(699, c), before(699, c));
        }
        QVERIFY(x.col(count / 2).head(699).isZero(0.0));
    }
    Eigen::MatrixXd empty(0, 6);
    f.zeroPhaseLowPassColumnsInPlace(empty);
}

QTEST_GUILESS_MAIN(TestFilteringEstimator)
#include "tst_filteringestimator.moc"
