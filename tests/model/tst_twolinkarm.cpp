#include "../support/NumericAssert.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "model/TwoLinkArm.h"

#include <Eigen/Dense>
#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;

namespace {

struct State
{
    Eigen::Vector2d q, qd, qdd;
};

State randomState(std::mt19937 &rng)
{
    std::uniform_real_distribution<double> angle(-M_PI, M_PI);
    std::uniform_real_distribution<double> rate(-5.0, 5.0);
    std::uniform_real_distribution<double> accel(-50.0, 50.0);
    State s;
    s.q << angle(rng), angle(rng);
    s.qd << rate(rng), rate(rng);
    s.qdd << accel(rng), accel(rng);
    return s;
}

// A physically possible phi: a, c > 0 and b^2 < a c (M positive definite at every q).
Eigen::Vector3d randomPhysicalPhi(std::mt19937 &rng)
{
    std::uniform_real_distribution<double> inertia(0.5, 40.0);
    std::uniform_real_distribution<double> share(-0.95, 0.95);
    const double a = inertia(rng);
    const double c = inertia(rng);
    return {a, share(rng) * std::sqrt(a * c), c};
}

// Floating-point scale of W phi: the sum of |W_ij phi_j|, so that 1e-12 is relative to the
// terms that are added, not to a result that may cancel.
Eigen::Vector2d termScale(const Eigen::MatrixXd &w, const Eigen::Vector3d &phi)
{
    return w.cwiseAbs() * phi.cwiseAbs();
}

// A smooth joint trajectory with every component of q, qd, qdd non-trivial.
Eigen::Vector2d trajQ(double t)
{
    return {0.7 * std::sin(1.3 * t) + 0.2, 1.1 * std::cos(0.9 * t) - 0.4 * t};
}
Eigen::Vector2d trajQd(double t)
{
    return {0.91 * std::cos(1.3 * t), -0.99 * std::sin(0.9 * t) - 0.4};
}
Eigen::Vector2d trajQdd(double t)
{
    return {-1.183 * std::sin(1.3 * t), -0.891 * std::cos(0.9 * t)};
}

double kineticEnergy(const TwoLinkArm &arm, const Eigen::Vector2d &q, const Eigen::Vector2d &qd,
                     const Eigen::Vector3d &phi)
{
    Eigen::MatrixXd m(2, 2);
    arm.massMatrix(q, phi, m);
    return 0.5 * qd.dot(m * qd);
}

} // namespace

class TestTwoLinkArm : public QObject
{
    Q_OBJECT

private slots:
    void describesThreeInertiaParameters();
    void regressorTimesPhi_equalsInverseDynamics();
    void regressor_matchesPaperEquationAtRightAngle();
    void inverseDynamicsOverride_equalsMassMatrixPlusBias();
    void forwardDynamics_invertsInverseDynamics();
    void defaultForwardDynamics_agreesWithClosedForm();
    void massMatrix_equalsRegressorColumnsAtUnitAcceleration();
    void biasTorque_equalsRegressorAtZeroAcceleration();
    void massMatrix_isSymmetric();
    void nonPhysicalPhi_isDetectedWhereLinksAreAligned();
    void power_equalsRateOfKineticEnergy();
    void torque_satisfiesLagrangeEquations();
    void factory_createsEveryKnownModelAndRejectsUnknownIds();
    void rk4StepOverride_equalsGenericRk4();
    void regressorSeries_equalsTheRegressorAtEverySample();
};

void TestTwoLinkArm::describesThreeInertiaParameters()
{
    const TwoLinkArm arm;
    QCOMPARE(arm.dof(), 2);
    QCOMPARE(arm.parameterCount(), 3);
    const QList<ParameterInfo> p = arm.parameters();
    QCOMPARE(p.size(), arm.parameterCount());
    QCOMPARE(p[0].name, QStringLiteral("a"));
    QCOMPARE(p[1].name, QStringLiteral("b"));
    QCOMPARE(p[2].name, QStringLiteral("c"));
    for (const ParameterInfo &info : p) {
        QCOMPARE(info.unit, QStringLiteral("kg m^2"));
        QVERIFY(!info.description.isEmpty());
    }
}

