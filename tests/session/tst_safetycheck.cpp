#include "control/PidController.h"
#include "model/TwoLinkArm.h"
#include "robot/SimulatedRobot.h"
#include "session/SafetyCheck.h"
#include "session/TrialPlanner.h"

#include <Eigen/Eigenvalues>
#include <QTest>

using namespace learnid;

class TestSafetyCheck : public QObject
{
    Q_OBJECT

private slots:
    void paperGainsWithLambda200_areStableAlongThePath();
    void paperLambda40_isUnstableForTheTrueInertiaOnly();
    void restVerdict_agreesWithContinuousTimePoles_data();
    void restVerdict_agreesWithContinuousTimePoles();
    void restRadius_equalsTheLoopBuiltFromTheStateSpaceHelpers();
    void lambda40_simulatedRobotLimitCycles();
    void nonPhysicalEstimate_isRefused();
    void plannedTorqueAboveLimit_isRefusedNamingTheJoint();

private:
    // The plan of scenario s with phi cut to its first 10 samples: the start pose at rest.
    TrialPlan restPlan(const Scenario &s, const Eigen::VectorXd &phi) const;

    std::shared_ptr<TwoLinkArm> m_model = std::make_shared<TwoLinkArm>();
    Eigen::VectorXd m_truth = Eigen::Vector3d(20, 5, 8);
    Eigen::VectorXd m_initial = Eigen::Vector3d(40, 20, 30);
};

TrialPlan TestSafetyCheck::restPlan(const Scenario &s, const Eigen::VectorXd &phi) const
{
    TrialPlan plan = TrialPlanner(s, m_model).plan(phi);
    for (Eigen::MatrixXd *m :
         {&plan.desired.q, &plan.desired.qd, &plan.desired.qdd, &plan.feedforward})
        m->conservativeResize(Eigen::NoChange, 10);
    return plan;
}

void TestSafetyCheck::paperGainsWithLambda200_areStableAlongThePath()
{
    const Scenario s;
    const TrialPlanner planner(s, m_model);
    for (const Eigen::VectorXd &phi : {m_initial, m_truth}) {
        const SafetyVerdict v = checkTrial(*m_model, phi, planner.plan(phi));
        QVERIFY2(v.passed(), qPrintable(v.reason));
        QVERIFY(v.worstSpectralRadius < 1.0);
        QVERIFY(v.reason.isEmpty());
    }
}

// docs/method.md §3: the paper's gains were tuned on the initial model; with lambda = 40 the
// loop is stable for phi_0 but not for the true inertia, so the check must refuse once the
// estimate nears the truth.
void TestSafetyCheck::paperLambda40_isUnstableForTheTrueInertiaOnly()
{
    Scenario s;
    s.controller.lambda = 40.0;
    const TrialPlanner planner(s, m_model);
    QVERIFY(checkTrial(*m_model, m_initial, planner.plan(m_initial)).passed());
    const SafetyVerdict v = checkTrial(*m_model, m_truth, planner.plan(m_truth));
    QVERIFY(!v.passed());
    QVERIFY(!v.stable);
    QVERIFY(v.worstDecayRate > 0.0);
    QVERIFY2(v.reason.contains(QStringLiteral("unstable")), qPrintable(v.reason));
    QVERIFY2(v.reason.contains(QStringLiteral("lambda")), qPrintable(v.reason));
}

void TestSafetyCheck::restVerdict_agreesWithContinuousTimePoles_data()
{
    QTest::addColumn<double>("lambda");
    QTest::addColumn<Eigen::VectorXd>("phi");
    for (double lambda : {40.0, 60.0, 100.0, 200.0}) {
        QTest::addRow("lambda %g, truth", lambda) << lambda << m_truth;
        QTest::addRow("lambda %g, phi0", lambda) << lambda << m_initial;
    }
}

// An independent verdict at the start pose: the continuous plant at rest (x'' = M^-1 tau) in
// closed loop with the continuous PID. Where its poles are clearly on one side, the discrete
// check must agree.
void TestSafetyCheck::restVerdict_agreesWithContinuousTimePoles()
{
    QFETCH(double, lambda);
    QFETCH(Eigen::VectorXd, phi);
    Scenario s;
    s.controller.lambda = lambda;
    const TrialPlan plan = restPlan(s, phi);
    const SafetyVerdict v = checkTrial(*m_model, phi, plan);

    Eigen::MatrixXd m(2, 2);
    m_model->massMatrix(plan.desired.q.col(0), phi, m);
    Eigen::MatrixXd cl = Eigen::MatrixXd::Zero(10, 10); // q, qd, 3 PID states per joint
    cl.block(0, 2, 2, 2).setIdentity();
    const Eigen::MatrixXd mInv = m.inverse();
    for (int j = 0; j < 2; ++j) {
        const StateSpace c =
            pidStateSpace(s.controller.kp[j], s.controller.ki[j], s.controller.kd[j], lambda);
        // u_j = Cc x_j + Dc e_j with e_j = -q_j; controller state x_j' = Ac x_j + Bc e_j.
        cl.block(2, 4 + 3 * j, 2, 3) = mInv.col(j) * c.c;
        cl.block(2, j, 2, 1) -= mInv.col(j) * c.d(0, 0);
        cl.block(4 + 3 * j, 4 + 3 * j, 3, 3) = c.a;
        cl.block(4 + 3 * j, j, 3, 1) = -c.b;
    }
    const double maxReal = Eigen::EigenSolver<Eigen::MatrixXd>(cl).eigenvalues().real().maxCoeff();
    // The slowest stable pole is the integrator's, near -ki/kp; it stays stable when discretised.
    QCOMPARE(v.stable, maxReal < 0.0);
    if (lambda == 40.0 && phi == m_truth)
        QVERIFY2(maxReal > 1.0, qPrintable(QString::number(maxReal))); // the paper's case
}

