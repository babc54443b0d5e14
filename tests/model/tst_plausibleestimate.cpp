#include "../support/NumericAssert.h"
#include "InertiaSamples.h"
#include "model/Error.h"
#include "model/Plausibility.h"
#include "model/PlausibleEstimate.h"

#include <Eigen/Dense>
#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;
using namespace learnid::test;

namespace {

Box slenderBox()
{
    Box box = sampleBox();
    box.mass = 1.5;
    box.size = {0.6, 0.08, 0.08};
    box.centre = {0.35, 0.02, 0.0};
    return box;
}

// Two links and four joint terms: armature, viscous, Coulomb (nonnegative), offset (20-23).
Eigen::VectorXd twoLinkPrior()
{
    Eigen::VectorXd prior(24);
    prior << boxInertial(sampleBox()), boxInertial(slenderBox()), 0.02, 0.1, 0.4, -0.05;
    return prior;
}

PlausibleProblem problemOf(const Eigen::MatrixXd &a, const Eigen::VectorXd &b,
                           const Eigen::VectorXd &prior, double share)
{
    PlausibleProblem p;
    p.a = a;
    p.b = b;
    p.prior = prior;
    p.links = 2;
    p.nonnegative = {20, 21, 22};
    p.priorShare = share;
    return p;
}

// The log-det divergence from its definition through eigenvalues (not the Cholesky factors the
// estimator uses): sum over the eigenvalues l of J0^-1/2 J J0^-1/2 of l - ln l - 1.
double divergence(const Vector10d &pi, const Vector10d &prior)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> p0(pseudoInertia(prior));
    const Eigen::Matrix4d root = p0.operatorInverseSqrt();
    const Eigen::Vector4d l =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(root * pseudoInertia(pi) * root)
            .eigenvalues();
    if (!(l.minCoeff() > 0.0))
        return INFINITY;
    return (l.array() - l.array().log() - 1.0).sum();
}

// The estimator's cost written out independently, with its weights (PlausibleEstimate.h):
// gamma from the result, the joint terms' weights share |A_i|.
double costOf(const PlausibleProblem &p, const PlausibleEstimate &fit, const Eigen::VectorXd &pi)
{
    double cost = (p.a * pi - p.b).squaredNorm();
    for (int l = 0; l < p.links; ++l)
        cost += fit.linkWeight * divergence(pi.segment<10>(10 * l), p.prior.segment<10>(10 * l));
    for (Eigen::Index i = 10 * p.links; i < pi.size(); ++i) {
        const double column = p.a.col(i).norm();
        const double w = column > 0.0 ? p.priorShare * column : 1.0;
        cost += std::pow(w * (pi[i] - p.prior[i]), 2);
    }
    return cost;
}

bool feasible(const PlausibleProblem &p, const Eigen::VectorXd &pi)
{
    for (const int i : p.nonnegative)
        if (pi[i] < 0.0)
            return false;
    for (const LinkConsistency &c : checkConsistency(pi, p.links, 0.0))
        if (!c.consistent || c.degenerate)
            return false;
    return true;
}

} // namespace

class TestPlausibleEstimate : public QObject
{
    Q_OBJECT

private slots:
    void fullRankRows_plausibleTarget_isFollowed();
    void rankDeficientRows_isOptimalAndKeepsUnseenLinkAtPrior();
    void negativeFrictionTarget_isExactlyZero();
    void needleTarget_staysPlausibleByTheRule();
    void comOutsideVolume_isPulledInside();
    void badInput_throwsNamingTheArgument();
};

// Rows that see every parameter well (100 x the identity): a plausible target near the prior is
// the answer to within the prior's share^2 pull.
void TestPlausibleEstimate::fullRankRows_plausibleTarget_isFollowed()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    Eigen::VectorXd target = prior;
    Box first = sampleBox();
    first.mass = 3.3;
    first.centre += Eigen::Vector3d(0.01, -0.02, 0.005);
    target.head<10>() = boxInertial(first);
    target.tail<4>() << 0.03, 0.2, 0.3, 0.1;
    const Eigen::MatrixXd a = 100.0 * Eigen::MatrixXd::Identity(24, 24);
    const PlausibleProblem p = problemOf(a, a * target, prior, 1e-3);
    const PlausibleEstimate fit = plausibleEstimate(p);
    QVERIFY(fit.converged);
    LEARNID_COMPARE_MATRIX(fit.standard, target, 1e-4 * target.cwiseAbs().maxCoeff());
}

