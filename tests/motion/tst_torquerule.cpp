#include "../support/ErrorOf.h"
#include "../support/NumericAssert.h"
#include "model/Error.h"
#include "model/TwoLinkArm.h"
#include "motion/JointPath.h"
#include "motion/TorqueRule.h"
#include "motion/TwoLinkKinematics.h"

#include <QTest>
#include <cmath>

using namespace learnid;

namespace {

// The paper arm in a vertical plane: phi = [a, b, c, g1, g2], g1 and g2 the gravity moments of
// the links [N m], potential V = g1 sin q1 + g2 sin q2 (absolute angles), so the gravity torque
// dV/dq = [g1 cos q1, g2 cos q2] is configuration dependent and independent of the speed.
class VerticalTwoLinkArm final : public RobotModel
{
public:
    QString id() const override { return QStringLiteral("test-vertical-2link"); }
    int dof() const override { return 2; }
    int parameterCount() const override { return 5; }
    QList<ParameterInfo> parameters() const override
    {
        QList<ParameterInfo> p = m_arm.parameters();
        p.append({QStringLiteral("g1"), QStringLiteral("N m"), QString(), QString()});
        p.append({QStringLiteral("g2"), QStringLiteral("N m"), QString(), QString()});
        return p;
    }
    void regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                   Eigen::Ref<Eigen::MatrixXd> out) const override
    {
        m_arm.regressor(q, qd, qdd, out.leftCols(3));
        out(0, 3) = std::cos(q[0]);
        out(0, 4) = 0.0;
        out(1, 3) = 0.0;
        out(1, 4) = std::cos(q[1]);
    }
    void massMatrix(const VectorRef &q, const VectorRef &phi,
                    Eigen::Ref<Eigen::MatrixXd> out) const override
    {
        m_arm.massMatrix(q, phi.head(3), out);
    }
    void biasTorque(const VectorRef &q, const VectorRef &qd, const VectorRef &phi,
                    Eigen::Ref<Eigen::VectorXd> out) const override
    {
        m_arm.biasTorque(q, qd, phi.head(3), out);
        out[0] += phi[3] * std::cos(q[0]);
        out[1] += phi[4] * std::cos(q[1]);
    }

private:
    TwoLinkArm m_arm;
};

// docs/design.md §2.
const TwoLinkKinematics paperArm(0.75, 0.75);
const Eigen::Vector3d phiInitial(40.0, 20.0, 30.0);
const Eigen::Vector3d phiTrue(20.0, 5.0, 8.0);
const Eigen::Vector2d torqueLimit(8.0, 4.0);
constexpr double fraction = 0.8;

// Independent of the rule's A/T^2 + g split and its grid: plan the motion of duration T densely
// with planLine (no rests) and take the peak |tau_j| of the model's inverse dynamics.
Eigen::VectorXd densePeakTorque(const RobotModel &model, const Eigen::VectorXd &phi, double T)
{
    MotionTiming timing;
    timing.motionDuration = T;
    timing.restBefore = 0.0;
    timing.restAfter = 0.0;
    timing.samplePeriod = T / 4000.0;
    const JointTrajectory traj = planLine(paperArm, CartesianLine(), timing);
    Eigen::VectorXd peak = Eigen::VectorXd::Zero(model.dof());
    Eigen::VectorXd tau(model.dof());
    for (int k = 0; k < traj.samples(); ++k) {
        model.inverseDynamics(traj.q.col(k), traj.qd.col(k), traj.qdd.col(k), phi, tau);
        peak = peak.cwiseMax(tau.cwiseAbs());
    }
    return peak;
}

Eigen::VectorXd verticalPhi(const Eigen::Vector3d &inertia, double g1, double g2)
{
    Eigen::VectorXd phi(5);
    phi << inertia, g1, g2;
    return phi;
}

} // namespace

