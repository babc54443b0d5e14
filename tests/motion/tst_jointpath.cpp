#include "../support/ErrorOf.h"
#include "../support/NumericAssert.h"
#include "model/Error.h"
#include "motion/JointPath.h"
#include "motion/TwoLinkKinematics.h"

#include <QTest>
#include <algorithm>
#include <cmath>
#include <limits>

using namespace learnid;

namespace {

// The quintic time scaling and its derivatives, written out independently of the production code.
double quintic(double v)
{
    return 10.0 * std::pow(v, 3) - 15.0 * std::pow(v, 4) + 6.0 * std::pow(v, 5);
}
double quinticD1(double v)
{
    return 30.0 * std::pow(v, 2) - 60.0 * std::pow(v, 3) + 30.0 * std::pow(v, 4);
}
double quinticD2(double v)
{
    return 60.0 * v - 180.0 * std::pow(v, 2) + 120.0 * std::pow(v, 3);
}

// Three joints, four waypoints; the segments' largest displacements are 1.2, 0.3 and 0.75 rad.
std::vector<Eigen::VectorXd> threeJointWaypoints()
{
    return {Eigen::Vector3d(0.1, -0.2, 0.5), Eigen::Vector3d(1.3, 0.4, 0.0),
            Eigen::Vector3d(1.1, 0.4, -0.3), Eigen::Vector3d(0.35, 0.0, 0.2)};
}

// A smooth recorded motion over [0, D] with zero velocity at both ends (as the clamped spline
// assumes): q1 = 0.5 (1 - cos(pi t / D)), q2 = 0.1 + 0.2 (1 - cos(3 pi t / D)).
constexpr double D = 2.0;
Eigen::Vector2d smoothQ(double t)
{
    const double w = M_PI / D;
    return {0.5 * (1.0 - std::cos(w * t)), 0.1 + 0.2 * (1.0 - std::cos(3.0 * w * t))};
}
Eigen::Vector2d smoothQd(double t)
{
    const double w = M_PI / D;
    return {0.5 * w * std::sin(w * t), 0.6 * w * std::sin(3.0 * w * t)};
}
Eigen::Vector2d smoothQdd(double t)
{
    const double w = M_PI / D;
    return {0.5 * w * w * std::cos(w * t), 1.8 * w * w * std::cos(3.0 * w * t)};
}

// N samples of smoothQ at unevenly spaced times t = D (x - 0.05 sin(2 pi x)), x = k / (N - 1),
// offset by 3 s (a recording need not start at 0).
void smoothSamples(int count, Eigen::VectorXd &t, Eigen::MatrixXd &q)
{
    t.resize(count);
    q.resize(2, count);
    for (int k = 0; k < count; ++k) {
        const double x = double(k) / (count - 1);
        const double local = D * (x - 0.05 * std::sin(2.0 * M_PI * x));
        t[k] = 3.0 + local;
        q.col(k) = smoothQ(local);
    }
}

struct State
{
    Eigen::VectorXd q, d1, d2;
};

State stateOf(const JointPath &path, double u)
{
    State s{Eigen::VectorXd(path.dof()), Eigen::VectorXd(path.dof()), Eigen::VectorXd(path.dof())};
    path.stateInto(u, s.q, s.d1, s.d2);
    return s;
}

// Central differences of q and dq/du over [0.01, 0.99], skipping points within 2 steps of the
// given knots (where q''' jumps); returns the largest errors of dq/du and d2q/du2.
Eigen::Vector2d centralDifferenceErrors(const JointPath &path, const std::vector<double> &knots)
{
    const double h = 1e-6;
    Eigen::Vector2d worst = Eigen::Vector2d::Zero();
    for (double u = 0.01; u < 0.99; u += 0.00731) {
        const bool nearKnot = std::any_of(knots.begin(), knots.end(),
                                          [&](double k) { return std::abs(u - k) < 2.0 * h; });
        if (nearKnot)
            continue;
        const State s = stateOf(path, u), lo = stateOf(path, u - h), hi = stateOf(path, u + h);
        worst[0] = std::max(worst[0], ((hi.q - lo.q) / (2 * h) - s.d1).cwiseAbs().maxCoeff());
        worst[1] = std::max(worst[1], ((hi.d1 - lo.d1) / (2 * h) - s.d2).cwiseAbs().maxCoeff());
    }
    return worst;
}

using test::errorOf;

} // namespace

