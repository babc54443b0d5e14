#include "../support/NumericAssert.h"
#include "InertiaSamples.h"
#include "model/LogCholesky.h"
#include "model/PhysicalConsistency.h"

#include <Eigen/Dense>
#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;
using namespace learnid::test;

namespace {

double maxEigenvalue(const Vector10d &pi)
{
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(pseudoInertia(pi)).eigenvalues()[3];
}

// A J-eigenvalue-clipped copy of every link (consistent; degenerate where it was violated).
Eigen::VectorXd clippedLinks(Eigen::VectorXd pi, int links)
{
    for (int l = 0; l < links; ++l) {
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> e(
            pseudoInertia(pi.segment<10>(10 * l)));
        const Eigen::Matrix4d j = e.eigenvectors() * e.eigenvalues().cwiseMax(0.0).asDiagonal() *
                                  e.eigenvectors().transpose();
        pi.segment<10>(10 * l) = inertialFromPseudoInertia(j);
    }
    return pi;
}

double costOf(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, const Eigen::VectorXd &pi)
{
    return (a * pi - b).squaredNorm();
}

Box slenderBox()
{
    Box box = sampleBox();
    box.mass = 1.5;
    box.size = {0.6, 0.08, 0.08};
    box.centre = {0.35, 0.02, 0.0};
    return box;
}

// A two-link prior with four joint terms: armature, viscous, Coulomb, offset (indices 20-23).
Eigen::VectorXd twoLinkPrior()
{
    Eigen::VectorXd prior(24);
    prior << boxInertial(sampleBox()), boxInertial(slenderBox()), 0.02, 0.1, 0.4, -0.05;
    return prior;
}

bool allConsistent(const Eigen::VectorXd &pi, int links, double tolerance)
{
    for (const LinkConsistency &v : checkConsistency(pi, links, tolerance))
        if (!v.consistent)
            return false;
    return true;
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
    void nearest_ofConsistentTarget_returnsTheTarget();
    void nearest_ofInconsistentTarget_isConsistentAndNoWorseThanCandidates();
    void nearest_rankDeficientRows_keepUnseenDirectionsAtPrior();
    void nearest_rankDeficientRowsInconsistentFit_isOptimalOverConsistentSet();
    void nearest_negativeViscousTarget_isClippedToZero();
    void nearest_badInput_throwsNamingTheArgument();
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

void TestPhysicalConsistency::nearest_ofConsistentTarget_returnsTheTarget()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    Eigen::VectorXd target = prior;
    target.head<10>() =
        boxInertial({2.5, {0.3, 0.3, 0.1}, Eigen::Matrix3d::Identity(), {0.1, 0.0, 0.2}});
    target.tail<4>() << 0.03, 0.2, 0.0, 0.1;
    const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(24, 24);
    const ConsistentEstimate fit = nearestConsistentEstimate(
        a, target, prior, Eigen::VectorXd::Ones(24), 0.0, 2, {20, 21, 22});
    QVERIFY(fit.converged);
    LEARNID_COMPARE_MATRIX(fit.standard, target, 1e-8 * target.cwiseAbs().maxCoeff());
    QVERIFY(fit.cost <= 1e-16);
}

void TestPhysicalConsistency::nearest_ofInconsistentTarget_isConsistentAndNoWorseThanCandidates()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    Eigen::VectorXd target = prior;
    target[0] = -0.5; // link 0: negative mass, a large violation
    // Link 1: Ixx about the centre 0.1 % past Iyy + Izz, a small one.
    const Eigen::Vector3d c1(0.35, 0.02, 0.0);
    const Eigen::Vector3d ic1(1.001 * (0.045 + 0.046), 0.045, 0.046);
    target.segment<10>(10) = inertialOf(1.5, ic1.asDiagonal(), c1);
    const Vector10d triangleMet =
        inertialOf(1.5, Eigen::Vector3d(0.091, 0.045, 0.046).asDiagonal(), c1);
    QVERIFY(!allConsistent(target, 2, 1e-12));