class TestTorqueRule : public QObject
{
    Q_OBJECT

private slots:
    void paperScenario_initialEstimate_gives493Seconds();
    void paperScenario_trueParameters_giveAbout356Seconds();
    void duration_putsDensePeakOfLimitingJointAtFractionOfLimit_data();
    void duration_putsDensePeakOfLimitingJointAtFractionOfLimit();
    void withoutGravity_durationScalesAsInverseSquareRootOfTorque();
    void gravity_bisectionPutsDensePeakAtLimit();
    void negligibleGravity_bisectionAgreesWithClosedForm();
    void gravityAboveLimit_throws();
    void invalidArguments_throw();
    void zeroLengthLine_throws();
    void torqueRuleGrid_ofJointPath_equalsDirectRegressor();
    void torqueRuleGrid_ofSampledLine_approximatesLineGrid();
    void shortestDuration_ofJointPathWithoutGravity_isClosedForm();
    void torqueRuleGrid_pathWithOtherJointCount_throws();
};

// docs/design.md §2 reference: T_0 = 4.93 s with phi_0 (two decimals quoted, hence +- 0.005 s).
void TestTorqueRule::paperScenario_initialEstimate_gives493Seconds()
{
    const TwoLinkArm arm;
    const TorqueRuleResult r =
        shortestDuration(arm, phiInitial, paperArm, CartesianLine(), torqueLimit, fraction);
    LEARNID_COMPARE_NEAR(r.duration, 4.93, 0.005);
    QCOMPARE(r.peakTorque.size(), 2);
    LEARNID_COMPARE_NEAR(r.peakTorque[r.limitingJoint], fraction * torqueLimit[r.limitingJoint],
                         1e-9);
}

void TestTorqueRule::paperScenario_trueParameters_giveAbout356Seconds()
{
    const TwoLinkArm arm;
    const TorqueRuleResult r =
        shortestDuration(arm, phiTrue, paperArm, CartesianLine(), torqueLimit, fraction);
    LEARNID_COMPARE_NEAR(r.duration, 3.56, 0.005);
}

void TestTorqueRule::duration_putsDensePeakOfLimitingJointAtFractionOfLimit_data()
{
    QTest::addColumn<Eigen::Vector3d>("phi");
    QTest::newRow("initial estimate") << phiInitial;
    QTest::newRow("truth") << phiTrue;
    QTest::newRow("light elbow") << Eigen::Vector3d(30.0, 1.0, 2.0);
}

// Peak |tau| over the dense samples vs the rule's 2001-point grid: the grid misses a smooth
// peak by ~ (du/2)^2 |tau''|/(2 |tau|) ~ 1e-6 relative, so 1e-3 is loose but catches any error
// in the 1/T^2 scaling or in the choice of joint.
void TestTorqueRule::duration_putsDensePeakOfLimitingJointAtFractionOfLimit()
{
    QFETCH(Eigen::Vector3d, phi);
    const TwoLinkArm arm;
    const TorqueRuleResult r =
        shortestDuration(arm, phi, paperArm, CartesianLine(), torqueLimit, fraction);
    const Eigen::VectorXd peak = densePeakTorque(arm, phi, r.duration);
    const Eigen::Vector2d allowed = fraction * torqueLimit;
    const int j = r.limitingJoint;
    QVERIFY(j == 0 || j == 1);
    LEARNID_COMPARE_NEAR(peak[j] / allowed[j], 1.0, 1e-3);
    QVERIFY2(peak[1 - j] <= allowed[1 - j] * (1.0 + 1e-3),
             qPrintable(QStringLiteral("joint %1 peaks at %2 N m").arg(2 - j).arg(peak[1 - j])));
    for (int i = 0; i < 2; ++i)
        LEARNID_COMPARE_NEAR(r.peakTorque[i], peak[i], 1e-3 * allowed[i]);
    // Any shorter motion breaks the rule.
    const Eigen::VectorXd faster = densePeakTorque(arm, phi, 0.99 * r.duration);
    QVERIFY(faster[j] > allowed[j]);
}