void TestTwoLinkArm::regressorTimesPhi_equalsInverseDynamics()
{
    const TwoLinkArm arm;
    std::mt19937 rng(20240501);
    for (int trial = 0; trial < 500; ++trial) {
        const State s = randomState(rng);
        const Eigen::Vector3d phi = randomPhysicalPhi(rng);
        Eigen::MatrixXd w(2, 3);
        arm.regressor(s.q, s.qd, s.qdd, w);
        Eigen::VectorXd tau(2);
        arm.inverseDynamics(s.q, s.qd, s.qdd, phi, tau);
        const Eigen::Vector2d scale = termScale(w, phi);
        for (int j = 0; j < 2; ++j)
            LEARNID_COMPARE_NEAR((w * phi)[j], tau[j], 1e-12 * scale[j]);
        // The allocating conveniences give the same numbers.
        LEARNID_COMPARE_MATRIX(arm.regressorAt(s.q, s.qd, s.qdd), w, 0.0);
        LEARNID_COMPARE_MATRIX(arm.torqueAt(s.q, s.qd, s.qdd, phi), tau, 0.0);
    }
}

// eq. (22) by hand at theta2 - theta1 = pi/2 (cos d = 0, sin d = 1):
//   tau1 = a qdd1 - b qd2^2,   tau2 = b qd1^2 + c qdd2.
void TestTwoLinkArm::regressor_matchesPaperEquationAtRightAngle()
{
    const TwoLinkArm arm;
    const Eigen::Vector2d q(0.3, 0.3 + M_PI / 2);
    const Eigen::Vector2d qd(2.0, -3.0);
    const Eigen::Vector2d qdd(5.0, 7.0);
    Eigen::MatrixXd expected(2, 3);
    expected << 5.0, -9.0, 0.0, 0.0, 4.0, 7.0;
    LEARNID_COMPARE_MATRIX(arm.regressorAt(q, qd, qdd), expected, 1e-14);

    const Eigen::Vector3d phi(20.0, 5.0, 8.0);
    LEARNID_COMPARE_MATRIX(arm.torqueAt(q, qd, qdd, phi),
                           Eigen::Vector2d(100.0 - 45.0, 20.0 + 56.0), 1e-12);
}

void TestTwoLinkArm::inverseDynamicsOverride_equalsMassMatrixPlusBias()
{
    const TwoLinkArm arm;
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        const State s = randomState(rng);
        const Eigen::Vector3d phi = randomPhysicalPhi(rng);
        Eigen::VectorXd closed(2), generic(2);
        arm.inverseDynamics(s.q, s.qd, s.qdd, phi, closed);
        arm.RobotModel::inverseDynamics(s.q, s.qd, s.qdd, phi, generic);
        const Eigen::Vector2d scale = termScale(arm.regressorAt(s.q, s.qd, s.qdd), phi);
        for (int j = 0; j < 2; ++j)
            LEARNID_COMPARE_NEAR(closed[j], generic[j], 1e-12 * scale[j]);
    }
}

void TestTwoLinkArm::forwardDynamics_invertsInverseDynamics()
{
    const TwoLinkArm arm;
    std::mt19937 rng(11);
    for (int trial = 0; trial < 500; ++trial) {
        const State s = randomState(rng);
        const Eigen::Vector3d phi = randomPhysicalPhi(rng);
        const Eigen::VectorXd tau = arm.torqueAt(s.q, s.qd, s.qdd, phi);
        Eigen::VectorXd qdd(2);
        arm.forwardDynamics(s.q, s.qd, tau, phi, qdd);
        // M^-1 amplifies rounding by cond(M) <= (a + c)^2 / (a c - b^2 cos^2 d) for these phi.
        Eigen::MatrixXd m(2, 2);
        arm.massMatrix(s.q, phi, m);
        const double cond = m.norm() * m.inverse().norm();
        LEARNID_COMPARE_MATRIX(qdd, s.qdd, 1e-13 * cond * (s.qdd.norm() + 10.0));
    }
}