class TestJointPath : public QObject
{
    Q_OBJECT

private slots:
    void waypointPath_reachesEachWaypointExactlyAtRest();
    void waypointPath_insideSegment_equalsIndependentQuintic();
    void waypointPath_derivatives_equalCentralDifferences();
    void waypointPath_sqrtShares_giveEveryLongestJointTheSamePeakAcceleration();
    void waypointPath_badInputs_throwNamingWaypointAndJoint();
    void sampledPath_interpolatesSamplesAndApproximatesDerivatives();
    void sampledPath_isClampedC2RestsOutsideAndMatchesCentralDifferences();
    void sampledPath_tenThousandSamples_interpolate();
    void sampledPath_badInputs_throwNamingSampleAndJoint();
    void jointPathStateInto_scalesDerivativesByDuration();
    void planJointPath_sampleCount_asPlanLine();
    void planJointPath_samplesFollowPathAndRestAtItsEnds();
    void planJointPath_invalidTiming_throws();
};

// The boundaries are the cumulative sqrt shares, computed here from the waypoints.
void TestJointPath::waypointPath_reachesEachWaypointExactlyAtRest()
{
    const std::vector<Eigen::VectorXd> w = threeJointWaypoints();
    const WaypointPath path(w);
    QCOMPARE(path.dof(), 3);
    const double roots[] = {std::sqrt(1.2), std::sqrt(0.3), std::sqrt(0.75)};
    const double sum = roots[0] + roots[1] + roots[2];
    const double expected[] = {0.0, roots[0] / sum, (roots[0] + roots[1]) / sum, 1.0};
    QCOMPARE(int(path.waypointTimes().size()), 4);
    for (std::size_t i = 0; i < 4; ++i) {
        LEARNID_COMPARE_NEAR(path.waypointTimes()[i], expected[i], 1e-15);
        const State s = stateOf(path, path.waypointTimes()[i]);
        QVERIFY2(s.q == w[i], qPrintable(QString::number(i)));
        QCOMPARE(s.d1.cwiseAbs().maxCoeff(), 0.0);
        QCOMPARE(s.d2.cwiseAbs().maxCoeff(), 0.0);
    }
    for (double u : {-0.5, 1.5}) { // outside: at rest at the ends
        const State s = stateOf(path, u);
        QVERIFY(s.q == (u < 0 ? w.front() : w.back()));
        QCOMPARE(s.d1.cwiseAbs().maxCoeff() + s.d2.cwiseAbs().maxCoeff(), 0.0);
    }
}

void TestJointPath::waypointPath_insideSegment_equalsIndependentQuintic()
{
    const std::vector<Eigen::VectorXd> w = threeJointWaypoints();
    const WaypointPath path(w);
    const std::vector<double> &b = path.waypointTimes();
    for (std::size_t i = 0; i + 1 < w.size(); ++i) {
        const double width = b[i + 1] - b[i];
        const Eigen::VectorXd delta = w[i + 1] - w[i];
        for (double v : {0.013, 0.25, 0.5, 0.6, 0.9, 0.999}) {
            const State s = stateOf(path, b[i] + v * width);
            LEARNID_COMPARE_MATRIX(s.q, w[i] + quintic(v) * delta, 1e-14);
            LEARNID_COMPARE_MATRIX(s.d1, quinticD1(v) / width * delta, 1e-12);
            LEARNID_COMPARE_MATRIX(s.d2, quinticD2(v) / (width * width) * delta, 1e-10);
        }
    }
}

// Step 1e-6 in u: truncation h^2/6 |q'''| <= 1e-12/6 * 60 * 1.2 / 0.36^3 ~ 3e-10; rounding
// ~1e-16 / 1e-6 = 1e-10 for dq/du, ~1e-16 * 30 / 1e-6 = 3e-9 for d2q/du2.
void TestJointPath::waypointPath_derivatives_equalCentralDifferences()
{
    const WaypointPath path(threeJointWaypoints());
    const Eigen::Vector2d err = centralDifferenceErrors(path, path.waypointTimes());
    QVERIFY2(err[0] < 1e-8 && err[1] < 1e-7,
             qPrintable(QStringLiteral("%1 %2").arg(err[0]).arg(err[1])));
}