// Without gravity tau(T) = A / T^2 exactly: a quarter of the torque needs twice the time, and
// scaling all inertias by k scales T by sqrt(k).
void TestTorqueRule::withoutGravity_durationScalesAsInverseSquareRootOfTorque()
{
    const TwoLinkArm arm;
    const CartesianLine line;
    const TorqueRuleResult base =
        shortestDuration(arm, phiTrue, paperArm, line, torqueLimit, fraction);
    const TorqueRuleResult quarter =
        shortestDuration(arm, phiTrue, paperArm, line, torqueLimit, fraction / 4.0);
    LEARNID_COMPARE_NEAR(quarter.duration, 2.0 * base.duration, 1e-12 * base.duration);
    QCOMPARE(quarter.limitingJoint, base.limitingJoint);
    LEARNID_COMPARE_MATRIX(quarter.peakTorque, base.peakTorque / 4.0, 1e-12);

    const TorqueRuleResult heavy =
        shortestDuration(arm, 9.0 * phiTrue, paperArm, line, torqueLimit, fraction);
    LEARNID_COMPARE_NEAR(heavy.duration, 3.0 * base.duration, 1e-12 * base.duration);
}

void TestTorqueRule::gravity_bisectionPutsDensePeakAtLimit()
{
    const VerticalTwoLinkArm arm;
    const CartesianLine line;
    const Eigen::Vector2d allowed = fraction * torqueLimit;
    const TwoLinkArm horizontal;
    const double horizontalT =
        shortestDuration(horizontal, phiTrue, paperArm, line, torqueLimit, fraction).duration;
    // Joint 1 limits in the first two cases, joint 2 (elbow gravity near its limit) in the third.
    for (const auto &g :
         {Eigen::Vector2d(2.0, 1.0), Eigen::Vector2d(-5.0, 0.5), Eigen::Vector2d(0.0, 4.4)}) {
        const Eigen::VectorXd phi = verticalPhi(phiTrue, g[0], g[1]);
        const TorqueRuleResult r =
            shortestDuration(arm, phi, paperArm, line, torqueLimit, fraction);
        const Eigen::VectorXd peak = densePeakTorque(arm, phi, r.duration);
        const int j = r.limitingJoint;
        LEARNID_COMPARE_NEAR(peak[j] / allowed[j], 1.0, 1e-3);
        QVERIFY(peak[1 - j] <= allowed[1 - j] * (1.0 + 1e-3));
        QVERIFY(densePeakTorque(arm, phi, 0.99 * r.duration)[j] > allowed[j]);
        // Gravity here changes the answer: the test really exercises the bisection.
        QVERIFY2(std::abs(r.duration - horizontalT) > 0.5,
                 qPrintable(QStringLiteral("%1 s vs %2 s").arg(r.duration).arg(horizontalT)));
    }
}

void TestTorqueRule::negligibleGravity_bisectionAgreesWithClosedForm()
{
    const TwoLinkArm horizontal;
    const VerticalTwoLinkArm vertical;
    const CartesianLine line;
    const double closedForm =
        shortestDuration(horizontal, phiTrue, paperArm, line, torqueLimit, fraction).duration;
    const double bisected = shortestDuration(vertical, verticalPhi(phiTrue, 1e-9, 1e-9), paperArm,
                                             line, torqueLimit, fraction)
                                .duration;
    // A gravity of 1e-9 N m against a 6.4 N m peak moves T by ~ 1e-10 relative.
    LEARNID_COMPARE_NEAR(bisected, closedForm, 1e-8 * closedForm);
    // Gravity on joint 2 only, which does not limit here: the bisection finds the closed form's T.
    const TorqueRuleResult elbowOnly = shortestDuration(vertical, verticalPhi(phiTrue, 0.0, 2.0),
                                                        paperArm, line, torqueLimit, fraction);
    QCOMPARE(elbowOnly.limitingJoint, 0);
    LEARNID_COMPARE_NEAR(elbowOnly.duration, closedForm, 1e-10 * closedForm);
    // And with gravity exactly zero the vertical model takes the closed form.
    const double zero = shortestDuration(vertical, verticalPhi(phiTrue, 0.0, 0.0), paperArm, line,
                                         torqueLimit, fraction)
                            .duration;
    LEARNID_COMPARE_NEAR(zero, closedForm, 1e-14 * closedForm);
}

