// The built-in robots (resources/robots/*.urdf) against what they were written from, each check
// computed here without the URDF: the paper's arm against eq. (21) with phi = (20, 5, 8); the
// double pendulum against the textbook closed form of the lab's identified model (its yml, read
// here); the PUMA 560 and the Franka Emika Panda against the (standard, modified) DH product of
// their tables and the mass matrix and gravity torques summed over their links from the sources'
// masses, centres of mass and inertias.

#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "model/ChainDynamics.h"
#include "model/PhysicalConsistency.h"
#include "model/TwoLinkArm.h"
#include "model/UrdfChain.h"

#include <Eigen/Eigenvalues>
#include <QFile>
#include <QMap>
#include <QTest>
#include <cmath>
#include <random>

#ifndef LEARNID_ROBOTS_DIR
#error "tests/model/CMakeLists.txt defines LEARNID_ROBOTS_DIR"
#endif

using namespace learnid;

namespace {

SerialChain builtIn(const char *file)
{
    return readUrdfChain(QStringLiteral(LEARNID_ROBOTS_DIR "/") + QLatin1String(file));
}

Eigen::VectorXd standardParameters(const SerialChain &chain)
{
    Eigen::VectorXd pi(10 * chain.dof());
    for (int k = 0; k < chain.dof(); ++k)
        pi.segment<10>(10 * k) = chain.joints[size_t(k)].inertial;
    return pi;
}

Eigen::VectorXd randomVector(int size, std::mt19937 &random, double scale)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Eigen::VectorXd v(size);
    for (double &x : v)
        x = scale * unit(random);
    return v;
}

// The PUMA 560 as tabulated (Corke's mdl_puma560 after Armstrong, Khatib, Burdick 1986):
// standard DH rows, mass, centre of mass and diagonal inertia about it in DH frame i ...
struct PumaLink
{
    double d, a, alpha, mass;
    Eigen::Vector3d r, inertia;
};
const double halfPi = M_PI / 2.0;
const PumaLink puma[6] = {
    {0, 0, halfPi, 0, {0, 0, 0}, {0, 0.35, 0}},
    {0, 0.4318, 0, 17.4, {-0.3638, 0.006, 0.2275}, {0.13, 0.524, 0.539}},
    {0.15005, 0.0203, -halfPi, 4.8, {-0.0203, -0.0141, 0.070}, {0.066, 0.086, 0.0125}},
    {0.4318, 0, halfPi, 0.82, {0, 0.019, 0}, {1.8e-3, 1.3e-3, 1.8e-3}},
    {0, 0, -halfPi, 0.34, {0, 0, 0}, {0.3e-3, 0.4e-3, 0.3e-3}},
    {0, 0, 0, 0.09, {0, 0, 0.032}, {0.15e-3, 0.15e-3, 0.04e-3}},
};
// ... and its drives: limits [deg] and effort [N m]; gear ratio G, viscous B [N m s] and Coulomb
// Tc+, Tc- [N m] friction referred to the motor.
struct PumaDrive
{
    double lowerDeg, upperDeg, effort, gear, viscous, coulombUp, coulombDown;
};
const PumaDrive pumaDrives[6] = {
    {-160, 160, 97.6, -62.6111, 1.48e-3, 0.395, -0.435},
    {-45, 225, 186.4, 107.815, 0.817e-3, 0.126, -0.071},
    {-225, 45, 89.4, -53.7063, 1.38e-3, 0.132, -0.105},
    {-110, 170, 24.2, 76.0364, 71.2e-6, 11.2e-3, -16.9e-3},
    {-100, 100, 20.1, 71.923, 82.6e-6, 9.26e-3, -14.5e-3},
    {-266, 266, 21.3, 76.686, 36.7e-6, 3.96e-3, -10.5e-3},
};

