#include "../support/NumericAssert.h"
#include "model/Error.h"
#include "motion/TwoLinkKinematics.h"

#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;

namespace {

constexpr double deg = M_PI / 180.0;
constexpr double linkLength = 0.75; // docs/design.md §2

// A random point of the reachable annulus of two links l1, l2, away from its boundaries.
Eigen::Vector2d randomReachablePoint(std::mt19937 &rng, double l1, double l2)
{
    const double rMin = std::abs(l1 - l2) + 0.02;
    const double rMax = l1 + l2 - 0.02;
    std::uniform_real_distribution<double> radius(rMin, rMax);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI);
    const double r = radius(rng);
    const double a = angle(rng);
    return {r * std::cos(a), r * std::sin(a)};
}

const Eigen::VectorXd noNear;

} // namespace

class TestTwoLinkKinematics : public QObject
{
    Q_OBJECT

private slots:
    void paperStart_givesPaperAngles();
    void forwardOfInverse_isIdentity_data();
    void forwardOfInverse_isIdentity();
    void elbowSign_selectsBranch();
    void jacobian_equalsCentralDifferences();
    void jacobianDotTimesQd_equalsDerivativeOfJacobianAlongQd();
    void jointState_equalsTheGenericInverseJacobianRoute();
    void unreachablePoint_throwsNamingThePoint();
    void singularPoints_throw();
    void near_keepsTheTwoPiBranch();
    void near_keepsPathContinuousAcrossAngleCut();
};

// docs/design.md §2: with equal links l, a point at distance r and bearing psi has
// th1 = psi - alpha, th2 = psi + alpha, cos alpha = r / (2 l). At (0.5, 0.5) m, l = 0.75 m:
// psi = 45 deg, alpha = 61.87 deg, i.e. -16.87 deg / 106.87 deg.
void TestTwoLinkKinematics::paperStart_givesPaperAngles()
{
    const TwoLinkKinematics kin(linkLength, linkLength);
    QCOMPARE(kin.dof(), 2);
    const Eigen::Vector2d start(0.5, 0.5);
    const Eigen::VectorXd q = kin.inverse(start, noNear);
    QCOMPARE(q.size(), 2);
    const double psi = std::atan2(start.y(), start.x());
    const double alpha = std::acos(start.norm() / (2.0 * linkLength));
    LEARNID_COMPARE_NEAR(q[0], psi - alpha, 1e-12);
    LEARNID_COMPARE_NEAR(q[1], psi + alpha, 1e-12);
    // The paper quotes two decimals.
    LEARNID_COMPARE_NEAR(q[0] / deg, -16.87, 0.005);
    LEARNID_COMPARE_NEAR(q[1] / deg, 106.87, 0.005);
}

void TestTwoLinkKinematics::forwardOfInverse_isIdentity_data()
{
    QTest::addColumn<double>("l1");
    QTest::addColumn<double>("l2");
    QTest::addColumn<int>("elbow");
    QTest::newRow("paper arm, elbow +") << 0.75 << 0.75 << 1;
    QTest::newRow("paper arm, elbow -") << 0.75 << 0.75 << -1;
    QTest::newRow("unequal links, elbow +") << 0.9 << 0.4 << 1;
    QTest::newRow("unequal links, elbow -") << 0.3 << 0.7 << -1;
}

void TestTwoLinkKinematics::forwardOfInverse_isIdentity()
{
    QFETCH(double, l1);
    QFETCH(double, l2);
    QFETCH(int, elbow);
    const TwoLinkKinematics kin(l1, l2, elbow);
    std::mt19937 rng(31);
    for (int trial = 0; trial < 500; ++trial) {
        const Eigen::Vector2d x = randomReachablePoint(rng, l1, l2);
        const Eigen::VectorXd q = kin.inverse(x, noNear);
        LEARNID_COMPARE_MATRIX(kin.forward(q), x, 1e-12);
        // forward() against the definition, independently of inverse().
        const Eigen::Vector2d expected(l1 * std::cos(q[0]) + l2 * std::cos(q[1]),
                                       l1 * std::sin(q[0]) + l2 * std::sin(q[1]));
        LEARNID_COMPARE_MATRIX(kin.forward(q), expected, 1e-15);
    }
}

