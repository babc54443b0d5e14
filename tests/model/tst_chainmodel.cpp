// A chain as a model in its base parameters: the base regressor reproduces the standard one for
// any parameters; the paper's arm written as a URDF agrees with eq. (21) after the change from
// relative to absolute angles and its base parameters are a, b, c (and link 2's centre of mass
// across the link); a path that leaves a joint still cannot see that joint's terms, and the
// update keeps them.

#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "identify/ObservableUpdate.h"
#include "model/ChainModel.h"
#include "model/TwoLinkArm.h"
#include "model/UrdfChain.h"

#include <QTest>
#include <algorithm>
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

// The paper's arm (docs/design.md §2: 0.75 m links) as a URDF: horizontal, both axes along z,
// joint 2 relative to link 1. The inertias are arbitrary: any arm of this shape has eq. (21).
const QByteArray paperArmUrdf = R"(<robot name="paper-arm">
  <link name="base"/>
  <joint name="shoulder" type="continuous"><parent link="base"/><child link="upper"/>
    <axis xyz="0 0 1"/></joint>
  <link name="upper"><inertial><origin xyz="0.4 0 0"/><mass value="6"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.3" iyz="0" izz="0.3"/></inertial></link>
  <joint name="elbow" type="continuous"><parent link="upper"/><child link="fore"/>
    <origin xyz="0.75 0 0"/><axis xyz="0 0 1"/></joint>
  <link name="fore"><inertial><origin xyz="0.3 0 0"/><mass value="4"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.2"/></inertial></link>
</robot>)";

Eigen::VectorXd randomVector(int size, std::mt19937 &random, double scale = 1.0)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Eigen::VectorXd v(size);
    for (double &x : v)
        x = scale * unit(random);
    return v;
}

JointTerms allTerms()
{
    JointTerms terms;
    terms.armature = terms.viscous = terms.coulomb = terms.offset = true;
    return terms;
}

} // namespace

class TestChainModel : public QObject
{
    Q_OBJECT

private slots:
    void baseRegressor_reproducesStandardTorquesForAnyParameters();
    void baseParameters_roundTripThroughTheCadPrior();
    void cancellingTerms_giveAnExactZero();
    void paperArmUrdf_equalsEquation21AfterTheChangeOfAngles();
    void paperArmUrdf_baseParametersAreABAndC();
    void pathNotMovingAJoint_leavesItsTermsUnobservedAndKept();
};