// DH frames 0..6 in the base: frame i = frame i-1 Rz(q_i) Tz(d_i) Tx(a_i) Rx(alpha_i).
std::vector<Eigen::Isometry3d> dhFrames(const Eigen::VectorXd &q)
{
    std::vector<Eigen::Isometry3d> frames(1, Eigen::Isometry3d::Identity());
    for (int i = 0; i < 6; ++i) {
        const PumaLink &l = puma[i];
        frames.push_back(frames.back() * Eigen::AngleAxisd(q[i], Eigen::Vector3d::UnitZ()) *
                         Eigen::Translation3d(l.a, 0, l.d) *
                         Eigen::AngleAxisd(l.alpha, Eigen::Vector3d::UnitX()));
    }
    return frames;
}

// A body of a table: mass, centre of mass and inertia about it, in the body's own frame.
struct TableBody
{
    double mass;
    Eigen::Vector3d c;
    Eigen::Matrix3d inertia;
};

// M = sum_k m_k Jv_k^T Jv_k + Jw_k^T R_k I_k R_k^T Jw_k and the holding torque against gravity
// g_j = sum_k z_j . ((c_k - o_j) x (-m_k g)), from a table alone: joint j turns about z of
// axes[j] through its origin, body k sits in bodies[k] (both in the base, n each).
void sumOverLinks(const std::vector<Eigen::Isometry3d> &axes,
                  const std::vector<Eigen::Isometry3d> &bodies, const std::vector<TableBody> &table,
                  Eigen::MatrixXd &mass, Eigen::VectorXd &gravity)
{
    const int n = int(table.size());
    const Eigen::Vector3d g(0, 0, -9.81);
    mass.setZero(n, n);
    gravity.setZero(n);
    for (int k = 0; k < n; ++k) {
        const TableBody &b = table[size_t(k)];
        const Eigen::Vector3d c = bodies[size_t(k)] * b.c;
        const Eigen::Matrix3d rot = bodies[size_t(k)].linear();
        const Eigen::Matrix3d inertia = rot * b.inertia * rot.transpose();
        Eigen::MatrixXd jv = Eigen::MatrixXd::Zero(3, n), jw = Eigen::MatrixXd::Zero(3, n);
        for (int j = 0; j <= k; ++j) {
            const Eigen::Vector3d z = axes[size_t(j)].linear().col(2);
            const Eigen::Vector3d lever = c - axes[size_t(j)].translation();
            jw.col(j) = z;
            jv.col(j) = z.cross(lever);
            gravity[j] += z.dot(lever.cross(-b.mass * g));
        }
        mass += b.mass * jv.transpose() * jv + jw.transpose() * inertia * jw;
    }
}

// The PUMA: joint i turns about z of DH frame i-1, link i's data are in DH frame i.
void pumaByJacobians(const Eigen::VectorXd &q, Eigen::MatrixXd &mass, Eigen::VectorXd &gravity)
{
    const std::vector<Eigen::Isometry3d> f = dhFrames(q);
    std::vector<TableBody> table;
    for (const PumaLink &l : puma)
        table.push_back({l.mass, l.r, l.inertia.asDiagonal()});
    sumOverLinks({f.begin(), f.end() - 1}, {f.begin() + 1, f.end()}, table, mass, gravity);
}