void TestTwoLinkArm::defaultForwardDynamics_agreesWithClosedForm()
{
    const TwoLinkArm arm;
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> torque(-10.0, 10.0);
    for (int trial = 0; trial < 500; ++trial) {
        const State s = randomState(rng);
        const Eigen::Vector3d phi = randomPhysicalPhi(rng);
        const Eigen::Vector2d tau(torque(rng), torque(rng));
        Eigen::VectorXd closed(2), generic(2);
        arm.forwardDynamics(s.q, s.qd, tau, phi, closed);
        arm.RobotModel::forwardDynamics(s.q, s.qd, tau, phi, generic);
        Eigen::MatrixXd m(2, 2);
        arm.massMatrix(s.q, phi, m);
        const double cond = m.norm() * m.inverse().norm();
        LEARNID_COMPARE_MATRIX(closed, generic, 1e-13 * cond * (generic.norm() + 1.0));
    }
}

// M e_j = W(q, 0, e_j) phi: the regressor and the mass matrix describe the same inertia.
void TestTwoLinkArm::massMatrix_equalsRegressorColumnsAtUnitAcceleration()
{
    const TwoLinkArm arm;
    std::mt19937 rng(17);
    for (int trial = 0; trial < 200; ++trial) {
        const State s = randomState(rng);
        const Eigen::Vector3d phi = randomPhysicalPhi(rng);
        Eigen::MatrixXd m(2, 2);
        arm.massMatrix(s.q, phi, m);
        for (int j = 0; j < 2; ++j) {
            const Eigen::Vector2d unit = Eigen::Vector2d::Unit(j);
            const Eigen::VectorXd col = arm.regressorAt(s.q, Eigen::Vector2d::Zero(), unit) * phi;
            LEARNID_COMPARE_MATRIX(m.col(j), col, 1e-13 * phi.norm());
        }
    }
}

void TestTwoLinkArm::biasTorque_equalsRegressorAtZeroAcceleration()
{
    const TwoLinkArm arm;
    std::mt19937 rng(19);
    for (int trial = 0; trial < 200; ++trial) {
        const State s = randomState(rng);
        const Eigen::Vector3d phi = randomPhysicalPhi(rng);
        Eigen::VectorXd h(2);
        arm.biasTorque(s.q, s.qd, phi, h);
        const Eigen::MatrixXd w = arm.regressorAt(s.q, s.qd, Eigen::Vector2d::Zero());
        LEARNID_COMPARE_MATRIX(h, w * phi, 1e-12 * termScale(w, phi).maxCoeff());
        // Coriolis and centripetal torques are quadratic in qd.
        Eigen::VectorXd h2(2);
        arm.biasTorque(s.q, 2.0 * s.qd, phi, h2);
        LEARNID_COMPARE_MATRIX(h2, 4.0 * h, 1e-12 * h2.norm());
    }
}

void TestTwoLinkArm::massMatrix_isSymmetric()
{
    const TwoLinkArm arm;
    std::mt19937 rng(23);
    for (int trial = 0; trial < 100; ++trial) {
        const State s = randomState(rng);
        const Eigen::Vector3d phi = randomPhysicalPhi(rng);
        Eigen::MatrixXd m(2, 2);
        arm.massMatrix(s.q, phi, m);
        QCOMPARE(m(0, 1), m(1, 0));
        QVERIFY(arm.massMatrixPositiveDefinite(s.q, phi));
    }
}

