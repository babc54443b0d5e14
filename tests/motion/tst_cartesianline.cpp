#include "../support/NumericAssert.h"
#include "model/Error.h"
#include "motion/CartesianLine.h"
#include "motion/TwoLinkKinematics.h"

#include <Eigen/LU>

#include <QTest>
#include <algorithm>
#include <cmath>
#include <limits>

using namespace learnid;

namespace {

// The quintic time scaling, written out independently of the production code.
double quintic(double u)
{
    u = std::clamp(u, 0.0, 1.0);
    return 10.0 * std::pow(u, 3) - 15.0 * std::pow(u, 4) + 6.0 * std::pow(u, 5);
}

// docs/design.md §2: the paper's arm and line.
const TwoLinkKinematics paperArm(0.75, 0.75);

} // namespace

class TestCartesianLine : public QObject
{
    Q_OBJECT

private slots:
    void paperLine_endsAtPaperPoint();
    void plannedSamples_lieOnLineAtQuinticProgress();
    void plannedVelocityAndAcceleration_equalCentralDifferences();
    void rests_haveZeroVelocityAndAccelerationAndHoldPosition();
    void sampleCount_isFloorOfTotalOverPeriodPlusOne_data();
    void sampleCount_isFloorOfTotalOverPeriodPlusOne();
    void lineStateAt_endsAtRestOnTheEndPoints();
    void lineStateAt_velocityMapsToCartesianVelocity();
    void invalidTiming_throws();
    void lineLeavingWorkspace_throws();
};

void TestCartesianLine::paperLine_endsAtPaperPoint()
{
    const CartesianLine line; // defaults are the paper scenario
    const Eigen::Vector2d expected(0.5 - 0.5 / std::sqrt(2.0), 0.5 + 0.5 / std::sqrt(2.0));
    LEARNID_COMPARE_MATRIX(line.end(), expected, 1e-15);
    LEARNID_COMPARE_NEAR(line.end().x(), 0.1464, 5e-5);
    LEARNID_COMPARE_NEAR(line.end().y(), 0.8536, 5e-5);
    LEARNID_COMPARE_NEAR(line.direction().norm(), 1.0, 1e-15);
    LEARNID_COMPARE_NEAR((line.end() - line.start).norm(), line.length, 1e-15);
}

// Forward kinematics of every sample is start + s(u) L dir, u = (t_k - restBefore) / T.
void TestCartesianLine::plannedSamples_lieOnLineAtQuinticProgress()
{
    const CartesianLine line;
    MotionTiming timing;
    timing.motionDuration = 1.3;
    const JointTrajectory traj = planLine(paperArm, line, timing);
    QCOMPARE(traj.dof(), 2);
    QCOMPARE(traj.samplePeriod, timing.samplePeriod);
    for (int k = 0; k < traj.samples(); ++k) {
        const double t = k * timing.samplePeriod;
        const double u = (t - timing.restBefore) / timing.motionDuration;
        const Eigen::Vector2d expected = line.start + quintic(u) * line.length * line.direction();
        LEARNID_COMPARE_MATRIX(paperArm.forward(traj.q.col(k)), expected, 1e-12);
    }
    LEARNID_COMPARE_MATRIX(paperArm.forward(traj.q.col(traj.samples() - 1)), line.end(), 1e-12);
    // One elbow branch, no 2 pi jumps: neighbouring samples are close.
    const double maxStep =
        (traj.q.rightCols(traj.samples() - 1) - traj.q.leftCols(traj.samples() - 1))
            .cwiseAbs()
            .maxCoeff();
    QVERIFY2(maxStep < 0.01, qPrintable(QString::number(maxStep)));
}

