#include "../support/NumericAssert.h"
#include "control/StateSpace.h"

#include <Eigen/Dense>
#include <QTest>
#include <complex>
#include <random>

using namespace learnid;

namespace {

using Complex = std::complex<double>;

// C (s I - A)^-1 B + D at a complex point s (continuous s, or discrete z).
Eigen::MatrixXcd transferAt(const StateSpace &sys, Complex s)
{
    const int n = sys.states();
    const Eigen::MatrixXcd a = sys.a.cast<Complex>();
    const Eigen::MatrixXcd sIminusA = s * Eigen::MatrixXcd::Identity(n, n) - a;
    return sys.c.cast<Complex>() * sIminusA.partialPivLu().solve(sys.b.cast<Complex>()) +
           sys.d.cast<Complex>();
}

// A random stable system: A = S - (|S|_2 + margin) I has every eigenvalue in Re < -margin.
StateSpace randomStableSystem(std::mt19937 &rng, int n, int inputs, int outputs)
{
    std::normal_distribution<double> normal(0.0, 1.0);
    auto randomMatrix = [&](int r, int c, double scale) {
        Eigen::MatrixXd m(r, c);
        for (int i = 0; i < r; ++i)
            for (int j = 0; j < c; ++j)
                m(i, j) = scale * normal(rng);
        return m;
    };
    StateSpace s;
    const Eigen::MatrixXd raw = randomMatrix(n, n, 20.0);
    const double norm2 = Eigen::JacobiSVD<Eigen::MatrixXd>(raw).singularValues()[0];
    s.a = raw - (norm2 + 1.0) * Eigen::MatrixXd::Identity(n, n);
    s.b = randomMatrix(n, inputs, 3.0);
    s.c = randomMatrix(outputs, n, 2.0);
    s.d = randomMatrix(outputs, inputs, 1.0);
    return s;
}

double relativeDifference(const Eigen::MatrixXcd &a, const Eigen::MatrixXcd &b)
{
    return (a - b).norm() / std::max(b.norm(), 1e-300);
}

// y[k] of a discrete system started at x[0] = x0 under the inputs u (inputs x N).
Eigen::MatrixXd simulate(const StateSpace &d, const Eigen::MatrixXd &u, Eigen::VectorXd x)
{
    Eigen::MatrixXd y(d.c.rows(), u.cols());
    for (int k = 0; k < u.cols(); ++k) {
        y.col(k) = d.c * x + d.d * u.col(k);
        x = d.a * x + d.b * u.col(k);
    }
    return y;
}

} // namespace

class TestStateSpace : public QObject
{
    Q_OBJECT

private slots:
    void tustin_frequencyResponseEqualsContinuousAtPrewarpedFrequency();
    void tustin_ofIntegrator_isTrapezoidalRule();
    void tustin_keepsStableSystemsStable();
    void zeroOrderHold_ofIntegrators_isExact();
    void zeroOrderHold_ofFirstOrderLag_matchesAnalyticStepResponse();
    void zeroOrderHold_ofOscillator_matchesAnalyticResponseToHeldInput();
    void steadyState_isFixedPointWithContinuousDcGain();
};

// The bilinear map z = (1 + s T/2)/(1 - s T/2) sends s = j (2/T) tan(w T/2) to z = e^{j w T}, so
// H_d(e^{j w T}) = H_c(j (2/T) tan(w T/2)) holds exactly, for any realisation of H_d.
void TestStateSpace::tustin_frequencyResponseEqualsContinuousAtPrewarpedFrequency()
{
    std::mt19937 rng(101);
    const double ts = 0.01;
    for (int trial = 0; trial < 40; ++trial) {
        const int n = 1 + trial % 5;
        const StateSpace c = randomStableSystem(rng, n, 1 + trial % 3, 1 + (trial / 3) % 3);
        const StateSpace d = tustin(c, ts);
        QCOMPARE(d.a.rows(), c.a.rows());
        QCOMPARE(d.b.cols(), c.b.cols());
        QCOMPARE(d.c.rows(), c.c.rows());
        for (double wt : {1e-3, 0.05, 0.4, 1.0, 2.0, 3.0}) {
            const double w = wt / ts;
            const Complex z = std::polar(1.0, w * ts);
            const Complex s(0.0, 2.0 / ts * std::tan(w * ts / 2.0));
            const double rel = relativeDifference(transferAt(d, z), transferAt(c, s));
            QVERIFY2(
                rel < 1e-9,
                qPrintable(QStringLiteral("n %1, wT %2: relative %3").arg(n).arg(wt).arg(rel)));
        }
    }
}