// a c < b^2 is not a robot: M = [a, b; b, c] is indefinite where cos(theta2 - theta1) = +-1.
// Where the links are at right angles M is diagonal, so only there does such phi pass.
void TestTwoLinkArm::nonPhysicalPhi_isDetectedWhereLinksAreAligned()
{
    const TwoLinkArm arm;
    const Eigen::Vector3d bad(1.0, 2.0, 1.0);
    QVERIFY(!arm.massMatrixPositiveDefinite(Eigen::Vector2d(0.4, 0.4), bad));
    QVERIFY(!arm.massMatrixPositiveDefinite(Eigen::Vector2d(0.4, 0.4 + M_PI), bad));
    QVERIFY(arm.massMatrixPositiveDefinite(Eigen::Vector2d(0.4, 0.4 + M_PI / 2), bad));
    // Threshold: with cos d = 1, a c = b^2 (1 + eps) still passes, a c = b^2 (1 - eps) does not.
    const double b = 5.0;
    const Eigen::Vector2d aligned(0.0, 0.0);
    QVERIFY(arm.massMatrixPositiveDefinite(aligned, Eigen::Vector3d(b * b * 1.001 / 8.0, b, 8.0)));
    QVERIFY(!arm.massMatrixPositiveDefinite(aligned, Eigen::Vector3d(b * b * 0.999 / 8.0, b, 8.0)));
    QVERIFY(!arm.massMatrixPositiveDefinite(aligned, Eigen::Vector3d(-1.0, 0.0, 8.0)));
    QVERIFY(arm.massMatrixPositiveDefinite(aligned, Eigen::Vector3d(20.0, 5.0, 8.0)));
}

// Power balance qd^T tau = d/dt (1/2 qd^T M qd) for a horizontal arm (no potential energy).
// It checks the Coriolis/centripetal terms against the mass matrix alone, without the regressor.
// Central difference of the energy with step h: error ~ h^2/6 |E'''| ~ 1e-9 here.
void TestTwoLinkArm::power_equalsRateOfKineticEnergy()
{
    const TwoLinkArm arm;
    const Eigen::Vector3d phi(20.0, 5.0, 8.0);
    const double h = 1e-4;
    for (double t = 0.0; t < 10.0; t += 0.37) {
        const Eigen::VectorXd tau = arm.torqueAt(trajQ(t), trajQd(t), trajQdd(t), phi);
        const double power = trajQd(t).dot(tau);
        const double dEdt = (kineticEnergy(arm, trajQ(t + h), trajQd(t + h), phi) -
                             kineticEnergy(arm, trajQ(t - h), trajQd(t - h), phi)) /
                            (2.0 * h);
        LEARNID_COMPARE_NEAR(power, dEdt, 1e-6);
    }
}

// Lagrange: tau = d/dt(M(q) qd) - dT/dq with T = 1/2 qd^T M(q) qd, both by central differences
// (the time derivative along the trajectory, dT/dq at fixed qd). Stronger than the power balance:
// it checks each joint, including terms that do no work (qd^T S qd = 0 for skew S).
void TestTwoLinkArm::torque_satisfiesLagrangeEquations()
{
    const TwoLinkArm arm;
    const Eigen::Vector3d phi(20.0, 5.0, 8.0);
    const double h = 1e-4;
    auto momentum = [&](double t) {
        Eigen::MatrixXd m(2, 2);
        arm.massMatrix(trajQ(t), phi, m);
        return Eigen::Vector2d(m * trajQd(t));
    };
    for (double t = 0.0; t < 10.0; t += 0.41) {
        const Eigen::Vector2d q = trajQ(t);
        const Eigen::Vector2d qd = trajQd(t);
        Eigen::Vector2d dTdq;
        for (int i = 0; i < 2; ++i) {
            const Eigen::Vector2d dq = h * Eigen::Vector2d::Unit(i);
            dTdq[i] = (kineticEnergy(arm, q + dq, qd, phi) - kineticEnergy(arm, q - dq, qd, phi)) /
                      (2.0 * h);
        }
        const Eigen::Vector2d expected = (momentum(t + h) - momentum(t - h)) / (2.0 * h) - dTdq;
        LEARNID_COMPARE_MATRIX(arm.torqueAt(q, qd, trajQdd(t), phi), expected, 1e-6);
    }
}