void TestTwoLinkKinematics::elbowSign_selectsBranch()
{
    std::mt19937 rng(37);
    const TwoLinkKinematics up(linkLength, linkLength, +1);
    const TwoLinkKinematics down(linkLength, linkLength, -1);
    for (int trial = 0; trial < 200; ++trial) {
        const Eigen::Vector2d x = randomReachablePoint(rng, linkLength, linkLength);
        const Eigen::VectorXd qUp = up.inverse(x, noNear);
        const Eigen::VectorXd qDown = down.inverse(x, noNear);
        const double relUp = qUp[1] - qUp[0];
        const double relDown = qDown[1] - qDown[0];
        QVERIFY2(relUp > 0.0 && relUp < M_PI, qPrintable(QString::number(relUp)));
        QVERIFY2(relDown < 0.0 && relDown > -M_PI, qPrintable(QString::number(relDown)));
        LEARNID_COMPARE_NEAR(relUp, -relDown, 1e-12);
    }
}

// Central differences with step h: truncation ~ h^2 |x'''| / 6 ~ 1e-13, rounding ~ 1e-16 / h.
void TestTwoLinkKinematics::jacobian_equalsCentralDifferences()
{
    const TwoLinkKinematics kin(0.9, 0.4);
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI);
    const double h = 1e-6;
    for (int trial = 0; trial < 200; ++trial) {
        const Eigen::Vector2d q(angle(rng), angle(rng));
        Eigen::Matrix2d numeric;
        for (int i = 0; i < 2; ++i) {
            const Eigen::Vector2d dq = h * Eigen::Vector2d::Unit(i);
            numeric.col(i) = (kin.forward(q + dq) - kin.forward(q - dq)) / (2.0 * h);
        }
        LEARNID_COMPARE_MATRIX(kin.jacobian(q), numeric, 1e-9);
    }
}

// Jdot qd = (dJ/dq . qd) qd = d/dh J(q + h qd) qd at h = 0.
void TestTwoLinkKinematics::jacobianDotTimesQd_equalsDerivativeOfJacobianAlongQd()
{
    const TwoLinkKinematics kin(0.9, 0.4);
    std::mt19937 rng(43);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI);
    std::uniform_real_distribution<double> rate(-4.0, 4.0);
    const double h = 1e-6;
    for (int trial = 0; trial < 200; ++trial) {
        const Eigen::Vector2d q(angle(rng), angle(rng));
        const Eigen::Vector2d qd(rate(rng), rate(rng));
        const Eigen::Vector2d numeric =
            (kin.jacobian(q + h * qd) - kin.jacobian(q - h * qd)) * qd / (2.0 * h);
        LEARNID_COMPARE_MATRIX(kin.jacobianDotTimesQd(q, qd), numeric, 1e-7);
    }
}

// The override shares one set of sines and cosines; the base class evaluates inverse kinematics,
// Jacobian and Jdot qd separately (sin/cos of each angle) and inverts J: the same state.
void TestTwoLinkKinematics::jointState_equalsTheGenericInverseJacobianRoute()
{
    for (int elbow : {1, -1}) {
        const TwoLinkKinematics kin(0.9, 0.4, elbow);
        std::mt19937 rng(47);
        std::uniform_real_distribution<double> rate(-2.0, 2.0);
        for (int trial = 0; trial < 300; ++trial) {
            const Eigen::Vector2d x = randomReachablePoint(rng, 0.9, 0.4);
            const Eigen::Vector2d xd(rate(rng), rate(rng)), xdd(rate(rng), rate(rng));
            const Eigen::Vector2d near = kin.inverse(x, noNear) + Eigen::Vector2d(0.3, -0.2);
            Eigen::VectorXd q(2), qd(2), qdd(2), qRef(2), qdRef(2), qddRef(2);
            kin.jointStateInto(x, xd, xdd, near, q, qd, qdd);
            kin.Kinematics::jointStateInto(x, xd, xdd, near, qRef, qdRef, qddRef);
            QCOMPARE(q, qRef);
            // J^-1 grows near the folded arm (r = 0.52 m): compare relative to the magnitudes.
            LEARNID_COMPARE_MATRIX(qd, qdRef, 1e-12 * (1.0 + qdRef.cwiseAbs().maxCoeff()));
            LEARNID_COMPARE_MATRIX(qdd, qddRef, 1e-11 * (1.0 + qddRef.cwiseAbs().maxCoeff()));
            LEARNID_COMPARE_MATRIX(kin.forward(q), x, 1e-12);
        }
    }
}