// Tustin of 1/s: x[k+1] = x[k] + T u[k], y[k] = x[k] + T/2 u[k], i.e. the trapezoidal
// integral of the samples (with u[-1] = 0).
void TestStateSpace::tustin_ofIntegrator_isTrapezoidalRule()
{
    StateSpace integrator;
    integrator.a = Eigen::MatrixXd::Zero(1, 1);
    integrator.b = Eigen::MatrixXd::Ones(1, 1);
    integrator.c = Eigen::MatrixXd::Ones(1, 1);
    integrator.d = Eigen::MatrixXd::Zero(1, 1);
    const double ts = 0.002;
    const StateSpace d = tustin(integrator, ts);
    std::mt19937 rng(103);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    Eigen::MatrixXd u(1, 200);
    for (int k = 0; k < u.cols(); ++k)
        u(0, k) = value(rng);
    const Eigen::MatrixXd y = simulate(d, u, Eigen::VectorXd::Zero(1));
    double trapezoid = 0.0;
    double previous = 0.0;
    for (int k = 0; k < u.cols(); ++k) {
        trapezoid += 0.5 * ts * (previous + u(0, k));
        previous = u(0, k);
        LEARNID_COMPARE_NEAR(y(0, k), trapezoid, 1e-15);
    }
}

void TestStateSpace::tustin_keepsStableSystemsStable()
{
    std::mt19937 rng(107);
    for (int trial = 0; trial < 20; ++trial) {
        const StateSpace c = randomStableSystem(rng, 4, 1, 1);
        for (double ts : {1e-4, 0.01, 1.0}) {
            const Eigen::VectorXcd eig = tustin(c, ts).a.eigenvalues();
            QVERIFY(eig.cwiseAbs().maxCoeff() < 1.0);
        }
    }
}

// 1/s and 1/s^2 held over T: x[k+1] = x[k] + T u and [1 T; 0 1] x + [T^2/2; T] u, exactly.
void TestStateSpace::zeroOrderHold_ofIntegrators_isExact()
{
    const double ts = 0.002;
    StateSpace single;
    single.a = Eigen::MatrixXd::Zero(1, 1);
    single.b = Eigen::MatrixXd::Ones(1, 1);
    single.c = Eigen::MatrixXd::Ones(1, 1);
    single.d = Eigen::MatrixXd::Zero(1, 1);
    const StateSpace d1 = zeroOrderHold(single, ts);
    LEARNID_COMPARE_NEAR(d1.a(0, 0), 1.0, 1e-15);
    LEARNID_COMPARE_NEAR(d1.b(0, 0), ts, 1e-18);

    StateSpace dbl;
    dbl.a = Eigen::MatrixXd::Zero(2, 2);
    dbl.a(0, 1) = 1.0;
    dbl.b = Eigen::MatrixXd::Zero(2, 1);
    dbl.b(1, 0) = 1.0;
    dbl.c = Eigen::MatrixXd::Identity(2, 2);
    dbl.d = Eigen::MatrixXd::Zero(2, 1);
    const StateSpace d2 = zeroOrderHold(dbl, ts);
    Eigen::Matrix2d aExpected;
    aExpected << 1.0, ts, 0.0, 1.0;
    LEARNID_COMPARE_MATRIX(d2.a, aExpected, 1e-15);
    LEARNID_COMPARE_MATRIX(d2.b, Eigen::Vector2d(ts * ts / 2.0, ts), 1e-18);
    LEARNID_COMPARE_MATRIX(d2.c, dbl.c, 0.0);
    LEARNID_COMPARE_MATRIX(d2.d, dbl.d, 0.0);
}

