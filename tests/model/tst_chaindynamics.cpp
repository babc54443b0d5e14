// The chain's dynamics against Orocos KDL, the oracle: the regressor column by column (KDL's
// recursive Newton-Euler with one unit inertial parameter on one link), inverse dynamics, the
// mass matrix and gravity (KDL's ChainDynParam), on the KUKA LWR4+ URDF at random states; and
// against physics: forward dynamics inverts inverse dynamics, the simulator keeps the energy.

#include "../support/KdlChain.h"
#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "model/ChainDynamics.h"
#include "model/ChainModel.h"
#include "model/UrdfChain.h"

#include <QTest>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <random>

using namespace learnid;

namespace {

// Only the links' inertia: no friction, armature or offset.
JointTerms inertiaOnly()
{
    JointTerms terms;
    terms.viscous = terms.coulomb = false;
    return terms;
}

const KDL::Vector kdlGravity(0.0, 0.0, -9.81);

KDL::JntArray toKdl(const Eigen::VectorXd &v)
{
    KDL::JntArray a(unsigned(v.size()));
    a.data = v;
    return a;
}

// (m, h, I about the origin) as a KDL inertia, any values (m = 0 with h != 0 included): KDL
// builds inertias from mass, centre and inertia about the centre, so this goes by linearity.
KDL::RigidBodyInertia kdlFromStandard(const InertialParameters &pi)
{
    const KDL::RotationalInertia rotational(pi[4], pi[6], pi[9], pi[5], pi[7], pi[8]);
    KDL::RigidBodyInertia out = KDL::RigidBodyInertia(pi[0], KDL::Vector::Zero()) +
                                KDL::RigidBodyInertia(0.0, KDL::Vector::Zero(), rotational);
    for (int a = 0; a < 3; ++a) {
        KDL::Vector unit = KDL::Vector::Zero();
        unit(a) = 1.0;
        // m = 1 at the unit point: h = unit, I = E - unit unit^T; take away m and I.
        Eigen::Matrix3d shift = Eigen::Matrix3d::Identity();
        shift(a, a) = 0.0;
        const KDL::RotationalInertia removeI(-shift(0, 0), -shift(1, 1), -shift(2, 2), 0, 0, 0);
        const KDL::RigidBodyInertia pureH =
            KDL::RigidBodyInertia(1.0, unit) + KDL::RigidBodyInertia(-1.0, KDL::Vector::Zero()) +
            KDL::RigidBodyInertia(0.0, KDL::Vector::Zero(), removeI);
        out = out + pi[1 + a] * pureH;
    }
    return out;
}

struct State
{
    Eigen::VectorXd q, qd, qdd;
};

// KDL's recursive Newton-Euler torque at s; NaN (which no comparison passes) if KDL fails.
Eigen::VectorXd kdlTorque(const KDL::Chain &chain, const State &s)
{
    KDL::ChainIdSolver_RNE rne(chain, kdlGravity);
    KDL::JntArray tau(chain.getNrOfJoints());
    const KDL::Wrenches none(chain.getNrOfSegments(), KDL::Wrench::Zero());
    if (rne.CartToJnt(toKdl(s.q), toKdl(s.qd), toKdl(s.qdd), none, tau) != 0)
        return Eigen::VectorXd::Constant(s.q.size(), NAN);
    return tau.data;
}

// The chain's standard inertial parameters, 10 per link.
Eigen::VectorXd inertialsOf(const SerialChain &chain)
{
    Eigen::VectorXd pi(10 * chain.dof());
    for (int k = 0; k < chain.dof(); ++k)
        pi.segment<10>(10 * k) = chain.joints[size_t(k)].inertial;
    return pi;
}

std::vector<State> randomStates(int n, int count, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<State> states;
    for (int s = 0; s < count; ++s) {
        State st{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
        for (int j = 0; j < n; ++j) {
            st.q[j] = 2.5 * unit(random);
            st.qd[j] = 2.0 * unit(random);
            st.qdd[j] = 4.0 * unit(random);
        }
        states.push_back(st);
    }
    return states;
}

// KDL's segments that move (one per moving joint), by index into chain.segments.
std::vector<unsigned> movingSegments(const KDL::Chain &chain)
{
    std::vector<unsigned> out;
    for (unsigned i = 0; i < chain.getNrOfSegments(); ++i)
        if (chain.getSegment(i).getJoint().getType() != KDL::Joint::Fixed)
            out.push_back(i);
    return out;
}

} // namespace

class TestChainDynamics : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void regressorColumns_equalKdlTorquesOfUnitParameters();
    void inverseDynamics_equalsKdlRecursiveNewtonEuler();
    void massMatrixAndGravity_equalKdlChainDynParam();
    void regressorTimesParameters_equalsInverseDynamics();
    void fixedLinksAndPrismaticJoints_equalKdl();
    void forwardDynamics_invertsInverseDynamics();
    void simulationWithoutFriction_keepsItsEnergy();

private:
    QString m_urdf;
    SerialChain m_chain;
    KDL::Chain m_kdl;
};