// The header's claim: peak |d2q/du2| of each segment's largest joint is 10/sqrt(3) S^2,
// S = sum sqrt(d_i), reached at v = (3 - sqrt(3)) / 6.
void TestJointPath::waypointPath_sqrtShares_giveEveryLongestJointTheSamePeakAcceleration()
{
    const WaypointPath path(threeJointWaypoints());
    const double sum = std::sqrt(1.2) + std::sqrt(0.3) + std::sqrt(0.75);
    const double vPeak = (3.0 - std::sqrt(3.0)) / 6.0;
    const std::vector<double> &b = path.waypointTimes();
    for (std::size_t i = 0; i + 1 < b.size(); ++i) {
        const State s = stateOf(path, b[i] + vPeak * (b[i + 1] - b[i]));
        LEARNID_COMPARE_NEAR(s.d2.cwiseAbs().maxCoeff(), 10.0 / std::sqrt(3.0) * sum * sum, 1e-9);
    }
}

void TestJointPath::waypointPath_badInputs_throwNamingWaypointAndJoint()
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto messageOf = [](std::vector<Eigen::VectorXd> w) {
        return errorOf([&] { WaypointPath path(std::move(w)); });
    };
    const Eigen::VectorXd a = Eigen::Vector2d(0.1, 0.2), b = Eigen::Vector2d(0.5, -0.3);
    const Eigen::VectorXd c3 = Eigen::Vector3d(1, 2, 3), bad = Eigen::Vector2d(0.3, nan);
    const Eigen::VectorXd inf = Eigen::Vector2d(INFINITY, 0.0);
    QVERIFY(messageOf({a}).contains(QStringLiteral("1 waypoints; a path needs at least 2")));
    QVERIFY(messageOf({}).contains(QStringLiteral("0 waypoints")));
    QVERIFY(messageOf({a, b, c3})
                .contains(QStringLiteral("waypoint 2 has 3 joints, waypoint 0 has 2")));
    QVERIFY(
        messageOf({Eigen::VectorXd(), Eigen::VectorXd()}).contains(QStringLiteral("no joints")));
    QVERIFY(messageOf({a, bad, b}).contains(QStringLiteral("waypoint 1: joint 2 is nan")));
    QVERIFY(messageOf({a, b, inf}).contains(QStringLiteral("waypoint 2: joint 1 is inf")));
    QVERIFY(messageOf({a, b, b, a}).contains(QStringLiteral("waypoints 1 and 2 are equal")));
    QVERIFY(messageOf({a, a}).contains(QStringLiteral("waypoints 0 and 1 are equal")));
}

// Clamped cubic spline error bounds (Hall and Meyer 1976) for f with f'(ends) = 0 as here:
// |f - s| <= 5/384 h^4 |f''''|, |f' - s'| <= 1/24 h^3 |f''''|, |f'' - s''| <= 3/8 h^2 |f''''|.
// h <= D / 200 * (1 + 0.1 pi) = 0.0131 s, |f''''| <= 0.2 (3 pi / 2)^4 = 98.6 rad/s^4:
// 3.8e-8 rad, 9.2e-6 rad/s, 6.3e-3 rad/s^2 (measured 6e-9, 1.5e-6, 1.2e-3).
void TestJointPath::sampledPath_interpolatesSamplesAndApproximatesDerivatives()
{
    Eigen::VectorXd t;
    Eigen::MatrixXd q;
    smoothSamples(201, t, q);
    const SampledPath path(t, q);
    QCOMPARE(path.dof(), 2);
    QCOMPARE(path.samples(), 201);
    LEARNID_COMPARE_NEAR(path.nominalDuration(), D, 1e-15);
    for (int k = 0; k < t.size(); ++k) {
        const State s = stateOf(path, (t[k] - t[0]) / (t[t.size() - 1] - t[0]));
        LEARNID_COMPARE_MATRIX(s.q, q.col(k), 1e-15);
    }
    Eigen::Vector2d qv, qd, qdd;
    Eigen::Vector3d worst = Eigen::Vector3d::Zero();
    for (double local = 0.0; local <= D; local += 0.0017) {
        jointPathStateInto(path, path.nominalDuration(), local, qv, qd, qdd);
        worst[0] = std::max(worst[0], (qv - smoothQ(local)).cwiseAbs().maxCoeff());
        worst[1] = std::max(worst[1], (qd - smoothQd(local)).cwiseAbs().maxCoeff());
        worst[2] = std::max(worst[2], (qdd - smoothQdd(local)).cwiseAbs().maxCoeff());
    }
    const QString text = QStringLiteral("%1 %2 %3").arg(worst[0]).arg(worst[1]).arg(worst[2]);
    QVERIFY2(worst[0] < 3.8e-8 && worst[1] < 9.2e-6 && worst[2] < 6.3e-3, qPrintable(text));
}