// Along the paper line q1 runs from -16.9 to 25.5 deg (through 0) and q2 from 106.9 to 135 deg.
// Holding the arm still then takes g1 on joint 1 (where q1 = 0) and 0.707 g2 on joint 2 (at the
// end, q2 = 135 deg): above 80 % of the limit no duration can meet the rule; just below, one can.
void TestTorqueRule::gravityAboveLimit_throws()
{
    const VerticalTwoLinkArm arm;
    const CartesianLine line;
    const Eigen::VectorXd shoulderHeavy = verticalPhi(phiTrue, 6.5, 0.0); // 6.5 > 6.4 N m
    const Eigen::VectorXd elbowHeavy = verticalPhi(phiTrue, 0.0, 4.6);    // 0.71 * 4.6 > 3.2 N m
    for (const Eigen::VectorXd &phi : {shoulderHeavy, elbowHeavy}) {
        try {
            shortestDuration(arm, phi, paperArm, line, torqueLimit, fraction);
            QFAIL("a static torque above the limit was accepted");
        } catch (const Error &e) {
            QVERIFY2(e.message().contains(QStringLiteral("80")), qPrintable(e.message()));
        }
    }
    const Eigen::VectorXd justBelow = verticalPhi(phiTrue, 6.3, 0.0);
    const TorqueRuleResult r =
        shortestDuration(arm, justBelow, paperArm, line, torqueLimit, fraction);
    QVERIFY(std::isfinite(r.duration) && r.duration > 0.0);
}

void TestTorqueRule::invalidArguments_throw()
{
    const TwoLinkArm arm;
    const CartesianLine line;
    QVERIFY_THROWS_EXCEPTION(
        Error, shortestDuration(arm, phiTrue, paperArm, line, Eigen::Vector3d(8, 4, 4), fraction));
    QVERIFY_THROWS_EXCEPTION(
        Error, shortestDuration(arm, phiTrue, paperArm, line, Eigen::Vector2d(8, 0), fraction));
    QVERIFY_THROWS_EXCEPTION(
        Error, shortestDuration(arm, phiTrue, paperArm, line, Eigen::Vector2d(8, -4), fraction));
    QVERIFY_THROWS_EXCEPTION(Error,
                             shortestDuration(arm, phiTrue, paperArm, line, torqueLimit, 0.0));
    QVERIFY_THROWS_EXCEPTION(
        Error, shortestDuration(arm, phiTrue, paperArm, line, torqueLimit, std::nan("")));
    QVERIFY_THROWS_EXCEPTION(
        Error, shortestDuration(arm, phiTrue, paperArm, line, torqueLimit, fraction, 1));
}

void TestTorqueRule::zeroLengthLine_throws()
{
    const TwoLinkArm arm;
    CartesianLine line;
    line.length = 0.0;
    QVERIFY_THROWS_EXCEPTION(Error,
                             shortestDuration(arm, phiTrue, paperArm, line, torqueLimit, fraction));
}

namespace {

const TwoLinkArm planarArm;
const std::vector<Eigen::VectorXd> armWaypoints = {
    Eigen::Vector2d(-0.3, 1.9), Eigen::Vector2d(0.4, 1.2), Eigen::Vector2d(0.9, 2.4)};

// A joint path's state at normalised time u: q, dq/du, d2q/du2.
struct PathState
{
    Eigen::VectorXd q, d1, d2;
};

PathState pathState(const JointPath &path, double u)
{
    PathState s{Eigen::VectorXd(path.dof()), Eigen::VectorXd(path.dof()),
                Eigen::VectorXd(path.dof())};
    path.stateInto(u, s.q, s.d1, s.d2);
    return s;
}

} // namespace

// Joint-space paths (JointPath.h): the rule over their grid.

void TestTorqueRule::torqueRuleGrid_ofJointPath_equalsDirectRegressor()
{
    const WaypointPath path(armWaypoints);
    const int points = 201;
    const TorqueRuleGrid grid = torqueRuleGrid(planarArm, path, points);
    QCOMPARE(grid.dof, 2);
    QCOMPARE(int(grid.inertial.rows()), 2 * points);
    QCOMPARE(int(grid.inertial.cols()), 3);
    QVERIFY(grid.inertial.cwiseAbs().maxCoeff() > 1.0);
    const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
    for (int i = 0; i < points; ++i) {
        const PathState s = pathState(path, double(i) / (points - 1));
        const Eigen::MatrixXd w = planarArm.regressorAt(s.q, s.d1, s.d2);
        const Eigen::MatrixXd w0 = planarArm.regressorAt(s.q, zero, zero);
        LEARNID_COMPARE_MATRIX(grid.gravity.middleRows(2 * i, 2), w0, 0.0);
        LEARNID_COMPARE_MATRIX(grid.inertial.middleRows(2 * i, 2), w - w0, 1e-12);
    }
}