void TestChainDynamics::initTestCase()
{
    m_urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (m_urdf.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    m_chain = readUrdfChain(m_urdf);
    QCOMPARE(m_chain.dof(), 7);
    m_kdl = test::kdlChainFromUrdf(m_urdf, m_chain.baseLink.toStdString(),
                                   m_chain.tipLink.toStdString());
    QCOMPARE(int(m_kdl.getNrOfJoints()), 7);
}

void TestChainDynamics::regressorColumns_equalKdlTorquesOfUnitParameters()
{
    const ChainDynamics dynamics(m_chain);
    const std::vector<unsigned> moving = movingSegments(m_kdl);
    for (const State &s : randomStates(7, 5, 1)) {
        Eigen::MatrixXd y(7, 70);
        dynamics.regressor(s.q, s.qd, s.qdd, y);
        for (int k = 0; k < 7; ++k) {
            for (int p = 0; p < 10; ++p) {
                KDL::Chain unit = m_kdl;
                for (KDL::Segment &segment : unit.segments)
                    segment.setInertia(KDL::RigidBodyInertia::Zero());
                InertialParameters pi = InertialParameters::Zero();
                pi[p] = 1.0;
                unit.segments[moving[size_t(k)]].setInertia(kdlFromStandard(pi));
                LEARNID_COMPARE_MATRIX(y.col(10 * k + p), kdlTorque(unit, s), 1e-10);
            }
        }
    }
}

void TestChainDynamics::inverseDynamics_equalsKdlRecursiveNewtonEuler()
{
    const ChainDynamics dynamics(m_chain);
    const Eigen::VectorXd pi = inertialsOf(m_chain);
    for (const State &s : randomStates(7, 20, 2)) {
        Eigen::VectorXd ours(7);
        dynamics.inverseDynamics(s.q, s.qd, s.qdd, pi, ours);
        LEARNID_COMPARE_MATRIX(ours, kdlTorque(m_kdl, s), 1e-10);
    }
}

void TestChainDynamics::massMatrixAndGravity_equalKdlChainDynParam()
{
    const ChainDynamics dynamics(m_chain);
    const Eigen::VectorXd pi = inertialsOf(m_chain);
    KDL::ChainDynParam param(m_kdl, kdlGravity);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(7);
    for (const State &s : randomStates(7, 20, 3)) {
        KDL::JntSpaceInertiaMatrix m(7);
        KDL::JntArray g(7);
        QCOMPARE(param.JntToMass(toKdl(s.q), m), 0);
        QCOMPARE(param.JntToGravity(toKdl(s.q), g), 0);
        Eigen::MatrixXd ours(7, 7);
        dynamics.massMatrix(s.q, pi, ours);
        LEARNID_COMPARE_MATRIX(ours, m.data, 1e-10);
        Eigen::VectorXd gravity(7);
        dynamics.inverseDynamics(s.q, zero, zero, pi, gravity);
        LEARNID_COMPARE_MATRIX(gravity, g.data, 1e-10);
    }
}

void TestChainDynamics::regressorTimesParameters_equalsInverseDynamics()
{
    const ChainDynamics dynamics(m_chain);
    std::mt19937 random(4);
    std::normal_distribution<double> normal;
    Eigen::VectorXd pi(70);
    for (double &v : pi)
        v = normal(random); // any numbers: the regressor is linear, physical or not
    for (const State &s : randomStates(7, 10, 5)) {
        Eigen::MatrixXd y(7, 70);
        dynamics.regressor(s.q, s.qd, s.qdd, y);
        Eigen::VectorXd tau(7);
        dynamics.inverseDynamics(s.q, s.qd, s.qdd, pi, tau);
        LEARNID_COMPARE_MATRIX(y * pi, tau, 1e-11);
    }
}

void TestChainDynamics::fixedLinksAndPrismaticJoints_equalKdl()
{
    // A chain with a fixed link in the middle, a prismatic joint, tilted axes and a fixed tool
    // at the tip: merged into their moving bodies, the dynamics must not change.
    const QByteArray xml = R"(<robot name="mixed">
  <link name="base"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <origin xyz="0 0 0.3" rpy="0 0 0.2"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="50" velocity="2"/></joint>
  <link name="l1"><inertial><origin xyz="0.05 0.01 0.1" rpy="0.1 0.2 0.3"/><mass value="3"/>
    <inertia ixx="0.05" ixy="0.001" ixz="0.002" iyy="0.04" iyz="0.003" izz="0.03"/></inertial></link>
  <joint name="f1" type="fixed"><parent link="l1"/><child link="bracket"/>
    <origin xyz="0.1 0 0.2" rpy="0.3 0 0"/></joint>
  <link name="bracket"><inertial><origin xyz="0 0.02 0"/><mass value="0.5"/>
    <inertia ixx="0.002" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.002"/></inertial></link>
  <joint name="j2" type="prismatic"><parent link="bracket"/><child link="l2"/>
    <origin xyz="0 0.1 0" rpy="0 0.4 0"/><axis xyz="1 0 1"/>
    <limit lower="-0.2" upper="0.2" effort="100" velocity="1"/></joint>
  <link name="l2"><inertial><origin xyz="0.02 0 0.05"/><mass value="1.5"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.015"/></inertial></link>
  <joint name="j3" type="continuous"><parent link="l2"/><child link="l3"/>
    <origin xyz="0 0 0.25" rpy="-0.5 0 0.1"/><axis xyz="0 1 0"/></joint>
  <link name="l3"><inertial><origin xyz="0 0 0.1"/><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.002"/></inertial></link>
  <joint name="tool" type="fixed"><parent link="l3"/><child link="gripper"/>
    <origin xyz="0 0 0.2" rpy="0 0 1"/></joint>
  <link name="gripper"><inertial><origin xyz="0.01 0 0.03"/><mass value="0.8"/>
    <inertia ixx="0.003" ixy="0" ixz="0" iyy="0.003" iyz="0" izz="0.001"/></inertial></link>
</robot>)";
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mixed.urdf"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(xml);
    file.close();
    const SerialChain chain = readUrdfChain(path);
    QCOMPARE(chain.dof(), 3);
    QCOMPARE(chain.tipLink, QStringLiteral("gripper"));
    const KDL::Chain kdl = test::kdlChainFromUrdf(path, "base", "gripper");
    const ChainDynamics dynamics(chain);
    const Eigen::VectorXd pi = inertialsOf(chain);
    LEARNID_COMPARE_NEAR(pi[10], 1.5, 0.0); // the bracket is merged into l1, not l2
    LEARNID_COMPARE_NEAR(pi[0], 3.5, 1e-15);
    LEARNID_COMPARE_NEAR(pi[20], 1.8, 1e-15);
    KDL::ChainDynParam param(kdl, kdlGravity);
    for (State s : randomStates(3, 10, 6)) {
        s.q[1] *= 0.08;
        Eigen::VectorXd ours(3);
        dynamics.inverseDynamics(s.q, s.qd, s.qdd, pi, ours);
        LEARNID_COMPARE_MATRIX(ours, kdlTorque(kdl, s), 1e-10);
        KDL::JntSpaceInertiaMatrix m(3);
        QCOMPARE(param.JntToMass(toKdl(s.q), m), 0);
        Eigen::MatrixXd mass(3, 3);
        dynamics.massMatrix(s.q, pi, mass);
        LEARNID_COMPARE_MATRIX(mass, m.data, 1e-10);
    }
}