void TestJointPath::sampledPath_isClampedC2RestsOutsideAndMatchesCentralDifferences()
{
    Eigen::VectorXd t;
    Eigen::MatrixXd q;
    smoothSamples(40, t, q);
    const SampledPath path(t, q);
    LEARNID_COMPARE_NEAR(stateOf(path, 0.0).d1.cwiseAbs().maxCoeff(), 0.0, 1e-12);
    LEARNID_COMPARE_NEAR(stateOf(path, 1.0).d1.cwiseAbs().maxCoeff(), 0.0, 1e-12);
    // q, q' and q'' continuous across every inner knot.
    for (int k = 1; k + 1 < t.size(); ++k) {
        const double u = (t[k] - t[0]) / D;
        const State lo = stateOf(path, std::nextafter(u, 0.0)), hi = stateOf(path, u);
        LEARNID_COMPARE_MATRIX(lo.q, hi.q, 1e-13);
        LEARNID_COMPARE_MATRIX(lo.d1, hi.d1, 1e-12);
        LEARNID_COMPARE_MATRIX(lo.d2, hi.d2, 1e-10);
    }
    for (double u : {-0.1, 1.1}) {
        const State s = stateOf(path, u);
        QVERIFY(s.q == q.col(u < 0 ? 0 : q.cols() - 1));
        QCOMPARE(s.d1.cwiseAbs().maxCoeff() + s.d2.cwiseAbs().maxCoeff(), 0.0);
    }
    std::vector<double> knots;
    for (int k = 0; k < t.size(); ++k)
        knots.push_back((t[k] - t[0]) / D);
    const Eigen::Vector2d err = centralDifferenceErrors(path, knots);
    QVERIFY2(err[0] < 1e-8 && err[1] < 1e-7,
             qPrintable(QStringLiteral("%1 %2").arg(err[0]).arg(err[1])));
}

// A long recording (a dense solve would take minutes; the tridiagonal one milliseconds).
void TestJointPath::sampledPath_tenThousandSamples_interpolate()
{
    Eigen::VectorXd t;
    Eigen::MatrixXd q;
    smoothSamples(10000, t, q);
    const SampledPath path(t, q);
    Eigen::Vector2d qv, qd, qdd;
    jointPathStateInto(path, D, 0.77, qv, qd, qdd);
    LEARNID_COMPARE_MATRIX(qv, smoothQ(0.77), 1e-12);
    LEARNID_COMPARE_MATRIX(qd, smoothQd(0.77), 1e-8);
}

void TestJointPath::sampledPath_badInputs_throwNamingSampleAndJoint()
{
    Eigen::VectorXd t;
    Eigen::MatrixXd q;
    smoothSamples(6, t, q);
    auto messageOf = [](const Eigen::VectorXd &times, const Eigen::MatrixXd &angles) {
        return errorOf([&] { SampledPath path(times, angles); });
    };
    QCOMPARE(messageOf(t, q), QStringLiteral("<no error>"));
    QVERIFY(messageOf(t.head(5), q).contains(QStringLiteral("5 sample times but 6 samples")));
    QVERIFY(messageOf(t.head(3), q.leftCols(3))
                .contains(QStringLiteral("3 samples; a path needs at least 4")));
    QVERIFY(messageOf(t, Eigen::MatrixXd(0, 6)).contains(QStringLiteral("no joints")));
    Eigen::VectorXd t2 = t;
    t2[3] = t2[2];
    QVERIFY(messageOf(t2, q).contains(QStringLiteral("sample 3: the time 3")));
    QVERIFY(messageOf(t2, q).contains(QStringLiteral("does not increase from sample 2")));
    t2 = t;
    t2[4] = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(messageOf(t2, q).contains(QStringLiteral("sample 4: the time is nan")));
    Eigen::MatrixXd q2 = q;
    q2(1, 5) = -INFINITY;
    QVERIFY(messageOf(t, q2).contains(QStringLiteral("sample 5: joint 2 is -inf")));
}

