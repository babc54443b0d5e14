#include "../support/NumericAssert.h"
#include "control/PidController.h"

#include <Eigen/Dense>
#include <QTest>
#include <complex>
#include <random>

using namespace learnid;

namespace {

using Complex = std::complex<double>;

Eigen::MatrixXcd transferAt(const StateSpace &sys, Complex s)
{
    const int n = sys.states();
    const Eigen::MatrixXcd sIminusA = s * Eigen::MatrixXcd::Identity(n, n) - sys.a.cast<Complex>();
    return sys.c.cast<Complex>() * sIminusA.partialPivLu().solve(sys.b.cast<Complex>()) +
           sys.d.cast<Complex>();
}

// Paper eq. (24), written out: kp + ki/s + kd lambda^2 s/(s + lambda)^2.
Complex pidLaw(double kp, double ki, double kd, double lambda, Complex s)
{
    return kp + ki / s + kd * lambda * lambda * s / ((s + lambda) * (s + lambda));
}

ControllerSettings singleJoint(double kp, double ki, double kd, double lambda, double ts)
{
    ControllerSettings s;
    s.samplePeriod = ts;
    s.kp = Eigen::VectorXd::Constant(1, kp);
    s.ki = Eigen::VectorXd::Constant(1, ki);
    s.kd = Eigen::VectorXd::Constant(1, kd);
    s.lambda = lambda;
    return s;
}

// Max |u[k] - (kp + ki t + kd lambda^2 t e^{-lambda t})| over 50 ms of a unit step, with the
// analytic response taken at t_k + Ts/2 (see stepResponse_matchesAnalyticPidResponse).
double stepResponseError(double kp, double ki, double kd, double lambda, double ts)
{
    PidController pid(singleJoint(kp, ki, kd, lambda, ts));
    const Eigen::VectorXd e = Eigen::VectorXd::Ones(1);
    Eigen::VectorXd u(1);
    double worst = 0.0;
    for (int k = 0; k * ts < 0.05; ++k) {
        pid.step(e, u);
        const double t = (k + 0.5) * ts;
        const double analytic = kp + ki * t + kd * lambda * lambda * t * std::exp(-lambda * t);
        worst = std::max(worst, std::abs(u[0] - analytic));
    }
    return worst;
}

} // namespace

class TestPidController : public QObject
{
    Q_OBJECT

private slots:
    void continuousStateSpace_realisesPaperPidLaw();
    void frequencyResponse_equalsContinuousPidAtPrewarpedFrequency();
    void stepResponse_matchesAnalyticPidResponse();
    void stepResponseError_isSecondOrderInSamplePeriod();
    void proportionalOnly_isExactGain();
    void reset_clearsState();
    void joints_areIndependentWithTheirOwnGains();
};

void TestPidController::continuousStateSpace_realisesPaperPidLaw()
{
    const StateSpace c = pidStateSpace(4500.0, 30.0, 600.0, 200.0);
    QCOMPARE(c.states(), 3);
    for (const Complex s : {Complex(0.0, 1.0), Complex(0.0, 200.0), Complex(-30.0, 500.0),
                            Complex(10.0, -3.0), Complex(0.0, 1e4)}) {
        const Complex expected = pidLaw(4500.0, 30.0, 600.0, 200.0, s);
        const Complex actual = transferAt(c, s)(0, 0);
        QVERIFY2(std::abs(actual - expected) < 1e-10 * std::abs(expected),
                 qPrintable(QStringLiteral("s = %1%2j").arg(s.real()).arg(s.imag())));
    }
}

// Tustin maps z = e^{j w Ts} to s = j (2/Ts) tan(w Ts/2) exactly (see tst_statespace).
void TestPidController::frequencyResponse_equalsContinuousPidAtPrewarpedFrequency()
{
    ControllerSettings settings; // the paper controller, lambda = 200, Ts = 2 ms
    const PidController pid(settings);
    QCOMPARE(pid.dof(), 2);
    const double ts = settings.samplePeriod;
    for (int j = 0; j < pid.dof(); ++j) {
        for (double w : {0.1, 1.0, 10.0, 100.0, 200.0, 700.0, 1500.0}) {
            const Complex z = std::polar(1.0, w * ts);
            const Complex s(0.0, 2.0 / ts * std::tan(w * ts / 2.0));
            const Complex expected =
                pidLaw(settings.kp[j], settings.ki[j], settings.kd[j], settings.lambda, s);
            const Complex actual = transferAt(pid.joint(j), z)(0, 0);
            QVERIFY2(std::abs(actual - expected) < 1e-9 * std::abs(expected),
                     qPrintable(QStringLiteral("joint %1, w %2: |%3 - %4|")
                                    .arg(j)
                                    .arg(w)
                                    .arg(std::abs(actual))
                                    .arg(std::abs(expected))));
        }
    }
}