    std::mt19937_64 rng(3);
    std::normal_distribution<double> normal;
    const Eigen::MatrixXd random =
        Eigen::MatrixXd::NullaryExpr(30, 24, [&] { return normal(rng); });
    for (const Eigen::MatrixXd &a : {Eigen::MatrixXd(Eigen::MatrixXd::Identity(24, 24)), random}) {
        const Eigen::VectorXd b = a * target;
        const ConsistentEstimate fit = nearestConsistentEstimate(
            a, b, prior, prior.cwiseAbs().cwiseMax(1e-2).cwiseInverse(), 0.0, 2, {20, 21, 22});
        QVERIFY(fit.converged);
        QVERIFY(allConsistent(fit.standard, 2, 1e-10));
        QVERIFY(negativeJointTerms(fit.standard, {20, 21, 22}).empty());
        LEARNID_COMPARE_NEAR(fit.cost, costOf(a, b, fit.standard), 1e-12 * (1.0 + fit.cost));

        Eigen::VectorXd fixed = target;
        fixed.head<10>() = prior.head<10>();
        fixed.segment<10>(10) = triangleMet;
        const std::vector<Eigen::VectorXd> candidates = {prior, 1.3 * prior, 0.7 * prior,
                                                         clippedLinks(target, 2), fixed};
        for (const Eigen::VectorXd &candidate : candidates) {
            QVERIFY(allConsistent(candidate, 2, 1e-10));
            const double other = costOf(a, b, candidate);
            QVERIFY2(
                fit.cost <= other * (1.0 + 1e-9),
                qPrintable(QStringLiteral("cost %1 > candidate's %2").arg(fit.cost).arg(other)));
        }
        // Identity rows weigh every entry alike: the slightly violated link moves by about its
        // violation only.
        if (a.rows() == 24)
            QVERIFY((fit.standard.segment<10>(10) - target.segment<10>(10)).norm() <=
                    (triangleMet - target.segment<10>(10)).norm());
    }
}

// Rows that see link 0 and the joint terms through 10 mixtures (rank 10 of 24), a target a
// little off the prior: the unconstrained optimum is consistent, so it is the answer.
void TestPhysicalConsistency::nearest_rankDeficientRows_keepUnseenDirectionsAtPrior()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal;
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(10, 24);
    for (const int c : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 20, 21, 22, 23})
        for (int r = 0; r < 10; ++r)
            a(r, c) = normal(rng);
    Box first = sampleBox();
    first.mass = 3.003;
    first.centre.x() += 0.001;
    Eigen::VectorXd target = prior;
    target.head<10>() = boxInertial(first);
    target.tail<4>() << 0.0201, 0.1001, 0.4004, -0.0501;
    const Eigen::VectorXd b = a * target;
    const Eigen::VectorXd scale = prior.cwiseAbs().cwiseMax(1e-2).cwiseInverse();
    const double w = 1e-3;
    const ConsistentEstimate fit =
        nearestConsistentEstimate(a, b, prior, scale, w, 2, {20, 21, 22});
    QVERIFY(fit.converged);
    QVERIFY(allConsistent(fit.standard, 2, 1e-12));

    const Eigen::MatrixXd d2 = scale.cwiseAbs2().asDiagonal();
    const Eigen::VectorXd expected =
        (a.transpose() * a + w * w * d2).ldlt().solve(a.transpose() * b + w * w * d2 * prior);
    QVERIFY(allConsistent(expected, 2, 0.0));
    QVERIFY(negativeJointTerms(expected, {20, 21, 22}).empty());
    LEARNID_COMPARE_MATRIX(fit.standard, expected, 1e-8 * prior.cwiseAbs().maxCoeff());
    // Link 1 is not seen at all: it stays at the prior.
    LEARNID_COMPARE_MATRIX(fit.standard.segment<10>(10), prior.segment<10>(10),
                           1e-9 * prior.cwiseAbs().maxCoeff());
    // What the rows see is fitted (to the prior's small pull), and what they do not see stays
    // at the prior: N^T D^2 (pi - prior) = 0 for the null space N of A.
    LEARNID_COMPARE_MATRIX(a * fit.standard, b, 1e-5 * b.cwiseAbs().maxCoeff());
    const Eigen::MatrixXd kernel = a.fullPivLu().kernel();
    QCOMPARE(kernel.cols(), Eigen::Index(14));
    const Eigen::VectorXd moved = d2 * (fit.standard - prior);
    LEARNID_COMPARE_MATRIX(kernel.transpose() * moved, Eigen::VectorXd::Zero(14),
                           1e-6 * moved.norm());
}