void TestJointPath::jointPathStateInto_scalesDerivativesByDuration()
{
    const WaypointPath path(threeJointWaypoints());
    const double T = 1.7;
    Eigen::Vector3d q, qd, qdd;
    for (double t : {-0.2, 0.0, 0.3, 1.1, 1.7, 2.0}) {
        jointPathStateInto(path, T, t, q, qd, qdd);
        const State s = stateOf(path, t / T);
        LEARNID_COMPARE_MATRIX(q, s.q, 0.0);
        LEARNID_COMPARE_MATRIX(qd, s.d1 / T, 1e-15);
        LEARNID_COMPARE_MATRIX(qdd, s.d2 / (T * T), 1e-14);
    }
    Eigen::Vector2d wrong;
    QVERIFY_THROWS_EXCEPTION(Error, jointPathStateInto(path, T, 0.1, wrong, qd, qdd));
    QVERIFY_THROWS_EXCEPTION(Error, jointPathStateInto(path, 0.0, 0.1, q, qd, qdd));
    QVERIFY_THROWS_EXCEPTION(Error, jointPathStateInto(path, T, NAN, q, qd, qdd));
}

void TestJointPath::planJointPath_sampleCount_asPlanLine()
{
    // Both sample through sampleMotion; its count rule is tst_cartesianline's data-driven test.
    const MotionTiming timing{4.93, 0.1, 0.5, 0.002};
    const JointTrajectory traj = planJointPath(WaypointPath(threeJointWaypoints()), timing);
    QCOMPARE(traj.samples(), 2766);
    QCOMPARE(traj.samples(),
             planLine(TwoLinkKinematics(0.75, 0.75), CartesianLine(), timing).samples());
    QCOMPARE(traj.dof(), 3);
    QCOMPARE(traj.samplePeriod, 0.002);
    QCOMPARE(int(traj.qd.cols()), traj.samples());
    QCOMPARE(int(traj.qdd.cols()), traj.samples());
}

void TestJointPath::planJointPath_samplesFollowPathAndRestAtItsEnds()
{
    const std::vector<Eigen::VectorXd> w = threeJointWaypoints();
    const WaypointPath path(w);
    // At the sample instants, and at the middle of each sample (the mid-sample feedforward's).
    for (const double offset : {0.0, 0.001}) {
        const MotionTiming timing{2.0, 0.1, 0.5, 0.002, offset};
        const JointTrajectory traj = planJointPath(path, timing);
        QCOMPARE(traj.samples(), 1301);
        Eigen::Vector3d q, qd, qdd;
        int before = 0, after = 0;
        for (int k = 0; k < traj.samples(); ++k) {
            const double t = k * timing.samplePeriod + offset - timing.restBefore;
            if (t > 0.0 && t < timing.motionDuration) {
                jointPathStateInto(path, timing.motionDuration, t, q, qd, qdd);
                QVERIFY(traj.q.col(k) == q && traj.qd.col(k) == qd && traj.qdd.col(k) == qdd);
                continue;
            }
            if (t <= -1e-9)
                ++before;
            else if (t >= timing.motionDuration + 1e-9)
                ++after;
            QVERIFY2(traj.q.col(k) == (t <= 0.0 ? w.front() : w.back()),
                     qPrintable(QString::number(k)));
            QCOMPARE(traj.qd.col(k).cwiseAbs().maxCoeff() + traj.qdd.col(k).cwiseAbs().maxCoeff(),
                     0.0);
        }
        QCOMPARE(before, 50);
        QCOMPARE(after, offset == 0.0 ? 250 : 251); // at the offset, the motion's end is a rest
    }
}

void TestJointPath::planJointPath_invalidTiming_throws()
{
    const WaypointPath path(threeJointWaypoints());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const MotionTiming bad[] = {
        {1.0, 0.1, 0.5, 0.0},
        {1.0, 0.1, 0.5, -0.002},
        {0.0, 0.1, 0.5, 0.002},
        {-1.0, 0.1, 0.5, 0.002},
        {1.0, -0.1, 0.5, 0.002},
        {1.0, 0.1, -0.5, 0.002},
        {nan, 0.1, 0.5, 0.002},
        {1.0, 0.1, 0.5, nan},
        // the sample offset outside [0, Ts)
        {1.0, 0.1, 0.5, 0.002, 0.002},
        {1.0, 0.1, 0.5, 0.002, -1e-4},
        {1.0, 0.1, 0.5, 0.002, nan},
    };
    for (const MotionTiming &timing : bad)
        QVERIFY_THROWS_EXCEPTION(Error, planJointPath(path, timing));
}

QTEST_GUILESS_MAIN(TestJointPath)
#include "tst_jointpath.moc"
