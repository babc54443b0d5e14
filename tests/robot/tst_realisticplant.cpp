// RealisticPlant: Stribeck friction with stiction, rotor inertia, elastic joints and the torque
// sensor's offset and lag, each held against an equation.
#include "model/ChainModel.h"
#include "model/ModelFactory.h"
#include "robot/ArmSimulation.h"
#include "robot/RealisticPlant.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using namespace learnid;

namespace {

constexpr double kMass = 2.0;    // [kg]
constexpr double kCom = 0.2;     // [m] along the link's x
constexpr double kIzzCom = 0.05; // [kg m^2] about the centre of mass
constexpr double kGravity = 9.81;

// One link on a revolute joint: its axis along y (gravity acts on it) or z (gravity along the
// axis: no gravity torque). Viscous friction fv [N m s/rad] as URDF damping.
std::shared_ptr<const RobotModel> singleLink(const QTemporaryDir &dir, const char *axis, double fv)
{
    const QString path = dir.filePath(QStringLiteral("link-%1.urdf").arg(QLatin1String(axis)));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return nullptr;
    file.write(QStringLiteral(R"(<robot name="one">
  <link name="base"/>
  <link name="arm">
    <inertial><origin xyz="%1 0 0"/><mass value="%2"/>
      <inertia ixx="%3" ixy="0" ixz="0" iyy="%3" iyz="0" izz="%3"/></inertial>
  </link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="%4"/><limit lower="-3" upper="3" effort="100" velocity="5"/>
    <dynamics damping="%5" friction="0"/></joint>
</robot>)")
                   .arg(kCom)
                   .arg(kMass)
                   .arg(kIzzCom)
                   .arg(QLatin1String(axis))
                   .arg(fv)
                   .toUtf8());
    file.close();
    UrdfRobotSettings urdf;
    urdf.file = path;
    return makeRobotModel(QStringLiteral("urdf"), urdf);
}

Eigen::VectorXd cadPhi(const RobotModel &model)
{
    const auto &chain = dynamic_cast<const ChainModel &>(model);
    return chain.baseFromStandard(chain.cadStandard());
}

// Link inertia about the joint axis: I_c + m l^2.
constexpr double kAxisInertia = kIzzCom + kMass * kCom * kCom;

} // namespace

class TestRealisticPlant : public QObject
{
    Q_OBJECT

private slots:
    void staticFriction_holdsBelowFsAndLetsGoAbove();
    void slidingFriction_isTheStribeckCurve();
    void elasticJoint_springCarriesTheLinksGravityTorqueAtRest();
    void elasticJoint_oscillatesAtTheTwoMassFrequency();
    void sensorLag_stepResponseReachesOneMinusInverseEAtTau();
    void armature_addsIaTimesAccelerationToTheTorqueNeeded();
    void sensorOffset_shiftsTheReadingByExactlyTheOffset();
    void armSimulation_motorEncoderReadsTheMotorAngle();
};

void TestRealisticPlant::staticFriction_holdsBelowFsAndLetsGoAbove()
{
    // The paper's arm is horizontal: at rest no torque acts but the drive's.
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    const Eigen::Vector3d phi(20, 5, 8);
    JointRealism r;
    r.coulomb = Eigen::Vector2d(1.0, 0.5);
    r.staticFriction = Eigen::Vector2d(2.0, 1.0);
    r.stribeckVelocity = 0.1;
    const Eigen::Vector2d q0(0.3, 1.4);
    for (const double fraction : {0.9, 1.1}) {
        RealisticPlant plant(model, phi, r, 0.002, 10);
        plant.reset(q0);
        const Eigen::Vector2d tau(fraction * 2.0, 0.0);
        for (int k = 0; k < 10; ++k) // 20 ms
            plant.advance(tau);
        if (fraction < 1.0) {
            QCOMPARE(plant.q()[0], q0[0]); // exactly at rest
            QCOMPARE(plant.qd()[0], 0.0);
            QVERIFY(plant.stuck(0));
            continue;
        }
        // Broken free: q1'' = (tau - Fs) / M11 while |q'| << vs (friction still ~ Fs) and joint 2
        // still stuck, so q1 - q1(0) = (tau - Fs) t^2 / (2 M11).
        Eigen::MatrixXd mass(2, 2);
        model->massMatrix(q0, phi, mass);
        const double t = 0.02;
        const double expected = (tau[0] - 2.0) * t * t / (2.0 * mass(0, 0));
        QVERIFY(plant.stuck(1));
        QVERIFY2(
            std::abs((plant.q()[0] - q0[0]) / expected - 1.0) < 0.02,
            qPrintable(
                QStringLiteral("moved %1, expected %2").arg(plant.q()[0] - q0[0]).arg(expected)));
    }
}