// Random rows (rank 8 of 24), a weak prior (the costly case for log-Cholesky coordinates) and
// a target whose unconstrained fit leaves the consistent set: the result is consistent, and no
// consistent point along the way to other consistent points, or into J's interior, is cheaper
// (the problem is convex in pi, so that is optimality).
void TestPhysicalConsistency::nearest_rankDeficientRowsInconsistentFit_isOptimalOverConsistentSet()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    const Eigen::VectorXd scale = prior.cwiseAbs().cwiseMax(1e-2).cwiseInverse();
    for (const unsigned seed : {7u, 9u, 10u}) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> normal;
        const Eigen::MatrixXd a = Eigen::MatrixXd::NullaryExpr(8, 24, [&] { return normal(rng); });
        Box first = sampleBox(), second = slenderBox();
        for (Box *box : {&first, &second}) {
            box->mass *= 1.0 + 0.05 * normal(rng);
            for (int k = 0; k < 3; ++k) {
                box->size[k] *= 1.0 + 0.05 * normal(rng);
                box->centre[k] += 0.02 * normal(rng);
            }
        }
        Eigen::VectorXd target(24);
        target << boxInertial(first), boxInertial(second), 0.025, 0.08, 0.45, -0.02;
        const Eigen::VectorXd b = a * target;
        const double w = 1e-3;
        const Eigen::MatrixXd rows =
            (Eigen::MatrixXd(32, 24) << a, w * scale.asDiagonal().toDenseMatrix()).finished();
        const Eigen::VectorXd targets =
            (Eigen::VectorXd(32) << b, w * scale.cwiseProduct(prior)).finished();
        const Eigen::VectorXd unconstrained = rows.colPivHouseholderQr().solve(targets);
        QVERIFY(!allConsistent(unconstrained, 2, 1e-12));

        const ConsistentEstimate fit =
            nearestConsistentEstimate(a, b, prior, scale, w, 2, {20, 21, 22});
        QVERIFY(fit.converged);
        QVERIFY(fit.iterations < 200);
        QVERIFY(allConsistent(fit.standard, 2, 1e-12));
        QVERIFY(negativeJointTerms(fit.standard, {20, 21, 22}).empty());
        const double best = costOf(rows, targets, fit.standard);
        LEARNID_COMPARE_NEAR(fit.cost, best, 1e-12 * best);
        const double slack = 1e-8 * best;
        Eigen::VectorXd clipped = clippedLinks(unconstrained, 2);
        clipped.segment<3>(20) = clipped.segment<3>(20).cwiseMax(0.0);
        for (const Eigen::VectorXd &other : {prior, target, clipped}) {
            QVERIFY(allConsistent(other, 2, 1e-12));
            for (const double t : {1.0, 0.1, 1e-2, 1e-3}) {
                const double c = costOf(rows, targets, (1.0 - t) * fit.standard + t * other);
                QVERIFY2(c >= best - slack, qPrintable(QStringLiteral("seed %1, t %2: %3 < %4")
                                                           .arg(seed)
                                                           .arg(t)
                                                           .arg(c)
                                                           .arg(best)));
            }
        }
        for (int l = 0; l < 2; ++l) {
            for (int k = 0; k < 20; ++k) {
                const Eigen::Vector4d v = Eigen::Vector4d::NullaryExpr([&] { return normal(rng); });
                Eigen::VectorXd inside = fit.standard;
                inside.segment<10>(10 * l) += inertialFromPseudoInertia(1e-6 * v * v.transpose());
                QVERIFY(costOf(rows, targets, inside) >= best - slack);
            }
        }
    }
}