// Random rows of rank 12 that see link 0 and the joint terms only. Link 1 stays at the prior
// (its divergence is 0 there and nothing else acts on it), and no feasible point on the
// way to other feasible points is cheaper (the problem is convex in pi: that is optimality).
void TestPlausibleEstimate::rankDeficientRows_isOptimalAndKeepsUnseenLinkAtPrior()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    for (const unsigned seed : {3u, 7u, 11u}) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> normal;
        Eigen::MatrixXd a = Eigen::MatrixXd::Zero(12, 24);
        for (const int c : {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 20, 21, 22, 23})
            for (int r = 0; r < 12; ++r)
                a(r, c) = normal(rng);
        Box first = sampleBox();
        first.mass *= 1.0 + 0.2 * normal(rng);
        first.centre += 0.03 * Eigen::Vector3d::NullaryExpr([&] { return normal(rng); });
        Eigen::VectorXd target = prior;
        target.head<10>() = boxInertial(first);
        target.tail<4>() << 0.01, 0.15, 0.35, 0.02;
        const PlausibleProblem p = problemOf(a, a * target, prior, 0.01);
        const PlausibleEstimate fit = plausibleEstimate(p);
        QVERIFY(fit.converged);
        QVERIFY(feasible(p, fit.standard));
        // (to the barrier's last weight: 1e-10 of the cost over the divergence's weight)
        LEARNID_COMPARE_MATRIX(fit.standard.segment<10>(10), prior.segment<10>(10),
                               1e-6 * prior.cwiseAbs().maxCoeff());
        const double best = costOf(p, fit, fit.standard);
        LEARNID_COMPARE_NEAR(best, fit.dataCost + fit.priorCost, 1e-8 * best);
        const double slack = 1e-8 * best + 1e-12;
        for (const Eigen::VectorXd &other : {prior, target}) {
            QVERIFY(feasible(p, other));
            for (const double t : {1.0, 0.1, 1e-2, 1e-3}) {
                const double c = costOf(p, fit, (1.0 - t) * fit.standard + t * other);
                QVERIFY2(c >= best - slack, qPrintable(QStringLiteral("seed %1, t %2: %3 < %4")
                                                           .arg(seed)
                                                           .arg(t)
                                                           .arg(c)
                                                           .arg(best)));
            }
        }
        for (int k = 0; k < 40; ++k) {
            Eigen::VectorXd moved = fit.standard;
            moved.head<10>() += 1e-5 * prior.head<10>().cwiseAbs().cwiseProduct(
                                           Vector10d::NullaryExpr([&] { return normal(rng); }));
            moved.tail<4>() += 1e-5 * Eigen::Vector4d::NullaryExpr([&] { return normal(rng); });
            if (feasible(p, moved))
                QVERIFY(costOf(p, fit, moved) >= best - slack);
        }
    }
}

// The data want a negative viscous friction: it comes out exactly 0, not 1e-12 or a denormal,
// and the other terms follow the data.
void TestPlausibleEstimate::negativeFrictionTarget_isExactlyZero()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    Eigen::VectorXd target = prior;
    target.tail<4>() << 0.01, -0.2, 0.5, -0.3;
    const Eigen::MatrixXd a = 100.0 * Eigen::MatrixXd::Identity(24, 24);
    const PlausibleEstimate fit = plausibleEstimate(problemOf(a, a * target, prior, 1e-3));
    QVERIFY(fit.converged);
    QCOMPARE(fit.standard[21], 0.0);
    LEARNID_COMPARE_NEAR(fit.standard[22], 0.5, 1e-4);
    LEARNID_COMPARE_NEAR(fit.standard[23], -0.3, 1e-4);
    QVERIFY(tinyJointTerms(fit.standard, {20, 21, 22}).empty());
}

