#include "../support/NumericAssert.h"
#include "InertiaSamples.h"
#include "model/PhysicalConsistency.h"

#include <Eigen/Dense>
#include <QTest>
#include <cmath>

using namespace learnid;
using namespace learnid::test;

namespace {

double maxEigenvalue(const Vector10d &pi)
{
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(pseudoInertia(pi)).eigenvalues()[3];
}

} // namespace

class TestPhysicalConsistency : public QObject
{
    Q_OBJECT

private slots:
    void pseudoInertiaOfSolidBox_equalsItsSecondMoments();
    void negativeMassOrBrokenTriangleInequality_isInconsistentForThatLink();
    void pointMassAndThinRod_areConsistentButDegenerate();
    void negativeJointTerms_listsTheNegativeOnes();
};

void TestPhysicalConsistency::pseudoInertiaOfSolidBox_equalsItsSecondMoments()
{
    const Box box = sampleBox();
    const Vector10d pi = boxInertial(box);
    const Eigen::Matrix4d j = pseudoInertia(pi);
    LEARNID_COMPARE_MATRIX(j, boxSecondMoments(box), 1e-14);
    LEARNID_COMPARE_MATRIX(inertialFromPseudoInertia(j), pi, 1e-14);

    const std::vector<LinkConsistency> verdict = checkConsistency(pi, 1, 1e-12);
    QCOMPARE(verdict.size(), size_t(1));
    QCOMPARE(verdict[0].mass, 3.0);
    // The smallest second moment of the box is at least its thinnest spread, m 0.1^2 / 12,
    // shifted: positive, and far from the tolerance.
    QVERIFY(verdict[0].minEigenvalue > 1e-4);
    QVERIFY(verdict[0].consistent);
    QVERIFY(!verdict[0].degenerate);
}

void TestPhysicalConsistency::negativeMassOrBrokenTriangleInequality_isInconsistentForThatLink()
{
    const Vector10d good = boxInertial(sampleBox());
    Vector10d negativeMass = good;
    negativeMass[0] = -3.0;
    // About the centre Ixx = 1.05 (Iyy + Izz): no mass distribution has it.
    const Eigen::Vector3d c(0.1, 0.2, -0.1);
    const Vector10d broken =
        inertialOf(2.0, Eigen::Vector3d(1.05 * (0.02 + 0.03), 0.02, 0.03).asDiagonal(), c);
    Eigen::VectorXd standard(33);
    standard << good, negativeMass, broken, 0.5, -0.1, 0.2;

    const std::vector<LinkConsistency> verdicts = checkConsistency(standard, 3, 1e-12);
    QCOMPARE(verdicts.size(), size_t(3));
    for (int l = 0; l < 3; ++l)
        QCOMPARE(verdicts[size_t(l)].link, l);
    QVERIFY(verdicts[0].consistent);
    QVERIFY(!verdicts[1].consistent);
    QCOMPARE(verdicts[1].mass, -3.0);
    QVERIFY(!verdicts[2].consistent);
    QVERIFY(verdicts[2].mass > 0.0);
    // J's Sigma_xx about the centre is (Iyy + Izz - Ixx) / 2 < 0.
    QVERIFY(verdicts[2].minEigenvalue < -1e-4);
    // Just inside the triangle inequality is consistent.
    const Vector10d inside =
        inertialOf(2.0, Eigen::Vector3d(0.99 * (0.02 + 0.03), 0.02, 0.03).asDiagonal(), c);
    QVERIFY(checkConsistency(inside, 1, 1e-12)[0].consistent);

    QVERIFY_THROWS_EXCEPTION(Error, checkConsistency(standard, 4, 1e-12));
    standard[14] = NAN;
    QVERIFY_THROWS_EXCEPTION(Error, checkConsistency(standard, 3, 1e-12));
}

void TestPhysicalConsistency::pointMassAndThinRod_areConsistentButDegenerate()
{
    const Eigen::Vector3d c(0.4, -0.3, 0.2);
    const Vector10d point = inertialOf(2.0, Eigen::Matrix3d::Zero(), c);
    const Eigen::Vector3d u = Eigen::Vector3d(1.0, 2.0, -1.0).normalized();
    const double length = 0.8;
    const Vector10d rod = inertialOf(
        1.5, 1.5 * length * length / 12.0 * (Eigen::Matrix3d::Identity() - u * u.transpose()), c);

    for (const Vector10d &pi : {point, rod}) {
        const LinkConsistency exact = checkConsistency(pi, 1, 1e-12)[0];
        QVERIFY(exact.consistent);
        QVERIFY(exact.degenerate);
        QVERIFY(std::abs(exact.minEigenvalue) <= 1e-12 * exact.maxEigenvalue);
        // Rounding-sized negative eigenvalue: still consistent; a real one: not.
        const double scale = maxEigenvalue(pi);
        QVERIFY(
            checkConsistency(shiftedLeastEigenvalue(pi, -1e-14 * scale), 1, 1e-12)[0].consistent);
        QVERIFY(
            !checkConsistency(shiftedLeastEigenvalue(pi, -1e-6 * scale), 1, 1e-12)[0].consistent);
        // Fattened a little (every second moment): a solid body, no longer degenerate.
        const Vector10d fat = inertialFromPseudoInertia(pseudoInertia(pi) +
                                                        1e-6 * scale * Eigen::Matrix4d::Identity());
        const LinkConsistency solid = checkConsistency(fat, 1, 1e-12)[0];
        QVERIFY(solid.consistent);
        QVERIFY(!solid.degenerate);
    }
    // The rod's J has rank 2: two eigenvalues vanish.
    const Eigen::Vector4d rodEigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(pseudoInertia(rod)).eigenvalues();
    QVERIFY(std::abs(rodEigenvalues[1]) <= 1e-12 * rodEigenvalues[3]);
    QVERIFY(rodEigenvalues[2] > 1e-3);
}

void TestPhysicalConsistency::negativeJointTerms_listsTheNegativeOnes()
{
    Eigen::VectorXd standard(14);
    standard << boxInertial(sampleBox()), 0.0, -0.1, 0.3, -0.2;
    QCOMPARE(negativeJointTerms(standard, {10, 11, 12}), std::vector<int>({11}));
    QCOMPARE(negativeJointTerms(standard, {13, 11}), std::vector<int>({13, 11}));
    QVERIFY(negativeJointTerms(standard, {}).empty());
    QVERIFY_THROWS_EXCEPTION(Error, negativeJointTerms(standard, {14}));
}

QTEST_GUILESS_MAIN(TestPhysicalConsistency)
#include "tst_physicalconsistency.moc"