void TestChainDynamics::forwardDynamics_invertsInverseDynamics()
{
    JointTerms terms;
    terms.armature = terms.viscous = terms.coulomb = terms.offset = true;
    const ChainModel model(m_chain, terms, QStringLiteral("lwr4"));
    const Eigen::VectorXd phi = model.baseFromStandard(model.cadStandard());
    for (const State &s : randomStates(7, 10, 7)) {
        const Eigen::VectorXd tau = model.torqueAt(s.q, s.qd, s.qdd, phi);
        Eigen::VectorXd qdd(7);
        model.forwardDynamics(s.q, s.qd, tau, phi, qdd);
        LEARNID_COMPARE_MATRIX(qdd, s.qdd, 1e-9);
    }
}

void TestChainDynamics::simulationWithoutFriction_keepsItsEnergy()
{
    // Free motion under gravity: kinetic plus potential energy stays; with a constant torque
    // the energy grows by the work it does, integral of tau . qd (trapezoidal rule).
    const ChainModel model(m_chain, inertiaOnly(), QStringLiteral("lwr4"));
    const Eigen::VectorXd pi = model.cadStandard();
    const Eigen::VectorXd phi = model.baseFromStandard(pi);
    const auto energy = [&](const Eigen::VectorXd &q, const Eigen::VectorXd &qd) {
        Eigen::MatrixXd m(7, 7);
        model.massMatrix(q, phi, m);
        return 0.5 * qd.dot(m * qd) + model.dynamics().potentialEnergy(q, pi);
    };
    for (const double torque : {0.0, 0.5}) {
        Eigen::VectorXd q = randomStates(7, 1, 8)[0].q * 0.5;
        Eigen::VectorXd qd = Eigen::VectorXd::Constant(7, 0.3);
        const Eigen::VectorXd tau = Eigen::VectorXd::Constant(7, torque);
        const double start = energy(q, qd);
        double work = 0.0;
        const double h = 1e-4;
        for (int step = 0; step < 5000; ++step) {
            const Eigen::VectorXd before = qd;
            model.rk4Step(q, qd, tau, phi, h);
            work += 0.5 * h * tau.dot(before + qd);
        }
        const double scale = std::abs(start) + std::abs(work) + 1.0;
        LEARNID_COMPARE_NEAR(energy(q, qd) - start, work, 1e-6 * scale);
    }
}

QTEST_GUILESS_MAIN(TestChainDynamics)
#include "tst_chaindynamics.moc"