// The Franka Emika Panda (frankaemika/docs) with the inertial parameters of Gaz et al. (RA-L 2019,
// FrankaEmikaPandaDynModel's DynPars2VREP.m): modified DH rows a, d, alpha; mass, centre of mass
// and inertia about it (xx, xy, xz, yy, yz, zz) in DH frame i.
struct PandaLink
{
    double a, d, alpha, mass;
    Eigen::Vector3d c;
};
const PandaLink panda[7] = {
    {0, 0.333, 0, 4.970684, {3.875e-3, 2.081e-3, 0}},
    {0, 0, -halfPi, 0.646926, {-3.141e-3, -2.872e-2, 3.495e-3}},
    {0, 0.316, halfPi, 3.228604, {2.7518e-2, 3.9252e-2, -6.6502e-2}},
    {0.0825, 0, halfPi, 3.587895, {-5.317e-2, 1.04419e-1, 2.7454e-2}},
    {-0.0825, 0.384, -halfPi, 1.225946, {-1.1953e-2, 4.1065e-2, -3.8437e-2}},
    {0, 0, halfPi, 1.666555, {6.0149e-2, -1.4117e-2, -1.0517e-2}},
    {0.088, 0, halfPi, 0.735522, {1.0517e-2, -4.252e-3, 6.1597e-2}},
};
const double pandaInertia[7][6] = {
    {7.0337e-1, -1.3900e-4, 6.7720e-3, 7.0661e-1, 1.9169e-2, 9.1170e-3},
    {7.9620e-3, -3.9250e-3, 1.0254e-2, 2.8110e-2, 7.0400e-4, 2.5995e-2},
    {3.7242e-2, -4.7610e-3, -1.1396e-2, 3.6155e-2, -1.2805e-2, 1.0830e-2},
    {2.5853e-2, 7.7960e-3, -1.3320e-3, 1.9552e-2, 8.6410e-3, 2.8323e-2},
    {3.5549e-2, -2.1170e-3, -4.0370e-3, 2.9474e-2, 2.2900e-4, 8.6270e-3},
    {1.9640e-3, 1.0900e-4, -1.1580e-3, 4.3540e-3, 3.4100e-4, 5.4330e-3},
    {1.2516e-2, -4.2800e-4, -1.1960e-3, 1.0027e-2, -7.4100e-4, 4.8150e-3},
};
Eigen::Matrix3d pandaInertiaMatrix(int link)
{
    const double *i = pandaInertia[link];
    return (Eigen::Matrix3d() << i[0], i[1], i[2], i[1], i[3], i[4], i[2], i[4], i[5]).finished();
}
// ... its limits [rad], speeds [rad/s] and torques [N m] (Franka's "Limits for Panda"), and the
// level FI1 of the paper's friction sigmoid (get_FrictionTorque.m).
struct PandaDrive
{
    double lower, upper, speed, effort, fi1;
};
const PandaDrive pandaDrives[7] = {
    {-2.8973, 2.8973, 2.1750, 87, 0.54615}, {-1.7628, 1.7628, 2.1750, 87, 0.87224},
    {-2.8973, 2.8973, 2.1750, 87, 0.64068}, {-3.0718, -0.0698, 2.1750, 87, 1.2794},
    {-2.8973, 2.8973, 2.6100, 12, 0.83904}, {-0.0175, 3.7525, 2.6100, 12, 0.30301},
    {-2.8973, 2.8973, 2.6100, 12, 0.56489},
};

// Modified DH frames 1..7 in the base: frame i = frame i-1 Rx(alpha_i) Tx(a_i) Rz(q_i) Tz(d_i).
std::vector<Eigen::Isometry3d> modifiedDhFrames(const Eigen::VectorXd &q)
{
    std::vector<Eigen::Isometry3d> frames;
    Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
    for (int i = 0; i < 7; ++i) {
        const PandaLink &l = panda[i];
        f = f * Eigen::AngleAxisd(l.alpha, Eigen::Vector3d::UnitX()) *
            Eigen::Translation3d(l.a, 0, 0) * Eigen::AngleAxisd(q[i], Eigen::Vector3d::UnitZ()) *
            Eigen::Translation3d(0, 0, l.d);
        frames.push_back(f);
    }
    return frames;
}

// Joint i turns about z of DH frame i and link i's data are in it.
void pandaByJacobians(const Eigen::VectorXd &q, Eigen::MatrixXd &mass, Eigen::VectorXd &gravity)
{
    const std::vector<Eigen::Isometry3d> f = modifiedDhFrames(q);
    std::vector<TableBody> table;
    for (int k = 0; k < 7; ++k)
        table.push_back({panda[k].mass, panda[k].c, pandaInertiaMatrix(k)});
    sumOverLinks(f, f, table, mass, gravity);
}

