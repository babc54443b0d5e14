// ArmSimulation: the per-sample physics shared by SimulatedRobot and the CAN drive simulator.
#include "model/ModelFactory.h"
#include "robot/ArmSimulation.h"

#include <QTest>
#include <cmath>

using namespace learnid;

class TestArmSimulation : public QObject
{
    Q_OBJECT

private slots:
    void integrate_isSubstepsRk4StepsWithTheTorqueHeld();
    void fixedAndDynamicSize_moveTheArmIdentically();
    void twoLinkInlinePath_followsTheGenericRk4OverASecond();
    void measureAngles_roundsToWholeEncoderCounts();
    void torqueNoise_isTheSeededStreamScaledByTheLimit();
    void brakedJoint_keepsItsAngleWithZeroVelocity();
};

void TestArmSimulation::integrate_isSubstepsRk4StepsWithTheTorqueHeld()
{
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    const Eigen::Vector3d phi(20, 5, 8);
    MeasurementOptions options;
    options.substeps = 7;
    ArmSimulation<> arm(model, phi, options, 0.002);
    arm.reset(Eigen::Vector2d(0.1, 1.2));
    const Eigen::Vector2d tau(1.5, -0.7);
    arm.integrate(tau);
    Eigen::VectorXd q = Eigen::Vector2d(0.1, 1.2), qd = Eigen::Vector2d::Zero();
    for (int s = 0; s < 7; ++s)
        model->rk4Step(q, qd, tau, phi, 0.002 / 7);
    // The 2-link arm's sample period carries one sin/cos through its sub-steps by rotations:
    // the same steps to rounding.
    QVERIFY((Eigen::VectorXd(arm.q()) - q).cwiseAbs().maxCoeff() < 1e-15);
    QVERIFY((Eigen::VectorXd(arm.qd()) - qd).cwiseAbs().maxCoeff() < 1e-13);
    QVERIFY(!(arm.q() - Eigen::Vector2d(0.1, 1.2)).isZero()); // it moved
}

void TestArmSimulation::fixedAndDynamicSize_moveTheArmIdentically()
{
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    const Eigen::Vector3d phi(20, 5, 8);
    ArmSimulation<2> fixed(model, phi, {}, 0.002);
    ArmSimulation<> dynamic(model, phi, {}, 0.002);
    fixed.reset(Eigen::Vector2d(-0.3, 1.9));
    dynamic.reset(Eigen::Vector2d(-0.3, 1.9));
    for (int k = 0; k < 100; ++k) {
        const Eigen::Vector2d tau(std::sin(0.1 * k), std::cos(0.07 * k));
        fixed.integrate(tau);
        dynamic.integrate(tau);
    }
    QCOMPARE(Eigen::VectorXd(fixed.q()), Eigen::VectorXd(dynamic.q()));
}

// The inline 2-link path (one sin/cos per sample, carried through the sub-steps by rotations)
// against RobotModel's generic RK4 (four forward-dynamics evaluations with their own sin/cos per
// step) over 500 samples of fast motion: they agree to accumulated rounding.
void TestArmSimulation::twoLinkInlinePath_followsTheGenericRk4OverASecond()
{
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    const Eigen::Vector3d phi(2, 0.5, 0.8); // a light arm: several rad/s
    ArmSimulation<2> arm(model, phi, {}, 0.002);
    arm.reset(Eigen::Vector2d(-0.3, 1.9));
    Eigen::VectorXd q = Eigen::Vector2d(-0.3, 1.9), qd = Eigen::Vector2d::Zero();
    double fastest = 0.0;
    for (int k = 0; k < 500; ++k) {
        const Eigen::Vector2d tau(6.0 + std::sin(0.02 * k), -3.0 + std::cos(0.013 * k));
        arm.integrate(tau);
        for (int s = 0; s < 10; ++s)
            model->RobotModel::rk4Step(q, qd, tau, phi, 0.0002);
        fastest = std::max(fastest, qd.cwiseAbs().maxCoeff());
    }
    QVERIFY(fastest > 1.0); // the rotations covered large angles
    QVERIFY2((Eigen::VectorXd(arm.q()) - q).cwiseAbs().maxCoeff() < 1e-12,
             qPrintable(QString::number((Eigen::VectorXd(arm.q()) - q).cwiseAbs().maxCoeff())));
    QVERIFY((Eigen::VectorXd(arm.qd()) - qd).cwiseAbs().maxCoeff() < 1e-11);
}

void TestArmSimulation::measureAngles_roundsToWholeEncoderCounts()
{
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    MeasurementOptions options;
    options.encoderCounts = 1000;
    ArmSimulation<> arm(model, Eigen::Vector3d(20, 5, 8), options, 0.002);
    const double count = 2.0 * M_PI / 1000;
    arm.reset(Eigen::Vector2d(10.4 * count, -3.6 * count));
    Eigen::VectorXd measured(2);
    arm.measureAngles(measured);
    QCOMPARE(measured, Eigen::VectorXd(Eigen::Vector2d(10 * count, -4 * count)));
    QCOMPARE(arm.encoderCount(1, count), qint64(-4));

    ArmSimulation<> ideal(model, Eigen::Vector3d(20, 5, 8), {}, 0.002);
    ideal.reset(Eigen::Vector2d(0.123456789, 1));
    ideal.measureAngles(measured);
    QCOMPARE(measured[0], 0.123456789);
}

void TestArmSimulation::torqueNoise_isTheSeededStreamScaledByTheLimit()
{
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    MeasurementOptions options;
    options.torqueNoise = 0.01;
    options.seed = 42;
    ArmSimulation<> arm(model, Eigen::Vector3d(20, 5, 8), options, 0.002, 3);
    Eigen::VectorXd tau = Eigen::Vector2d(1, 2);
    arm.addTorqueNoise(tau, Eigen::Vector2d(8, 4));
    std::seed_seq seq{quint64(42), quint64(3)};
    std::mt19937_64 rng(seq);
    std::normal_distribution<double> normal(0.0, 1.0);
    const double n0 = normal(rng);
    const double n1 = normal(rng);
    QCOMPARE(tau[0], 1 + 0.01 * 8 * n0);
    QCOMPARE(tau[1], 2 + 0.01 * 4 * n1);
}

void TestArmSimulation::brakedJoint_keepsItsAngleWithZeroVelocity()
{
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    ArmSimulation<> arm(model, Eigen::Vector3d(20, 5, 8), {}, 0.002);
    arm.reset(Eigen::Vector2d(0.2, 1.0));
    arm.integrate(Eigen::Vector2d(1, 1)); // both joints move
    arm.setBraked(1, true);
    const double held = arm.q()[1];
    QCOMPARE(arm.qd()[1], 0.0);
    for (int k = 0; k < 50; ++k)
        arm.integrate(Eigen::Vector2d(1, 1));
    QCOMPARE(arm.q()[1], held);
    QCOMPARE(arm.qd()[1], 0.0);
    QVERIFY(arm.qd()[0] > 0.0);
    arm.setBraked(1, false);
    arm.integrate(Eigen::Vector2d(1, 1));
    QVERIFY(arm.q()[1] != held);
}

QTEST_GUILESS_MAIN(TestArmSimulation)
#include "tst_armsimulation.moc"