void TestChainModel::baseRegressor_reproducesStandardTorquesForAnyParameters()
{
    const QString urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (urdf.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const ChainModel model(readUrdfChain(urdf), allTerms(), QStringLiteral("lwr4"));
    const int p = model.standardCount();
    QCOMPARE(p, 98);
    QVERIFY(model.parameterCount() < p);
    std::mt19937 random(11);
    for (int trial = 0; trial < 10; ++trial) {
        const Eigen::VectorXd pi = randomVector(p, random);
        const Eigen::VectorXd q = randomVector(7, random, 2.5), qd = randomVector(7, random, 2.0),
                              qdd = randomVector(7, random, 4.0);
        Eigen::MatrixXd y(7, p);
        model.standardRegressor(q, qd, qdd, y);
        const Eigen::MatrixXd yBase = model.regressorAt(q, qd, qdd);
        LEARNID_COMPARE_MATRIX(yBase * model.baseFromStandard(pi), y * pi, 1e-10);
        // The model's own dynamics from phi equal the standard torques too.
        LEARNID_COMPARE_MATRIX(model.torqueAt(q, qd, qdd, model.baseFromStandard(pi)), y * pi,
                               1e-10);
    }
}

void TestChainModel::baseParameters_roundTripThroughTheCadPrior()
{
    const ChainModel model(parseUrdfChain(paperArmUrdf, QStringLiteral("paper arm")), allTerms(),
                           QStringLiteral("paper-urdf"));
    std::mt19937 random(12);
    const Eigen::VectorXd phi = randomVector(model.parameterCount(), random);
    const Eigen::VectorXd pi = model.standardFromBase(phi);
    LEARNID_COMPARE_MATRIX(model.baseFromStandard(pi), phi, 1e-12);
    // What the base parameters do not fix stays at the CAD value.
    for (const int d : model.base().dependent())
        LEARNID_COMPARE_NEAR(pi[d], model.cadStandard()[d], 0.0);
}

void TestChainModel::cancellingTerms_giveAnExactZero()
{
    // The LWR4+'s links 3 and 4 carry their centres of mass at y = +0.06 and -0.06 m with the
    // same mass: m cy3 + m cy4 is 0 in the CAD model, exactly, not a rounding residue (which
    // the learning laws, scaling each parameter by its value, would never move).
    const QString urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (urdf.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const ChainModel model(readUrdfChain(urdf), allTerms(), QStringLiteral("lwr4"));
    const Eigen::VectorXd phi = model.baseFromStandard(model.cadStandard());
    int found = 0;
    for (int i = 0; i < model.parameterCount(); ++i) {
        if (model.parameters()[i].name == QStringLiteral("m·cy₃ + m·cy₄")) {
            QCOMPARE(phi[i], 0.0);
            ++found;
        }
    }
    QCOMPARE(found, 1);
    // A sum that does not cancel is kept, however small against other parameters.
    Eigen::VectorXd pi = model.cadStandard();
    pi[22] += 1e-9; // m cy of link 3
    bool kept = false;
    for (int i = 0; i < model.parameterCount(); ++i)
        if (model.parameters()[i].name == QStringLiteral("m·cy₃ + m·cy₄"))
            kept = std::abs(model.baseFromStandard(pi)[i] - 1e-9) < 1e-15;
    QVERIFY(kept);
}

void TestChainModel::paperArmUrdf_equalsEquation21AfterTheChangeOfAngles()
{
    const ChainModel chain(parseUrdfChain(paperArmUrdf, QStringLiteral("paper arm")), inertiaOnly(),
                           QStringLiteral("paper-urdf"));
    const TwoLinkArm paper;
    Eigen::Matrix2d t; // absolute = T relative
    t << 1, 0, 1, 1;
    std::mt19937 random(13);
    for (int trial = 0; trial < 20; ++trial) {
        Eigen::VectorXd pi = randomVector(chain.standardCount(), random);
        pi[12] = 0.0; // m cy of link 2: the paper's arm has its centre of mass on the link
        const Eigen::VectorXd phi = chain.baseFromStandard(pi);
        const Eigen::Vector3d abc(phi[0], 0.75 * phi[1], phi[3]);
        const Eigen::VectorXd q = randomVector(2, random, 3.0), qd = randomVector(2, random, 2.0),
                              qdd = randomVector(2, random, 4.0);
        const Eigen::VectorXd tauAbsolute = paper.torqueAt(t * q, t * qd, t * qdd, abc);
        LEARNID_COMPARE_MATRIX(chain.torqueAt(q, qd, qdd, phi), t.transpose() * tauAbsolute, 1e-12);
    }
}

void TestChainModel::paperArmUrdf_baseParametersAreABAndC()
{
    const ChainModel chain(parseUrdfChain(paperArmUrdf, QStringLiteral("paper arm")), inertiaOnly(),
                           QStringLiteral("paper-urdf"));
    QCOMPARE(chain.parameterCount(), 4);
    QStringList names;
    for (const ParameterInfo &info : chain.parameters())
        names << info.name;
    // a = Izz1 + m2 l1^2, b = l1 m cx2, c = Izz2, and m cy2 (zero on the paper's arm).
    QCOMPARE(names, QStringList({QStringLiteral("Izz₁ + 0.5625·m₂"), QStringLiteral("m·cx₂"),
                                 QStringLiteral("m·cy₂"), QStringLiteral("Izz₂")}));
    const std::vector<int> &dependent = chain.base().dependent();
    const auto m2 = std::find(dependent.begin(), dependent.end(), 10); // link 2's mass
    QVERIFY(m2 != dependent.end());
    LEARNID_COMPARE_NEAR(chain.base().beta()(0, m2 - dependent.begin()), 0.5625, 1e-12);
}

void TestChainModel::pathNotMovingAJoint_leavesItsTermsUnobservedAndKept()
{
    const ChainModel model(parseUrdfChain(paperArmUrdf, QStringLiteral("paper arm")), allTerms(),
                           QStringLiteral("paper-urdf"));
    // The shoulder moves, the elbow is held at 0.4 rad.
    const int samples = 400;
    const int m = model.parameterCount();
    Eigen::MatrixXd a(2 * samples, m);
    for (int k = 0; k < samples; ++k) {
        const double t = 0.01 * k;
        const Eigen::Vector2d q(std::sin(t), 0.4), qd(std::cos(t), 0.0), qdd(-std::sin(t), 0.0);
        a.middleRows(2 * k, 2) = model.regressorAt(q, qd, qdd);
    }
    const Eigen::VectorXd truth = model.baseFromStandard(model.cadStandard()) * 1.3;
    const Eigen::VectorXd prior = model.baseFromStandard(model.cadStandard());
    const ParameterUpdate update = observableUpdate(a, a * truth, 2, prior, 1e-8);
    QVERIFY(update.rank < m);
    for (int i = 0; i < m; ++i) {
        const QString name = model.parameters()[i].name;
        const bool elbowTerm = name.startsWith(QStringLiteral("Ia₂")) ||
                               name.startsWith(QStringLiteral("fv₂")) ||
                               name.startsWith(QStringLiteral("fc₂"));
        if (elbowTerm) {
            QVERIFY2(!update.observable[size_t(i)], qPrintable(name));
            LEARNID_COMPARE_NEAR(update.phi[i], prior[i], 1e-12);
        }
    }
    // What the path sees is learnt exactly: the torques on the path are the truth's.
    LEARNID_COMPARE_MATRIX(a * update.phi, a * truth, 1e-9 * (a * truth).norm());
}

QTEST_GUILESS_MAIN(TestChainModel)
#include "tst_chainmodel.moc"