void TestRealisticPlant::slidingFriction_isTheStribeckCurve()
{
    // Sliding at v under a drive torque tau, q'' = (tau - f(v)) / J: the acceleration measured
    // over one short sample gives the friction, compared with the formula at vs, 2 vs, 0.
    QTemporaryDir dir;
    const auto model = singleLink(dir, "0 0 1", 0.0); // no gravity torque, no viscous term
    QVERIFY(model);
    JointRealism r;
    r.coulomb = Eigen::VectorXd::Constant(1, 1.0);
    r.staticFriction = Eigen::VectorXd::Constant(1, 3.0);
    r.stribeckVelocity = 0.2;
    // A large drive torque accelerates the link to v; the friction is read at the end.
    RealisticPlant plant(model, cadPhi(*model), r, 1e-4, 10);
    plant.reset(Eigen::VectorXd::Zero(1));
    const Eigen::VectorXd push = Eigen::VectorXd::Constant(1, 3.5);
    bool hit[3] = {false, false, false}; // v near vs, near 2 vs, far above
    for (int k = 0; k < 20000; ++k) {
        const double v0 = plant.qd()[0];
        plant.advance(push);
        const double a = (plant.qd()[0] - v0) / 1e-4;
        const double v = 0.5 * (v0 + plant.qd()[0]);
        const double friction = push[0] - kAxisInertia * a;
        const double x = v / r.stribeckVelocity;
        const double expected = 1.0 + 2.0 * std::exp(-x * x);
        const int window = std::abs(x - 1.0) < 0.02   ? 0
                           : std::abs(x - 2.0) < 0.02 ? 1
                           : x > 5.0                  ? 2
                                                      : -1;
        if (window >= 0) {
            QVERIFY2(std::abs(friction - expected) < 2e-3,
                     qPrintable(QStringLiteral("v %1: friction %2, Stribeck %3")
                                    .arg(v)
                                    .arg(friction)
                                    .arg(expected)));
            hit[window] = true;
        }
        if (hit[2])
            break;
    }
    QVERIFY(hit[0] && hit[1] && hit[2]);
}

void TestRealisticPlant::elasticJoint_springCarriesTheLinksGravityTorqueAtRest()
{
    // A pendulum on a spring, the motor driven by a constant torque tau: at rest the spring
    // torque equals both tau and the link's gravity torque m g l cos(q), the spring stretched by
    // tau / K.
    QTemporaryDir dir;
    const auto model = singleLink(dir, "0 -1 0", 2.0);
    QVERIFY(model);
    JointRealism r;
    r.armature = Eigen::VectorXd::Constant(1, kAxisInertia);
    r.stiffness = Eigen::VectorXd::Constant(1, 5000.0);
    r.damping = Eigen::VectorXd::Constant(1, 5.0);
    RealisticPlant plant(model, cadPhi(*model), r, 0.002, 10);
    plant.reset(Eigen::VectorXd::Constant(1, 0.2));
    const double tau = 0.6 * kMass * kGravity * kCom;
    for (int k = 0; k < 15000; ++k) // 30 s: the swing has died out
        plant.advance(Eigen::VectorXd::Constant(1, tau));
    const double q = plant.q()[0];
    const double gravityTorque = kMass * kGravity * kCom * std::cos(q);
    const double spring = plant.springTorque()[0];
    QVERIFY(std::abs(plant.qd()[0]) < 1e-9);
    QVERIFY2(
        std::abs(spring - gravityTorque) < 1e-9 * gravityTorque,
        qPrintable(QStringLiteral("spring %1, m g l cos q %2").arg(spring).arg(gravityTorque)));
    QVERIFY(std::abs(spring - tau) < 1e-9 * tau);
    QVERIFY(std::abs(plant.motorAngles()[0] - q - tau / 5000.0) < 1e-12);
    QVERIFY(std::abs(std::cos(q) - 0.6) < 1e-9);
}