// The check's fixed-size closed loop against one assembled from the dynamic StateSpace helpers
// (zeroOrderHold of the plant at rest, x'' = M^-1 u; the Tustin PIDs): the same spectral radius.
void TestSafetyCheck::restRadius_equalsTheLoopBuiltFromTheStateSpaceHelpers()
{
    for (double lambda : {40.0, 200.0}) {
        Scenario s;
        s.controller.lambda = lambda;
        const TrialPlan plan = restPlan(s, m_truth);
        const SafetyVerdict v = checkTrial(*m_model, m_truth, plan);

        Eigen::MatrixXd m(2, 2);
        m_model->massMatrix(plan.desired.q.col(0), m_truth, m);
        StateSpace plant;
        plant.a = Eigen::MatrixXd::Zero(4, 4);
        plant.a.block(0, 2, 2, 2).setIdentity();
        plant.b = Eigen::MatrixXd::Zero(4, 2);
        plant.b.bottomRows(2) = m.inverse();
        plant.c = Eigen::MatrixXd::Zero(2, 4);
        plant.c.leftCols(2).setIdentity();
        plant.d = Eigen::MatrixXd::Zero(2, 2);
        const StateSpace d = zeroOrderHold(plant, s.controller.samplePeriod);
        const PidController pid(s.controller);
        Eigen::MatrixXd cl = Eigen::MatrixXd::Zero(10, 10);
        cl.topLeftCorner(4, 4) = d.a;
        for (int j = 0; j < 2; ++j) {
            const StateSpace &c = pid.joint(j); // u_j = Cc x_j - Dc q_j; x_j+ = Ac x_j - Bc q_j
            cl.block(0, 4 + 3 * j, 4, 3) = d.b.col(j) * c.c;
            cl.block(0, j, 4, 1) -= d.b.col(j) * c.d(0, 0);
            cl.block(4 + 3 * j, 4 + 3 * j, 3, 3) = c.a;
            cl.block(4 + 3 * j, j, 3, 1) = -c.b;
        }
        const double radius =
            Eigen::EigenSolver<Eigen::MatrixXd>(cl, false).eigenvalues().cwiseAbs().maxCoeff();
        QVERIFY2(std::abs(v.worstSpectralRadius - radius) < 1e-9,
                 qPrintable(QStringLiteral("%1 vs %2")
                                .arg(v.worstSpectralRadius, 0, 'g', 17)
                                .arg(radius, 0, 'g', 17)));
        QCOMPARE(v.stable, radius < 1.0);
    }
}

// The verdict describes the robot: with lambda = 40 and a feedforward built with the truth, the
// simulated robot never settles (limit cycle in saturation), while lambda = 200 settles.
void TestSafetyCheck::lambda40_simulatedRobotLimitCycles()
{
    auto settledError = [this](double lambda) {
        Scenario s;
        s.controller.lambda = lambda;
        const TrialPlan plan = TrialPlanner(s, m_model).plan(m_truth);
        SimulatedRobot robot(m_model, m_truth);
        const TrialRecord r = robot.runTrial(plan, {});
        const int last = 100; // the final 0.2 s of the rest after the motion
        return (plan.desired.q.rightCols(last) - r.q.rightCols(last)).cwiseAbs().maxCoeff();
    };
    QVERIFY(settledError(200.0) < 1e-6);
    QVERIFY(settledError(40.0) > 1e-4);
}

void TestSafetyCheck::nonPhysicalEstimate_isRefused()
{
    const Scenario s;
    const Eigen::VectorXd bad = Eigen::Vector3d(4.0, 10.0, 3.0); // a c < b^2
    TrialPlan plan = TrialPlanner(s, m_model).plan(m_truth);
    const SafetyVerdict v = checkTrial(*m_model, bad, plan);
    QVERIFY(!v.passed());
    QVERIFY(!v.physical);
    QVERIFY2(v.reason.contains(QStringLiteral("not a physical robot")), qPrintable(v.reason));
}

void TestSafetyCheck::plannedTorqueAboveLimit_isRefusedNamingTheJoint()
{
    const Scenario s;
    TrialPlan plan = TrialPlanner(s, m_model).plan(m_truth);
    plan.torqueLimit[1] = 0.5 * plan.feedforward.row(1).cwiseAbs().maxCoeff();
    const SafetyVerdict v = checkTrial(*m_model, m_truth, plan);
    QVERIFY(!v.passed());
    QVERIFY(!v.torqueWithinLimits);
    QVERIFY2(v.reason.contains(QStringLiteral("joint 2")), qPrintable(v.reason));
}

QTEST_GUILESS_MAIN(TestSafetyCheck)
#include "tst_safetycheck.moc"