// The paper's line planned at T = 1 and sampled at 2001 points is a SampledPath; its grid is
// the line's to the spline's error in q'' (at most 3/8 h^2 |q''''|, h = 5e-4; measured 1.3e-6
// of the peak torque, tolerance 1e-5 of it).
void TestTorqueRule::torqueRuleGrid_ofSampledLine_approximatesLineGrid()
{
    const TwoLinkKinematics kinematics(0.75, 0.75);
    const JointTrajectory line = planLine(kinematics, CartesianLine(), {1.0, 0.0, 0.0, 1.0 / 2000});
    const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(line.samples(), 0.0, 1.0);
    const SampledPath path(t, line.q);
    const Eigen::VectorXd lineTau =
        torqueRuleGrid(planarArm, kinematics, CartesianLine()).inertial * phiTrue;
    const Eigen::VectorXd pathTau = torqueRuleGrid(planarArm, path).inertial * phiTrue;
    const double peak = lineTau.cwiseAbs().maxCoeff();
    LEARNID_COMPARE_MATRIX(pathTau / peak, lineTau / peak, 1e-5);
}

// No gravity: tau(u) at T = 1 is A(u), and at T it is A(u) / T^2, so T = sqrt(max_j max_u
// |A_j| / (fraction limit_j)). A is computed here by the model's inverse dynamics.
void TestTorqueRule::shortestDuration_ofJointPathWithoutGravity_isClosedForm()
{
    const WaypointPath path(armWaypoints);
    const int points = 2001;
    Eigen::Vector2d peak = Eigen::Vector2d::Zero();
    for (int i = 0; i < points; ++i) {
        const PathState s = pathState(path, double(i) / (points - 1));
        peak = peak.cwiseMax(planarArm.torqueAt(s.q, s.d1, s.d2, phiTrue).cwiseAbs());
    }
    const Eigen::Vector2d ratio = peak.cwiseQuotient(fraction * torqueLimit);
    int limiting = 0;
    const double expectedT = std::sqrt(ratio.maxCoeff(&limiting));

    const TorqueRuleResult r =
        shortestDuration(torqueRuleGrid(planarArm, path, points), phiTrue, torqueLimit, fraction);
    LEARNID_COMPARE_NEAR(r.duration, expectedT, 1e-12 * expectedT);
    QCOMPARE(r.limitingJoint, limiting);
    LEARNID_COMPARE_MATRIX(r.peakTorque, peak / (expectedT * expectedT), 1e-12);
    LEARNID_COMPARE_NEAR(r.peakTorque[limiting], fraction * torqueLimit[limiting], 1e-12);

    // Planned densely at that T, the peak torque is the rule's to the grid's resolution (the
    // 2001-point grid misses the peak by 2e-5 N m here).
    const JointTrajectory traj = planJointPath(path, {r.duration, 0.0, 0.0, r.duration / 20000});
    Eigen::Vector2d densePeak = Eigen::Vector2d::Zero();
    for (int k = 0; k < traj.samples(); ++k) {
        densePeak = densePeak.cwiseMax(
            planarArm.torqueAt(traj.q.col(k), traj.qd.col(k), traj.qdd.col(k), phiTrue).cwiseAbs());
    }
    LEARNID_COMPARE_MATRIX(densePeak, r.peakTorque, 1e-5 * fraction * torqueLimit.maxCoeff());
}

void TestTorqueRule::torqueRuleGrid_pathWithOtherJointCount_throws()
{
    const WaypointPath path({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1)});
    const QString message = test::errorOf([&] { torqueRuleGrid(planarArm, path); });
    QVERIFY2(message.contains(QStringLiteral("the path has 3 joints, the robot model 2")),
             qPrintable(message));
    QVERIFY_THROWS_EXCEPTION(Error, torqueRuleGrid(planarArm, WaypointPath(armWaypoints), 1));
}

QTEST_GUILESS_MAIN(TestTorqueRule)
#include "tst_torquerule.moc"