void TestRealisticPlant::elasticJoint_oscillatesAtTheTwoMassFrequency()
{
    // No gravity torque, no damping: after a torque pulse the spring torque oscillates at
    // w = sqrt(K (1/J + 1/Ia)); with a motor far heavier than the link, at sqrt(K / J).
    QTemporaryDir dir;
    const auto model = singleLink(dir, "0 0 1", 0.0);
    QVERIFY(model);
    const double stiffness = 8000.0;
    for (const double ia : {kAxisInertia, 1e6 * kAxisInertia}) {
        JointRealism r;
        r.armature = Eigen::VectorXd::Constant(1, ia);
        r.stiffness = Eigen::VectorXd::Constant(1, stiffness);
        const double ts = 1e-4;
        RealisticPlant plant(model, cadPhi(*model), r, ts, 1);
        plant.reset(Eigen::VectorXd::Zero(1));
        plant.advance(Eigen::VectorXd::Constant(1, 1e3 * ia / kAxisInertia));
        const Eigen::VectorXd zero = Eigen::VectorXd::Zero(1);
        std::vector<double> crossings;
        double previous = plant.springTorque()[0];
        for (int k = 1; k < 20000 && crossings.size() < 41; ++k) {
            plant.advance(zero);
            const double now = plant.springTorque()[0];
            if ((previous < 0.0) != (now < 0.0))
                crossings.push_back((k - 1 + previous / (previous - now)) * ts);
            previous = now;
        }
        QCOMPARE(int(crossings.size()), 41);
        const double period = 2.0 * (crossings.back() - crossings.front()) / 40.0;
        const double expected = std::sqrt(stiffness * (1.0 / kAxisInertia + 1.0 / ia));
        QVERIFY2(std::abs(2.0 * M_PI / period / expected - 1.0) < 1e-3,
                 qPrintable(QStringLiteral("w %1, sqrt(K (1/J + 1/Ia)) %2")
                                .arg(2.0 * M_PI / period)
                                .arg(expected)));
    }
}

void TestRealisticPlant::sensorLag_stepResponseReachesOneMinusInverseEAtTau()
{
    // Rigid joints: the raw reading is the command, held over each sample. A step of the
    // command to 1 has, after it acted for t, the lagged reading 1 - exp(-t / T): at t = T, 1 -
    // 1/e.
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    JointRealism r;
    r.sensorLag = 0.01;
    RealisticPlant plant(model, Eigen::Vector3d(20, 5, 8), r, 0.002, 10);
    plant.reset(Eigen::Vector2d(0.3, 1.4));
    Eigen::VectorXd reading(2);
    plant.measureTorque(Eigen::Vector2d::Zero(), reading); // at rest before the step
    QCOMPARE(reading[0], 0.0);
    for (int k = 1; k <= 5; ++k) { // reading k: the step acted for t = k * 2 ms
        plant.measureTorque(Eigen::Vector2d(1.0, -2.0), reading);
        const double t = k * 0.002;
        QVERIFY(std::abs(reading[0] - (1.0 - std::exp(-t / 0.01))) < 1e-14);
        QVERIFY(std::abs(reading[1] + 2.0 * (1.0 - std::exp(-t / 0.01))) < 1e-14);
    }
    QVERIFY(std::abs(reading[0] - (1.0 - std::exp(-1.0))) < 1e-14); // t = 10 ms = T
}