// A random configuration within the Panda's limits.
Eigen::VectorXd pandaConfiguration(std::mt19937 &random)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Eigen::VectorXd q(7);
    for (int i = 0; i < 7; ++i)
        q[i] = pandaDrives[i].lower + unit(random) * (pandaDrives[i].upper - pandaDrives[i].lower);
    return q;
}

// Where the URDF's fixed flange panda_link8 sits in link 7's frame, as the chain reads it: the
// first moment a 1 kg point mass there adds to link 7.
Eigen::Vector3d pandaFlange()
{
    QFile file(QStringLiteral(LEARNID_ROBOTS_DIR "/panda.urdf"));
    if (!file.open(QIODevice::ReadOnly))
        return Eigen::Vector3d::Constant(NAN);
    QByteArray xml = file.readAll();
    const SerialChain bare = parseUrdfChain(xml, QStringLiteral("panda"));
    xml.replace(R"(<link name="panda_link8"/>)",
                R"(<link name="panda_link8"><inertial><mass value="1"/><inertia ixx="0" ixy="0"
                   ixz="0" iyy="0" iyz="0" izz="0"/></inertial></link>)");
    const SerialChain loaded = parseUrdfChain(xml, QStringLiteral("panda with a flange mass"));
    return (loaded.joints[6].inertial - bare.joints[6].inertial).segment<3>(1);
}

// The lab's yml: `key: value` lines.
QMap<QString, double> readYml(const QString &path)
{
    QMap<QString, double> values;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return values;
    while (!file.atEnd()) {
        const QString line = QString::fromUtf8(file.readLine()).trimmed();
        const int colon = line.indexOf(QLatin1Char(':'));
        if (colon > 0)
            values.insert(line.left(colon).trimmed(), line.mid(colon + 1).trimmed().toDouble());
    }
    return values;
}

} // namespace

class TestBuiltInRobots : public QObject
{
    Q_OBJECT

private slots:
    void paperArm_equalsEquation21WithTheTrueParameters();
    void doublePendulum_equalsTheLabsClosedFormHangingDown();
    void puma560_framesAreTheStandardDhProduct();
    void puma560_massMatrixAndGravityEqualTheSumOverTheTable();
    void puma560_limitsFrictionAndMassAreTheSources();
    void panda_framesAreTheModifiedDhProduct();
    void panda_massMatrixAndGravityEqualTheSumOverTheTable();
    void panda_limitsFrictionAndMassAreTheSources();
    void panda_everyLinkIsARealBody();
};

void TestBuiltInRobots::paperArm_equalsEquation21WithTheTrueParameters()
{
    const SerialChain chain = builtIn("paper-2link.urdf");
    QCOMPARE(chain.dof(), 2);
    QCOMPARE(chain.joints[0].effortLimit, 8.0);
    QCOMPARE(chain.joints[1].effortLimit, 4.0);
    const ChainDynamics dynamics(chain);
    const Eigen::VectorXd pi = standardParameters(chain);
    const TwoLinkArm paper;
    const Eigen::Vector3d abc(20, 5, 8);
    Eigen::Matrix2d t; // absolute angles = T relative
    t << 1, 0, 1, 1;
    std::mt19937 random(21);
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::VectorXd q = randomVector(2, random, 3.0), qd = randomVector(2, random, 2.0),
                              qdd = randomVector(2, random, 4.0);
        Eigen::VectorXd tau(2);
        dynamics.inverseDynamics(q, qd, qdd, pi, tau);
        LEARNID_COMPARE_MATRIX(tau, t.transpose() * paper.torqueAt(t * q, t * qd, t * qdd, abc),
                               1e-12);
    }
}