void TestTwoLinkArm::factory_createsEveryKnownModelAndRejectsUnknownIds()
{
    const QStringList ids = knownRobotModels();
    QVERIFY(ids.contains(QStringLiteral("paper-2link")));
    for (const QString &id : ids) {
        if (id == QLatin1String("urdf")) { // any URDF: it needs the file
            QVERIFY_THROWS_EXCEPTION(Error, makeRobotModel(id));
            continue;
        }
        const auto model = makeRobotModel(id);
        QVERIFY2(model, qPrintable(id));
        QCOMPARE(model->id(), id);
        QCOMPARE(model->parameters().size(), model->parameterCount());
    }
    const auto arm = makeRobotModel(QStringLiteral("paper-2link"));
    QVERIFY(dynamic_cast<const TwoLinkArm *>(arm.get()) != nullptr);
    QVERIFY(!makeRobotModel(QStringLiteral("paper-3link")));
    QVERIFY(!makeRobotModel(QString()));
}

// The arm's RK4 shares one sin/cos per step between the stages; it must give the generic RK4's
// result (four full evaluations) to rounding, for slow steps (the rotation series) and fast ones
// (the direct fallback above 0.01 rad per stage).
void TestTwoLinkArm::rk4StepOverride_equalsGenericRk4()
{
    const TwoLinkArm arm;
    const Eigen::Vector3d phi(20.0, 5.0, 8.0);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> angle(-3.0, 3.0), speed(-3.0, 3.0), torque(-8.0, 8.0);
    for (double h : {2e-4, 2e-3, 0.05}) {
        for (int i = 0; i < 200; ++i) {
            const Eigen::Vector2d q0(angle(rng), angle(rng)), qd0(speed(rng), speed(rng));
            const Eigen::Vector2d tau(torque(rng), torque(rng));
            Eigen::VectorXd q = q0, qd = qd0, qGeneric = q0, qdGeneric = qd0;
            arm.rk4Step(q, qd, tau, phi, h);
            arm.RobotModel::rk4Step(qGeneric, qdGeneric, tau, phi, h);
            QVERIFY2((q - qGeneric).cwiseAbs().maxCoeff() <
                         1e-14 * (1.0 + q0.cwiseAbs().maxCoeff()),
                     qPrintable(QString::number((q - qGeneric).cwiseAbs().maxCoeff())));
            QVERIFY2((qd - qdGeneric).cwiseAbs().maxCoeff() <
                         1e-12 * (1.0 + qd0.cwiseAbs().maxCoeff()),
                     qPrintable(QString::number((qd - qdGeneric).cwiseAbs().maxCoeff())));
        }
    }
}

// The batch override against RobotModel's default (regressor() per sample), and the layout.
void TestTwoLinkArm::regressorSeries_equalsTheRegressorAtEverySample()
{
    const TwoLinkArm arm;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> value(-3.0, 3.0);
    Eigen::MatrixXd q(2, 50), qd(2, 50), qdd(2, 50);
    for (Eigen::MatrixXd *m : {&q, &qd, &qdd})
        for (Eigen::Index i = 0; i < m->size(); ++i)
            (*m)(i) = value(rng);
    Eigen::MatrixXd batch(6, 50), generic(6, 50);
    // Random samples jump (direct sin/cos); a smooth path rotates sin/cos between anchors.
    for (Eigen::Index k = 25; k < 50; ++k)
        q.col(k) = q.col(24) + 0.003 * double(k - 24) * Eigen::Vector2d(1.0, -0.5);
    arm.regressorSeries(q, qd, qdd, batch);
    arm.RobotModel::regressorSeries(q, qd, qdd, generic);
    LEARNID_COMPARE_MATRIX(batch, generic, 1e-14);
    for (int k = 0; k < 50; ++k) {
        const Eigen::MatrixXd w = arm.regressorAt(q.col(k), qd.col(k), qdd.col(k));
        LEARNID_COMPARE_MATRIX(
            Eigen::MatrixXd(Eigen::Map<const Eigen::MatrixXd>(batch.col(k).data(), 2, 3)), w,
            1e-14);
        QCOMPARE(batch(1, k), 0.0); // structural zeros W(1, 0), W(0, 2)
        QCOMPARE(batch(4, k), 0.0);
    }
}

QTEST_GUILESS_MAIN(TestTwoLinkArm)
#include "tst_twolinkarm.moc"