// Dense sampling (Ts = 0.1 ms, T = 0.6 s). Inside the motion and the rests, central differences
// err by Ts^2/6 |q'''| <= 1e-8/6 * 200 rad/s^3 ~ 3e-7 rad/s for qd, and Ts^2/6 |q''''| ~ 3e-6
// rad/s^2 for qdd (measured values; tolerances 3x). Where the motion starts and stops the jerk
// jumps by q''' = J^-1 s'''(0) L dir, s'''(0) = s'''(1) = 60 / T^3 (qd = qdd = 0 there, so the
// Jdot terms vanish): the central difference of qd at those two samples is off by exactly
// +-Ts/4 q''' to O(Ts^2), which the test predicts instead of excluding those samples.
void TestCartesianLine::plannedVelocityAndAcceleration_equalCentralDifferences()
{
    const CartesianLine line;
    MotionTiming timing;
    timing.motionDuration = 0.6;
    timing.samplePeriod = 1e-4;
    const JointTrajectory traj = planLine(paperArm, line, timing);
    const double ts = timing.samplePeriod;
    const int n = traj.samples();
    const int startSample = int(std::lround(timing.restBefore / ts));
    const int stopSample = int(std::lround((timing.restBefore + timing.motionDuration) / ts));
    QVERIFY(traj.qd.cwiseAbs().maxCoeff() > 1.0 && traj.qdd.cwiseAbs().maxCoeff() > 10.0);

    const double s3 = 60.0 / std::pow(timing.motionDuration, 3);
    auto jerkJump = [&](int k) {
        const Eigen::MatrixXd j = paperArm.jacobian(traj.q.col(k));
        return Eigen::Vector2d(j.partialPivLu().solve(s3 * line.length * line.direction()));
    };
    for (int k = 1; k < n - 1; ++k) {
        const Eigen::Vector2d qdNumeric = (traj.q.col(k + 1) - traj.q.col(k - 1)) / (2.0 * ts);
        LEARNID_COMPARE_MATRIX(traj.qd.col(k), qdNumeric, 1e-6);
        Eigen::Vector2d qddNumeric = (traj.qd.col(k + 1) - traj.qd.col(k - 1)) / (2.0 * ts);
        if (k == startSample)
            qddNumeric -= ts / 4.0 * jerkJump(k);
        else if (k == stopSample)
            qddNumeric += ts / 4.0 * jerkJump(k);
        LEARNID_COMPARE_MATRIX(traj.qdd.col(k), qddNumeric, 1e-5);
    }
}

void TestCartesianLine::rests_haveZeroVelocityAndAccelerationAndHoldPosition()
{
    const CartesianLine line;
    MotionTiming timing;
    timing.motionDuration = 2.0;
    timing.restBefore = 0.1;
    timing.restAfter = 0.5;
    const JointTrajectory traj = planLine(paperArm, line, timing);
    const Eigen::VectorXd qStart = paperArm.inverse(line.start, Eigen::VectorXd());
    const Eigen::VectorXd qEnd = traj.q.col(traj.samples() - 1);
    LEARNID_COMPARE_MATRIX(paperArm.forward(qEnd), line.end(), 1e-12);
    int before = 0, after = 0;
    for (int k = 0; k < traj.samples(); ++k) {
        const double t = k * timing.samplePeriod;
        const bool inRestBefore = t <= timing.restBefore - 1e-9;
        const bool inRestAfter = t >= timing.restBefore + timing.motionDuration + 1e-9;
        if (!inRestBefore && !inRestAfter)
            continue;
        (inRestBefore ? before : after)++;
        QCOMPARE(traj.qd.col(k).cwiseAbs().maxCoeff(), 0.0);
        QCOMPARE(traj.qdd.col(k).cwiseAbs().maxCoeff(), 0.0);
        LEARNID_COMPARE_MATRIX(traj.q.col(k), inRestBefore ? qStart : qEnd, 1e-14);
    }
    QCOMPARE(before, 50);
    QCOMPARE(after, 250);
}

void TestCartesianLine::sampleCount_isFloorOfTotalOverPeriodPlusOne_data()
{
    QTest::addColumn<double>("duration");
    QTest::addColumn<double>("restBefore");
    QTest::addColumn<double>("restAfter");
    QTest::addColumn<double>("period");
    QTest::addColumn<int>("samples");
    // 1.6 / 0.002 = 799.99999999999989 in doubles: the exact multiple must still count.
    QTest::newRow("paper timing, exact multiple") << 1.0 << 0.1 << 0.5 << 0.002 << 801;
    QTest::newRow("T = 4.93 s") << 4.93 << 0.1 << 0.5 << 0.002 << 2766;
    QTest::newRow("not a multiple") << 1.0 << 0.1 << 0.5 << 0.003 << 534;
    QTest::newRow("no rests") << 0.5 << 0.0 << 0.0 << 0.002 << 251;
    QTest::newRow("period longer than total") << 0.01 << 0.0 << 0.0 << 0.02 << 1;
}