void TestBuiltInRobots::doublePendulum_equalsTheLabsClosedFormHangingDown()
{
    const QString yml =
        test::sharedDataFile(QStringLiteral("double-pendulum/model_parameters_3.0.yml"));
    if (yml.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const QMap<QString, double> p = readYml(yml);
    for (const char *key : {"m1", "m2", "l1", "l2", "r1", "r2", "I1", "I2", "g", "b1", "b2", "cf1",
                            "cf2", "tl1", "tl2"})
        QVERIFY2(p.contains(QLatin1String(key)), key);
    const double m1 = p["m1"], m2 = p["m2"], l1 = p["l1"], l2 = p["l2"], r1 = p["r1"], r2 = p["r2"],
                 i1 = p["I1"], i2 = p["I2"], g = p["g"];

    const SerialChain chain = builtIn("double-pendulum.urdf");
    QCOMPARE(chain.dof(), 2);
    LEARNID_COMPARE_NEAR(chain.gravity.norm(), g, 1e-12);
    const ChainDynamics dynamics(chain);
    const Eigen::VectorXd pi = standardParameters(chain);
    std::mt19937 random(22);
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::VectorXd q = randomVector(2, random, M_PI);
        const double c2 = std::cos(q[1]), s1 = std::sin(q[0]), s12 = std::sin(q[0] + q[1]);
        Eigen::Matrix2d mass;
        mass << i1 + i2 + m2 * l1 * l1 + 2 * m2 * l1 * r2 * c2, i2 + m2 * l1 * r2 * c2,
            i2 + m2 * l1 * r2 * c2, i2;
        // Zero angles hanging down: the torque holding the links against gravity.
        const Eigen::Vector2d gravity(m1 * g * r1 * s1 + m2 * g * (l1 * s1 + r2 * s12),
                                      m2 * g * r2 * s12);
        Eigen::MatrixXd chainMass(2, 2);
        dynamics.massMatrix(q, pi, chainMass);
        LEARNID_COMPARE_MATRIX(chainMass, mass, 1e-10);
        Eigen::VectorXd tau(2);
        dynamics.inverseDynamics(q, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), pi, tau);
        LEARNID_COMPARE_MATRIX(tau, gravity, 1e-10);
        // The lab's forward kinematics, its upward y as z: x = l1 sin q1 + l2 sin(q1 + q2).
        const Eigen::Vector3d tip = dynamics.framePoses(q)[1] * Eigen::Vector3d(0, 0, -l2);
        const Eigen::Vector3d lab(l1 * s1 + l2 * s12, 0,
                                  -l1 * std::cos(q[0]) - l2 * std::cos(q[0] + q[1]));
        LEARNID_COMPARE_MATRIX(tip, lab, 1e-12);
    }
    // Friction: viscous b as given; the lab's Coulomb term cf atan(100 qd) levels at (pi/2) cf.
    for (int j = 0; j < 2; ++j) {
        const QString n = QString::number(j + 1);
        const ChainJoint &joint = chain.joints[size_t(j)];
        LEARNID_COMPARE_NEAR(joint.damping, p[QStringLiteral("b") + n], 1e-15);
        LEARNID_COMPARE_NEAR(joint.friction, halfPi * p[QStringLiteral("cf") + n], 1e-15);
        LEARNID_COMPARE_NEAR(joint.effortLimit, p[QStringLiteral("tl") + n], 0.0);
    }
}