void TestTwoLinkKinematics::unreachablePoint_throwsNamingThePoint()
{
    const TwoLinkKinematics kin(linkLength, linkLength);
    try {
        kin.inverse(Eigen::Vector2d(1.6, 0.3), noNear);
        QFAIL("a point 1.63 m from the base of a 1.5 m arm was accepted");
    } catch (const Error &e) {
        QVERIFY2(e.message().contains(QStringLiteral("(1.6000, 0.3000)")), qPrintable(e.message()));
        QCOMPARE(QString::fromStdString(e.what()), e.message());
    }
    // Inside the inner radius of unequal links.
    const TwoLinkKinematics unequal(0.9, 0.4);
    QVERIFY_THROWS_EXCEPTION(Error, unequal.inverse(Eigen::Vector2d(0.1, -0.2), noNear));
}

// Stretched (r = l1 + l2) and folded (r = |l1 - l2|) arms have no finite joint velocity.
void TestTwoLinkKinematics::singularPoints_throw()
{
    const TwoLinkKinematics kin(linkLength, linkLength);
    QVERIFY_THROWS_EXCEPTION(Error, kin.inverse(Eigen::Vector2d(1.5, 0.0), noNear));
    QVERIFY_THROWS_EXCEPTION(Error, kin.inverse(Eigen::Vector2d(0.0, 0.0), noNear));
    const double r = 1.5 / std::sqrt(2.0);
    QVERIFY_THROWS_EXCEPTION(Error, kin.inverse(Eigen::Vector2d(r, r), noNear));
    // Just inside the workspace is fine.
    const Eigen::VectorXd q = kin.inverse(Eigen::Vector2d(1.49, 0.0), noNear);
    LEARNID_COMPARE_MATRIX(kin.forward(q), Eigen::Vector2d(1.49, 0.0), 1e-12);
}

void TestTwoLinkKinematics::near_keepsTheTwoPiBranch()
{
    const TwoLinkKinematics kin(linkLength, linkLength);
    const Eigen::Vector2d x(0.5, 0.5);
    const Eigen::VectorXd base = kin.inverse(x, noNear);
    for (int k = -3; k <= 3; ++k) {
        // A reference anywhere within half a turn of the shifted solution selects that branch.
        for (double offset : {-3.0, -0.5, 0.0, 0.5, 3.0}) {
            const Eigen::Vector2d near = base + Eigen::Vector2d::Constant(2.0 * M_PI * k + offset);
            const Eigen::VectorXd q = kin.inverse(x, near);
            LEARNID_COMPARE_MATRIX(q, base + Eigen::Vector2d::Constant(2.0 * M_PI * k), 1e-12);
        }
    }
}

// A circle about the base crosses atan2's cut at 180 deg; with the previous solution as `near`
// the joint angles change smoothly; without it theta1 jumps by 2 pi.
void TestTwoLinkKinematics::near_keepsPathContinuousAcrossAngleCut()
{
    const TwoLinkKinematics kin(linkLength, linkLength);
    const double r = 1.0;
    const double alpha = std::acos(r / (2.0 * linkLength)); // equal links
    Eigen::VectorXd prev;
    bool jumpedWithoutNear = false;
    Eigen::VectorXd prevNoNear;
    for (int i = 0; i <= 400; ++i) {
        const double bearing = (150.0 + 0.2 * i) * deg; // 150 .. 230 deg
        const Eigen::Vector2d x(r * std::cos(bearing), r * std::sin(bearing));
        const Eigen::VectorXd q = kin.inverse(x, prev);
        // Continuous solution: th1 = bearing - alpha exactly (no wrapping).
        LEARNID_COMPARE_NEAR(q[0], bearing - alpha, 1e-12);
        LEARNID_COMPARE_NEAR(q[1], bearing + alpha, 1e-12);
        const Eigen::VectorXd qNoNear = kin.inverse(x, noNear);
        if (prevNoNear.size() == 2 && std::abs(qNoNear[0] - prevNoNear[0]) > M_PI)
            jumpedWithoutNear = true;
        prev = q;
        prevNoNear = qNoNear;
    }
    QVERIFY(jumpedWithoutNear); // the test path really crosses the cut
}

QTEST_GUILESS_MAIN(TestTwoLinkKinematics)
#include "tst_twolinkkinematics.moc"