// x' = -a x + a u: under a unit step x(t) = 1 - e^{-a t}, which ZOH reproduces at the samples.
void TestStateSpace::zeroOrderHold_ofFirstOrderLag_matchesAnalyticStepResponse()
{
    const double a = 7.0;
    const double ts = 0.01;
    StateSpace lag;
    lag.a = Eigen::MatrixXd::Constant(1, 1, -a);
    lag.b = Eigen::MatrixXd::Constant(1, 1, a);
    lag.c = Eigen::MatrixXd::Ones(1, 1);
    lag.d = Eigen::MatrixXd::Zero(1, 1);
    const StateSpace d = zeroOrderHold(lag, ts);
    LEARNID_COMPARE_NEAR(d.a(0, 0), std::exp(-a * ts), 1e-15);
    LEARNID_COMPARE_NEAR(d.b(0, 0), 1.0 - std::exp(-a * ts), 1e-15);
    const Eigen::MatrixXd y = simulate(d, Eigen::MatrixXd::Ones(1, 300), Eigen::VectorXd::Zero(1));
    for (int k = 0; k < 300; ++k)
        LEARNID_COMPARE_NEAR(y(0, k), 1.0 - std::exp(-a * k * ts), 1e-13);
}

// x'' = -w^2 x + u from rest. With u held at u0 on [0, t1) and u1 after:
//   x(t) = u0/w^2 (1 - cos w t) for t <= t1, then the response to the step u1 - u0 at t1 adds.
void TestStateSpace::zeroOrderHold_ofOscillator_matchesAnalyticResponseToHeldInput()
{
    const double w = 30.0;
    const double ts = 0.004;
    StateSpace osc;
    osc.a = Eigen::MatrixXd::Zero(2, 2);
    osc.a(0, 1) = 1.0;
    osc.a(1, 0) = -w * w;
    osc.b = Eigen::MatrixXd::Zero(2, 1);
    osc.b(1, 0) = 1.0;
    osc.c = Eigen::MatrixXd::Identity(2, 2);
    osc.d = Eigen::MatrixXd::Zero(2, 1);
    const StateSpace d = zeroOrderHold(osc, ts);

    const int n = 400;
    const int switchSample = 137;
    const double u0 = 2.0, u1 = -0.5;
    Eigen::MatrixXd u(1, n);
    for (int k = 0; k < n; ++k)
        u(0, k) = k < switchSample ? u0 : u1;
    const Eigen::MatrixXd y = simulate(d, u, Eigen::VectorXd::Zero(2));
    auto step = [&](double amplitude, double t) {
        return t <= 0.0 ? Eigen::Vector2d::Zero().eval()
                        : Eigen::Vector2d(amplitude / (w * w) * (1.0 - std::cos(w * t)),
                                          amplitude / w * std::sin(w * t));
    };
    for (int k = 0; k < n; ++k) {
        const double t = k * ts;
        const Eigen::Vector2d expected = step(u0, t) + step(u1 - u0, t - switchSample * ts);
        LEARNID_COMPARE_MATRIX(y.col(k), expected, 1e-13);
    }
}

// At rest x = A x + B u, and the output equals the continuous DC gain D - C A^-1 B (z = 1 maps to
// s = 0 under both Tustin and ZOH).
void TestStateSpace::steadyState_isFixedPointWithContinuousDcGain()
{
    std::mt19937 rng(109);
    std::uniform_real_distribution<double> value(-2.0, 2.0);
    for (int trial = 0; trial < 20; ++trial) {
        const int inputs = 1 + trial % 3;
        const StateSpace c = randomStableSystem(rng, 1 + trial % 5, inputs, 2);
        Eigen::VectorXd u(inputs);
        for (int i = 0; i < inputs; ++i)
            u[i] = value(rng);
        const Eigen::VectorXd dc = (c.d - c.c * c.a.partialPivLu().solve(c.b)) * u;
        for (const StateSpace &d : {tustin(c, 0.01), zeroOrderHold(c, 0.01)}) {
            const Eigen::VectorXd x = steadyState(d, u);
            QCOMPARE(x.size(), Eigen::Index(d.states()));
            LEARNID_COMPARE_MATRIX(d.a * x + d.b * u, x, 1e-12 * (x.norm() + 1.0));
            LEARNID_COMPARE_MATRIX(d.c * x + d.d * u, dc, 1e-10 * (dc.norm() + 1.0));
            // Simulating from the steady state stays there.
            const Eigen::MatrixXd y = simulate(d, u.replicate(1, 50), x);
            LEARNID_COMPARE_MATRIX(y, dc.replicate(1, 50), 1e-10 * (dc.norm() + 1.0));
        }
    }
}

QTEST_GUILESS_MAIN(TestStateSpace)
#include "tst_statespace.moc"