void TestBuiltInRobots::puma560_framesAreTheStandardDhProduct()
{
    const SerialChain chain = builtIn("puma560.urdf");
    QCOMPARE(chain.dof(), 6);
    QCOMPARE(chain.tipLink, QStringLiteral("tool"));
    const ChainDynamics dynamics(chain);
    std::vector<Eigen::VectorXd> configurations;
    Eigen::VectorXd q(6);
    configurations.push_back(Eigen::VectorXd::Zero(6));                            // qz: L-shaped
    configurations.push_back((q << 0, halfPi, -halfPi, 0, 0, 0).finished());       // qr: ready
    configurations.push_back((q << 0, M_PI / 4, M_PI, 0, M_PI / 4, 0).finished()); // qn
    std::mt19937 random(23);
    for (int trial = 0; trial < 10; ++trial)
        configurations.push_back(randomVector(6, random, M_PI));
    for (const Eigen::VectorXd &qk : configurations) {
        const std::vector<Eigen::Isometry3d> dh = dhFrames(qk);
        const std::vector<Eigen::Isometry3d> poses = dynamics.framePoses(qk);
        for (size_t i = 0; i < 6; ++i) {
            // Joint i+1 turns about z of DH frame i, through its origin.
            LEARNID_COMPARE_MATRIX(poses[i].translation(), dh[i].translation(), 1e-12);
            LEARNID_COMPARE_MATRIX(poses[i].linear() * chain.joints[i].axis, dh[i].linear().col(2),
                                   1e-12);
        }
        // The tool (fixed at link 6's frame) is DH frame 6, position and orientation.
        LEARNID_COMPARE_MATRIX(poses[5].matrix(), dh[6].matrix(), 1e-12);
    }
    // At zero the wrist centre is at (a2 + a3, -d3, d4): upper arm along x, forearm up.
    LEARNID_COMPARE_MATRIX(dynamics.framePoses(Eigen::VectorXd::Zero(6))[5].translation(),
                           Eigen::Vector3d(0.4521, -0.15005, 0.4318), 1e-12);
}

void TestBuiltInRobots::puma560_massMatrixAndGravityEqualTheSumOverTheTable()
{
    const SerialChain chain = builtIn("puma560.urdf");
    const ChainDynamics dynamics(chain);
    const Eigen::VectorXd pi = standardParameters(chain);
    std::vector<Eigen::VectorXd> configurations;
    Eigen::VectorXd q(6);
    configurations.push_back(Eigen::VectorXd::Zero(6));
    configurations.push_back((q << 0, -halfPi, halfPi, 0, 0, 0).finished());
    std::mt19937 random(24);
    for (int trial = 0; trial < 10; ++trial)
        configurations.push_back(randomVector(6, random, M_PI));
    for (const Eigen::VectorXd &qk : configurations) {
        Eigen::MatrixXd mass, chainMass(6, 6);
        Eigen::VectorXd gravity, tau(6);
        pumaByJacobians(qk, mass, gravity);
        dynamics.massMatrix(qk, pi, chainMass);
        LEARNID_COMPARE_MATRIX(chainMass, mass, 1e-10);
        const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
        dynamics.inverseDynamics(qk, zero, zero, pi, tau);
        LEARNID_COMPARE_MATRIX(tau, gravity, 1e-10);
    }
    // At zero joint 2 (axis -y) holds each link's weight on its horizontal lever x_c: the upper
    // arm's centre at a2 - 0.3638, the forearm's at a2 + a3 - 0.0203, the wrist's at a2 + a3.
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
    Eigen::VectorXd tau(6);
    dynamics.inverseDynamics(zero, zero, zero, pi, tau);
    const double moment = 17.4 * (0.4318 - 0.3638) + 4.8 * (0.4318 + 0.0203 - 0.0203) +
                          (0.82 + 0.34 + 0.09) * (0.4318 + 0.0203);
    LEARNID_COMPARE_NEAR(tau[1], 9.81 * moment, 1e-12);
}