void TestCartesianLine::sampleCount_isFloorOfTotalOverPeriodPlusOne()
{
    QFETCH(double, duration);
    QFETCH(double, restBefore);
    QFETCH(double, restAfter);
    QFETCH(double, period);
    QFETCH(int, samples);
    MotionTiming timing{duration, restBefore, restAfter, period};
    const JointTrajectory traj = planLine(paperArm, CartesianLine(), timing);
    QCOMPARE(traj.samples(), samples);
    QCOMPARE(int(traj.qd.cols()), samples);
    QCOMPARE(int(traj.qdd.cols()), samples);
    QVERIFY(traj.duration() <= duration + restBefore + restAfter + 1e-9);
    QVERIFY(traj.duration() + period > duration + restBefore + restAfter + 1e-9);
}

void TestCartesianLine::lineStateAt_endsAtRestOnTheEndPoints()
{
    const CartesianLine line;
    const double T = 0.8;
    for (double t : {-0.3, 0.0}) {
        const JointState s = lineStateAt(paperArm, line, T, t, Eigen::VectorXd());
        LEARNID_COMPARE_MATRIX(paperArm.forward(s.q), line.start, 1e-12);
        LEARNID_COMPARE_MATRIX(s.qd, Eigen::Vector2d::Zero(), 1e-12);
        LEARNID_COMPARE_MATRIX(s.qdd, Eigen::Vector2d::Zero(), 1e-12);
    }
    for (double t : {T, T + 0.3}) {
        const JointState s = lineStateAt(paperArm, line, T, t, Eigen::VectorXd());
        LEARNID_COMPARE_MATRIX(paperArm.forward(s.q), line.end(), 1e-12);
        LEARNID_COMPARE_MATRIX(s.qd, Eigen::Vector2d::Zero(), 1e-12);
        LEARNID_COMPARE_MATRIX(s.qdd, Eigen::Vector2d::Zero(), 1e-12);
    }
}

// J qd = s'(t) L dir and J qdd + Jdot qd = s''(t) L dir, with s', s'' the analytic derivatives
// of the quintic (30 u^2 (1-u)^2 / T and 60 u (1 - 3u + 2u^2) / T^2).
void TestCartesianLine::lineStateAt_velocityMapsToCartesianVelocity()
{
    const CartesianLine line;
    const double T = 0.8;
    for (double t = 0.01; t < T; t += 0.0537) {
        const double u = t / T;
        const double sd = 30.0 * u * u * (1.0 - u) * (1.0 - u) / T;
        const double sdd = (60.0 * u - 180.0 * u * u + 120.0 * u * u * u) / (T * T);
        const JointState s = lineStateAt(paperArm, line, T, t, Eigen::VectorXd());
        const Eigen::MatrixXd j = paperArm.jacobian(s.q);
        LEARNID_COMPARE_MATRIX(j * s.qd, sd * line.length * line.direction(), 1e-12);
        LEARNID_COMPARE_MATRIX(j * s.qdd + paperArm.jacobianDotTimesQd(s.q, s.qd),
                               sdd * line.length * line.direction(), 1e-11);
    }
}

void TestCartesianLine::invalidTiming_throws()
{
    const CartesianLine line;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const MotionTiming bad[] = {
        {1.0, 0.1, 0.5, 0.0},    {1.0, 0.1, 0.5, -0.002}, {0.0, 0.1, 0.5, 0.002},
        {-1.0, 0.1, 0.5, 0.002}, {1.0, -0.1, 0.5, 0.002}, {1.0, 0.1, -0.5, 0.002},
        {nan, 0.1, 0.5, 0.002},  {1.0, 0.1, 0.5, nan},
    };
    for (const MotionTiming &timing : bad)
        QVERIFY_THROWS_EXCEPTION(Error, planLine(paperArm, line, timing));
}

void TestCartesianLine::lineLeavingWorkspace_throws()
{
    CartesianLine line;
    line.length = 2.0; // from (0.5, 0.5) at 135 deg: leaves the 1.5 m reach
    QVERIFY_THROWS_EXCEPTION(Error, planLine(paperArm, line, MotionTiming()));
}

QTEST_GUILESS_MAIN(TestCartesianLine)
#include "tst_cartesianline.moc"