// The data want link 0 to be a needle (all its mass on a line): with the rule the estimate keeps
// every principal moment above the rule's share of the prior's smallest and a thickness.
void TestPlausibleEstimate::needleTarget_staysPlausibleByTheRule()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    Box needle = sampleBox();
    needle.size = {0.4, 1e-4, 1e-4};
    Eigen::VectorXd target = prior;
    target.head<10>() = boxInertial(needle);
    const Eigen::MatrixXd a = 1e3 * Eigen::MatrixXd::Identity(24, 24);
    PlausibleProblem p = problemOf(a, a * target, prior, 1e-5);
    const PlausibilityRule rule;
    const auto before = checkPlausibility(plausibleEstimate(p).standard, prior, 2, {}, rule);
    QVERIFY(!before[0].plausible); // with a weak prior and no rule the data win
    p.rule = rule;
    const PlausibleEstimate fit = plausibleEstimate(p);
    QVERIFY(fit.converged);
    const auto after = checkPlausibility(fit.standard, prior, 2, {}, rule);
    QVERIFY2(after[0].plausible, qPrintable(plausibilityProblem(after[0])));
    QVERIFY(after[0].moments[0] >= 1.1 * rule.minMomentShare * after[0].cadSmallestMoment * 0.999);
    QVERIFY(after[1].plausible);
}

// The data put link 1's centre of mass 0.3 m off its body: its bounding ellipsoid keeps the
// mass inside (tr(Q J) >= 0), and the centre of mass with it.
void TestPlausibleEstimate::comOutsideVolume_isPulledInside()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    Box moved = slenderBox();
    moved.centre += Eigen::Vector3d(0.0, 0.3, 0.0);
    Eigen::VectorXd target = prior;
    target.segment<10>(10) = boxInertial(moved);
    const Eigen::MatrixXd a = 1e3 * Eigen::MatrixXd::Identity(24, 24);
    PlausibleProblem p = problemOf(a, a * target, prior, 1e-3);
    const BoundingEllipsoid e =
        ellipsoidFromInertia(prior.segment<10>(10), cadVolumeMargin, cadVolumeMinimumAxis);
    QVERIFY(e.fitShare(target.segment<10>(10)) < 0.0);
    p.volumes = {std::nullopt, e};
    p.rule = PlausibilityRule();
    const PlausibleEstimate fit = plausibleEstimate(p);
    QVERIFY(fit.converged);
    QVERIFY(e.fitShare(fit.standard.segment<10>(10)) >= 0.0);
    const Eigen::Vector3d c = fit.standard.segment<3>(11) / fit.standard[10];
    QVERIFY(e.normalisedDistance(c) <= 1.0);
    // It moved towards the data as far as the volume lets it.
    QVERIFY(c.y() > slenderBox().centre.y() + 0.01);
}

void TestPlausibleEstimate::badInput_throwsNamingTheArgument()
{
    const Eigen::VectorXd prior = twoLinkPrior();
    const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(24, 24);
    const auto messageOf = [](const PlausibleProblem &p) {
        try {
            plausibleEstimate(p);
        } catch (const Error &e) {
            return e.message();
        }
        return QString();
    };
    PlausibleProblem p = problemOf(a, prior, prior, 0.01);
    p.b = prior.head(20);
    QVERIFY(messageOf(p).contains(QStringLiteral("b has 20 entries")));
    p = problemOf(a, prior, prior, 0.01);
    p.a(1, 2) = NAN;
    QVERIFY(messageOf(p).contains(QStringLiteral("not finite")));
    p = problemOf(a, prior, prior, 1.5);
    QVERIFY(messageOf(p).contains(QStringLiteral("between 0 and 1")));
    p = problemOf(a, prior, prior, 0.01);
    p.nonnegative = {4};
    QVERIFY(messageOf(p).contains(QStringLiteral("Index 4 is not a joint term")));
    p = problemOf(a, prior, prior, 0.01);
    p.prior[21] = -0.1;
    QVERIFY(messageOf(p).contains(QStringLiteral("joint term 21 is negative")));
    p = problemOf(a, prior, prior, 0.01);
    p.prior[10] = -1.0;
    QVERIFY(messageOf(p).contains(QStringLiteral("link 2")));
}

QTEST_GUILESS_MAIN(TestPlausibleEstimate)
#include "tst_plausibleestimate.moc"