// Unit step of e from rest: u(t) = kp + ki t + kd lambda^2 t e^{-lambda t}. Tustin integrates
// trapezoidally, so the sampled step (e[-1] = 0, e[0] = 1) acts as a ramp over [-Ts, 0], i.e. a
// step at -Ts/2: the samples are compared with u(t_k + Ts/2). What remains is the trapezoidal
// rule's O((lambda Ts)^2) error relative to the derivative term's scale kd lambda (its peak is
// kd lambda / e); measured 0.66 (lambda Ts)^2 kd lambda / e, tolerance (lambda Ts)^2 kd lambda.
void TestPidController::stepResponse_matchesAnalyticPidResponse()
{
    const double kp = 4500.0, ki = 30.0, kd = 600.0, lambda = 200.0;
    const double ts = 1e-4; // lambda Ts = 0.02
    const double tolerance = std::pow(lambda * ts, 2) * kd * lambda;
    LEARNID_COMPARE_NEAR(stepResponseError(kp, ki, kd, lambda, ts), 0.0, tolerance);
}

void TestPidController::stepResponseError_isSecondOrderInSamplePeriod()
{
    const double coarse = stepResponseError(4500.0, 30.0, 600.0, 200.0, 1e-4);
    const double fine = stepResponseError(4500.0, 30.0, 600.0, 200.0, 5e-5);
    QVERIFY2(coarse / fine > 3.5 && coarse / fine < 4.5,
             qPrintable(QStringLiteral("error ratio %1").arg(coarse / fine)));
}

void TestPidController::proportionalOnly_isExactGain()
{
    PidController pid(singleJoint(123.0, 0.0, 0.0, 200.0, 0.002));
    std::mt19937 rng(211);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    Eigen::VectorXd e(1), u(1);
    for (int k = 0; k < 100; ++k) {
        e[0] = value(rng);
        pid.step(e, u);
        LEARNID_COMPARE_NEAR(u[0], 123.0 * e[0], 1e-13);
    }
}

void TestPidController::reset_clearsState()
{
    const ControllerSettings settings;
    PidController used(settings);
    std::mt19937 rng(223);
    std::uniform_real_distribution<double> value(-1e-3, 1e-3);
    Eigen::MatrixXd e(2, 300);
    for (int k = 0; k < e.cols(); ++k)
        e.col(k) << value(rng), value(rng);
    auto run = [&](PidController &pid) {
        Eigen::MatrixXd u(2, e.cols());
        for (int k = 0; k < e.cols(); ++k)
            pid.step(e.col(k), u.col(k));
        return u;
    };
    const Eigen::MatrixXd first = run(used);
    const Eigen::MatrixXd again = run(used);
    QVERIFY(test::maxAbsDifference(first, again) > 1e-3); // the state carried over
    used.reset();
    LEARNID_COMPARE_MATRIX(run(used), first, 0.0);
    PidController fresh(settings);
    LEARNID_COMPARE_MATRIX(run(fresh), first, 0.0);
}

// Joint j of a two-joint controller behaves like a one-joint controller with joint j's gains,
// whatever the other joint's error.
void TestPidController::joints_areIndependentWithTheirOwnGains()
{
    ControllerSettings settings;
    settings.kp = Eigen::Vector2d(4500.0, 100.0);
    settings.ki = Eigen::Vector2d(30.0, 5.0);
    settings.kd = Eigen::Vector2d(600.0, 10.0);
    PidController both(settings);
    PidController first(singleJoint(4500.0, 30.0, 600.0, settings.lambda, settings.samplePeriod));
    PidController second(singleJoint(100.0, 5.0, 10.0, settings.lambda, settings.samplePeriod));
    std::mt19937 rng(227);
    std::uniform_real_distribution<double> value(-1e-2, 1e-2);
    Eigen::VectorXd e(2), u(2), u1(1), u2(1);
    for (int k = 0; k < 500; ++k) {
        e << value(rng), (k < 250 ? 0.0 : 50.0 * value(rng));
        both.step(e, u);
        first.step(e.head(1), u1);
        second.step(e.tail(1), u2);
        LEARNID_COMPARE_NEAR(u[0], u1[0], 1e-12 * (std::abs(u1[0]) + 1.0));
        LEARNID_COMPARE_NEAR(u[1], u2[0], 1e-12 * (std::abs(u2[0]) + 1.0));
        if (k < 250)
            QCOMPARE(u[1], 0.0);
    }
}

QTEST_GUILESS_MAIN(TestPidController)
#include "tst_pidcontroller.moc"