void TestRealisticPlant::armature_addsIaTimesAccelerationToTheTorqueNeeded()
{
    // From rest, q(h) - q0 = qdd h^2 / 2 + O(h^3). The rigid model's torque for an acceleration
    // a (M a, no gravity, no velocity) gives a only with Ia a added.
    const auto model = makeRobotModel(QStringLiteral("paper-2link"));
    const Eigen::Vector3d phi(20, 5, 8);
    const Eigen::Vector2d q0(0.3, 1.4), a(2.0, -3.0), ia(10.0, 4.0);
    JointRealism r;
    r.armature = ia;
    const double h = 1e-5;
    const auto reached = [&](const Eigen::Vector2d &tau) {
        RealisticPlant plant(model, phi, r, h, 1);
        plant.reset(q0);
        plant.advance(tau);
        return Eigen::Vector2d(2.0 * (plant.q() - q0) / (h * h));
    };
    const Eigen::VectorXd rigid = model->torqueAt(q0, Eigen::Vector2d::Zero(), a, phi);
    const Eigen::Vector2d withArmature = rigid + ia.cwiseProduct(a);
    QVERIFY((reached(withArmature) - a).norm() < 1e-4 * a.norm());
    QVERIFY((reached(rigid) - a).norm() > 0.1 * a.norm()); // the rigid model's torque falls short
}

void TestRealisticPlant::sensorOffset_shiftsTheReadingByExactlyTheOffset()
{
    QTemporaryDir dir;
    const auto model = singleLink(dir, "0 -1 0", 1.0);
    QVERIFY(model);
    const Eigen::VectorXd offset = Eigen::VectorXd::Constant(1, 0.37);
    for (const bool elastic : {false, true}) {
        JointRealism with, without;
        if (elastic) {
            for (JointRealism *r : {&with, &without}) {
                r->armature = Eigen::VectorXd::Constant(1, 0.1);
                r->stiffness = Eigen::VectorXd::Constant(1, 6000.0);
            }
        }
        with.sensorOffset = offset;
        RealisticPlant a(model, cadPhi(*model), with, 0.002, 10);
        RealisticPlant b(model, cadPhi(*model), without, 0.002, 10);
        a.reset(Eigen::VectorXd::Constant(1, 0.4));
        b.reset(Eigen::VectorXd::Constant(1, 0.4));
        Eigen::VectorXd ra(1), rb(1);
        for (int k = 0; k < 50; ++k) {
            const Eigen::VectorXd tau = Eigen::VectorXd::Constant(1, 3.0 + std::sin(0.1 * k));
            a.measureTorque(tau, ra);
            b.measureTorque(tau, rb);
            QVERIFY(std::abs(ra[0] - rb[0] - 0.37) < 1e-12);
            a.advance(tau);
            b.advance(tau);
        }
    }
}

void TestRealisticPlant::armSimulation_motorEncoderReadsTheMotorAngle()
{
    // Through ArmSimulation: the encoder reads the motor at the pose given, the link hangs
    // tau_g / K below it; with a link-side encoder the link is at the pose.
    QTemporaryDir dir;
    const auto model = singleLink(dir, "0 -1 0", 1.0);
    QVERIFY(model);
    for (const bool linkSide : {false, true}) {
        MeasurementOptions options;
        options.realism.armature = Eigen::VectorXd::Constant(1, 0.1);
        options.realism.stiffness = Eigen::VectorXd::Constant(1, 5000.0);
        options.realism.linkSideEncoder = linkSide;
        ArmSimulation<> arm(model, cadPhi(*model), options, 0.002);
        arm.reset(Eigen::VectorXd::Constant(1, 0.0));
        Eigen::VectorXd measured(1);
        arm.measureAngles(measured);
        QCOMPARE(measured[0], 0.0);
        const double sag = kMass * kGravity * kCom / 5000.0; // at q = 0 the full lever
        const double expectedLink = linkSide ? 0.0 : -sag;
        QVERIFY2(
            std::abs(arm.q()[0] - expectedLink) < 1e-6 * sag,
            qPrintable(QStringLiteral("link %1, expected %2").arg(arm.q()[0]).arg(expectedLink)));
    }
}

QTEST_GUILESS_MAIN(TestRealisticPlant)
#include "tst_realisticplant.moc"
