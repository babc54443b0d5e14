// The built-in Franka Emika Panda (resources/robots/panda.urdf) against what it was written
// from, each check computed here without the URDF: the modified DH product of Franka's table,
// the mass matrix and gravity torques summed over its links from the masses, centres of mass and
// inertias of Gaz et al. (2019), its limits, friction and masses, and every link a real body.

#include "../support/NumericAssert.h"
#include "BuiltInRobotSupport.h"
#include "model/ChainDynamics.h"
#include "model/PhysicalConsistency.h"
#include "model/UrdfChain.h"

#include <Eigen/Eigenvalues>
#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;
using namespace learnid::test;

namespace {

const double halfPi = M_PI / 2.0;

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

} // namespace

class TestPandaRobot : public QObject
{
    Q_OBJECT

private slots:
    void panda_framesAreTheModifiedDhProduct();
    void panda_massMatrixAndGravityEqualTheSumOverTheTable();
    void panda_limitsFrictionAndMassAreTheSources();
    void panda_everyLinkIsARealBody();
};

void TestPandaRobot::panda_framesAreTheModifiedDhProduct()
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

void TestPandaRobot::panda_massMatrixAndGravityEqualTheSumOverTheTable()
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

void TestPandaRobot::panda_limitsFrictionAndMassAreTheSources()
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

void TestPandaRobot::panda_everyLinkIsARealBody()
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

QTEST_GUILESS_MAIN(TestPandaRobot)
#include "tst_pandarobot.moc"