void TestBuiltInRobots::puma560_limitsFrictionAndMassAreTheSources()
{
    const SerialChain chain = builtIn("puma560.urdf");
    QCOMPARE(chain.dof(), 6);
    double total = 0.0, tableTotal = 0.0;
    for (int i = 0; i < 6; ++i) {
        const PumaDrive &drive = pumaDrives[i];
        const ChainJoint &joint = chain.joints[size_t(i)];
        QCOMPARE(joint.type, JointType::Revolute);
        LEARNID_COMPARE_NEAR(joint.lower, drive.lowerDeg * M_PI / 180.0, 1e-15);
        LEARNID_COMPARE_NEAR(joint.upper, drive.upperDeg * M_PI / 180.0, 1e-15);
        LEARNID_COMPARE_NEAR(joint.effortLimit, drive.effort, 0.0);
        // Motor-referenced B and Tc to the link side: B G^2, |G| mean(|Tc+|, |Tc-|).
        LEARNID_COMPARE_NEAR(joint.damping, drive.viscous * drive.gear * drive.gear, 1e-12);
        LEARNID_COMPARE_NEAR(joint.friction,
                             std::abs(drive.gear) * (drive.coulombUp - drive.coulombDown) / 2.0,
                             1e-12);
        total += joint.inertial[0];
        tableTotal += puma[i].mass;
    }
    LEARNID_COMPARE_NEAR(total, tableTotal, 1e-12);
    LEARNID_COMPARE_NEAR(total, 23.45, 1e-12);
}

void TestBuiltInRobots::panda_framesAreTheModifiedDhProduct()
{
    const SerialChain chain = builtIn("panda.urdf");
    QCOMPARE(chain.dof(), 7);
    QCOMPARE(chain.baseLink, QStringLiteral("panda_link0"));
    QCOMPARE(chain.tipLink, QStringLiteral("panda_link8"));
    // The flange: fixed 0.107 along link 7's z (DH row 8: a = 0, alpha = 0, d = 0.107).
    const Eigen::Vector3d flange = pandaFlange();
    LEARNID_COMPARE_MATRIX(flange, Eigen::Vector3d(0, 0, 0.107), 1e-15);
    const ChainDynamics dynamics(chain);
    std::vector<Eigen::VectorXd> configurations;
    configurations.push_back(Eigen::VectorXd::Zero(7));
    Eigen::VectorXd q(7);
    configurations.push_back((q << 0, -M_PI / 4, 0, -3 * M_PI / 4, 0, halfPi, M_PI / 4).finished());
    std::mt19937 random(25);
    for (int trial = 0; trial < 10; ++trial) {
        configurations.push_back(pandaConfiguration(random));
        configurations.push_back(randomVector(7, random, M_PI));
    }
    for (const Eigen::VectorXd &qk : configurations) {
        const std::vector<Eigen::Isometry3d> dh = modifiedDhFrames(qk);
        const std::vector<Eigen::Isometry3d> poses = dynamics.framePoses(qk);
        for (size_t i = 0; i < 7; ++i) {
            // Link i+1's frame is DH frame i+1, joint i+1 turning about its z.
            LEARNID_COMPARE_MATRIX(poses[i].matrix(), dh[i].matrix(), 1e-12);
            LEARNID_COMPARE_MATRIX(poses[i].linear() * chain.joints[i].axis, dh[i].linear().col(2),
                                   1e-12);
        }
        LEARNID_COMPARE_MATRIX(poses[6] * flange, dh[6] * Eigen::Vector3d(0, 0, 0.107), 1e-12);
    }
    // At zero the arm stands upright and the flange points down: (a4 + a5 + a7, 0, d1 + d3 + d5
    // - d_flange), Franka's (0.088, 0, 0.926).
    LEARNID_COMPARE_MATRIX(dynamics.framePoses(Eigen::VectorXd::Zero(7))[6] * flange,
                           Eigen::Vector3d(0.088, 0, 0.926), 1e-12);
}