void TestPhysicalConsistency::nearest_negativeViscousTarget_isClippedToZero()
{
    Eigen::VectorXd priorOneLink(14);
    priorOneLink << boxInertial(sampleBox()), 0.02, 0.1, 0.4, -0.05;
    Eigen::VectorXd target = priorOneLink;
    target.tail<4>() << 0.01, -0.2, 0.5, -0.3; // viscous < 0; the offset is free to be < 0
    const ConsistentEstimate fit =
        nearestConsistentEstimate(Eigen::MatrixXd::Identity(14, 14), target, priorOneLink,
                                  Eigen::VectorXd::Ones(14), 0.0, 1, {10, 11, 12});
    QVERIFY(fit.converged);
    QVERIFY(fit.standard[11] >= 0.0);
    QVERIFY(fit.standard[11] <= 1e-10);
    LEARNID_COMPARE_NEAR(fit.cost, 0.04, 1e-10);
    Eigen::VectorXd expected = target;
    expected[11] = 0.0;
    LEARNID_COMPARE_MATRIX(fit.standard, expected, 1e-8);
}

void TestPhysicalConsistency::nearest_badInput_throwsNamingTheArgument()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(24, 24);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(24);
    const auto messageOf = [&](Eigen::MatrixXd aa, Eigen::VectorXd b, Eigen::VectorXd p,
                               Eigen::VectorXd s, double w, int links, std::vector<int> nonneg) {
        try {
            nearestConsistentEstimate(aa, b, p, s, w, links, nonneg);
        } catch (const Error &e) {
            return e.message();
        }
        return QString();
    };
    const auto expectMessage = [](const QString &message, const QString &part) {
        QVERIFY2(message.contains(part),
                 qPrintable(QStringLiteral("'%1' does not name '%2'").arg(message, part)));
    };
    expectMessage(messageOf(a, prior.head(23), prior, ones, 0.0, 2, {}),
                  QStringLiteral("b has 23"));
    expectMessage(messageOf(a, prior, prior.head(20), ones, 0.0, 2, {}),
                  QStringLiteral("prior has 20"));
    expectMessage(messageOf(a, prior, prior, ones.head(3), 0.0, 2, {}),
                  QStringLiteral("priorScale has 3"));
    expectMessage(messageOf(a, prior, prior, ones, 0.0, 3, {}), QStringLiteral("3 links"));
    Eigen::MatrixXd badA = a;
    badA(1, 2) = NAN;
    expectMessage(messageOf(badA, prior, prior, ones, 0.0, 2, {}), QStringLiteral("A(1, 2)"));
    Eigen::VectorXd badPrior = prior;
    badPrior[3] = INFINITY;
    expectMessage(messageOf(a, prior, badPrior, ones, 0.0, 2, {}), QStringLiteral("prior[3]"));
    Eigen::VectorXd badB = prior;
    badB[21] = NAN;
    expectMessage(messageOf(a, badB, prior, ones, 0.0, 2, {}), QStringLiteral("b[21]"));
    expectMessage(messageOf(a, prior, prior, -ones, 0.0, 2, {}), QStringLiteral("priorScale[0]"));
    expectMessage(messageOf(a, prior, prior, ones, -1.0, 2, {}), QStringLiteral("priorWeight"));
    expectMessage(messageOf(a, prior, prior, ones, NAN, 2, {}), QStringLiteral("priorWeight"));
    expectMessage(messageOf(a, prior, prior, ones, 0.0, 2, {4}),
                  QStringLiteral("nonnegativeIndices holds 4"));
    Eigen::VectorXd massless = prior;
    massless[10] = 0.0;
    expectMessage(messageOf(a, prior, massless, ones, 0.0, 2, {}), QStringLiteral("prior[10]"));
}

QTEST_GUILESS_MAIN(TestPhysicalConsistency)
#include "tst_physicalconsistency.moc"