void TestBuiltInRobots::panda_massMatrixAndGravityEqualTheSumOverTheTable()
{
    const SerialChain chain = builtIn("panda.urdf");
    const ChainDynamics dynamics(chain);
    const Eigen::VectorXd pi = standardParameters(chain);
    std::vector<Eigen::VectorXd> configurations;
    Eigen::VectorXd q(7);
    configurations.push_back(Eigen::VectorXd::Zero(7));
    configurations.push_back((q << 0, -M_PI / 4, 0, -3 * M_PI / 4, 0, halfPi, M_PI / 4).finished());
    std::mt19937 random(26);
    for (int trial = 0; trial < 10; ++trial) {
        configurations.push_back(pandaConfiguration(random));
        configurations.push_back(randomVector(7, random, M_PI));
    }
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(7);
    for (const Eigen::VectorXd &qk : configurations) {
        Eigen::MatrixXd mass, chainMass(7, 7);
        Eigen::VectorXd gravity, tau(7);
        pandaByJacobians(qk, mass, gravity);
        dynamics.massMatrix(qk, pi, chainMass);
        LEARNID_COMPARE_MATRIX(chainMass, mass, 1e-9);
        dynamics.inverseDynamics(qk, zero, zero, pi, tau);
        LEARNID_COMPARE_MATRIX(tau, gravity, 1e-9);
        LEARNID_COMPARE_NEAR(tau[0], 0.0, 1e-12); // the vertical first axis holds no weight
    }
}

void TestBuiltInRobots::panda_limitsFrictionAndMassAreTheSources()
{
    const SerialChain chain = builtIn("panda.urdf");
    QCOMPARE(chain.dof(), 7);
    double total = 0.0;
    for (int i = 0; i < 7; ++i) {
        const PandaDrive &drive = pandaDrives[i];
        const ChainJoint &joint = chain.joints[size_t(i)];
        QCOMPARE(joint.type, JointType::Revolute);
        QCOMPARE(joint.name, QStringLiteral("panda_joint%1").arg(i + 1));
        QCOMPARE(joint.link, QStringLiteral("panda_link%1").arg(i + 1));
        LEARNID_COMPARE_NEAR(joint.lower, drive.lower, 0.0);
        LEARNID_COMPARE_NEAR(joint.upper, drive.upper, 0.0);
        LEARNID_COMPARE_NEAR(joint.velocityLimit, drive.speed, 0.0);
        LEARNID_COMPARE_NEAR(joint.effortLimit, drive.effort, 0.0);
        // The sigmoid steps by FI1 from one direction to the other: Coulomb FI1 / 2, no slope.
        LEARNID_COMPARE_NEAR(joint.friction, drive.fi1 / 2.0, 1e-15);
        LEARNID_COMPARE_NEAR(joint.damping, 0.0, 0.0);
        LEARNID_COMPARE_NEAR(joint.inertial[0], panda[i].mass, 0.0);
        total += joint.inertial[0];
    }
    LEARNID_COMPARE_NEAR(total, 16.062132, 1e-12);
}

void TestBuiltInRobots::panda_everyLinkIsARealBody()
{
    // From the table: positive principal moments about the centre of mass that satisfy the
    // triangle inequality (Gaz et al. retrieved them under these constraints) ...
    for (int k = 0; k < 7; ++k) {
        const Eigen::Vector3d m =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(pandaInertiaMatrix(k)).eigenvalues();
        QVERIFY(panda[k].mass > 0 && m[0] > 0);
        QVERIFY(m[0] + m[1] > m[2]);
    }
    // ... and the URDF's links: learnid's check on the pseudo-inertia, strictly inside.
    const SerialChain chain = builtIn("panda.urdf");
    for (const LinkConsistency &l : checkConsistency(standardParameters(chain), 7, 1e-12)) {
        QVERIFY2(
            l.consistent && !l.degenerate,
            qPrintable(
                QStringLiteral("link %1: lambda_min %2").arg(l.link + 1).arg(l.minEigenvalue)));
    }
}

QTEST_GUILESS_MAIN(TestBuiltInRobots)
#include "tst_builtinrobots.moc"
