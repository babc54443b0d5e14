#include "model/Error.h"
#include "model/TwoLinkArm.h"
#include "session/TrialPlanner.h"

#include <QTest>

using namespace learnid;

class TestTrialPlanner : public QObject
{
    Q_OBJECT

private slots:
    void paperScenario_plansDesignDurationsAndSamples();
    void feedforward_isRegressorTimesEstimate();
    void plan_carriesControllerLimitsAndThreshold();
    void unreachablePath_throwsNamingThePoint();

private:
    std::shared_ptr<TwoLinkArm> m_model = std::make_shared<TwoLinkArm>();
};

void TestTrialPlanner::paperScenario_plansDesignDurationsAndSamples()
{
    const Scenario s;
    const TrialPlanner planner(s, m_model);
    TorqueRuleResult rule;
    const TrialPlan first = planner.plan(s.initialParameters, &rule);
    QVERIFY2(std::abs(rule.duration - 4.93) < 0.005, qPrintable(QString::number(rule.duration)));
    QCOMPARE(first.motionDuration, rule.duration);
    // 0.1 s + T + 0.5 s sampled every 2 ms, both ends included.
    QCOMPARE(first.samples(), int(std::floor((0.6 + rule.duration) / 0.002 + 1e-9)) + 1);
    const TrialPlan truth = planner.plan(s.simulation.trueParameters, &rule);
    QVERIFY2(std::abs(rule.duration - 3.56) < 0.01, qPrintable(QString::number(rule.duration)));
    QVERIFY(truth.samples() < first.samples());
}

void TestTrialPlanner::feedforward_isRegressorTimesEstimate()
{
    const Scenario s;
    const Eigen::VectorXd phi = Eigen::Vector3d(31.0, 7.5, 12.0);
    const TrialPlan plan = TrialPlanner(s, m_model).plan(phi);
    QCOMPARE(plan.feedforwardParameters, phi);
    for (int k = 0; k < plan.samples(); k += 97) {
        const Eigen::MatrixXd w = m_model->regressorAt(
            plan.desired.q.col(k), plan.desired.qd.col(k), plan.desired.qdd.col(k));
        QVERIFY((w * phi - plan.feedforward.col(k)).cwiseAbs().maxCoeff() < 1e-12);
    }
}

void TestTrialPlanner::plan_carriesControllerLimitsAndThreshold()
{
    Scenario s;
    s.controller.lambda = 150.0;
    s.maxTrackingErrorDeg = 0.5;
    const TrialPlan plan = TrialPlanner(s, m_model).plan(s.initialParameters);
    QCOMPARE(plan.controller.lambda, 150.0);
    QCOMPARE(plan.torqueLimit, s.torqueLimits);
    QCOMPARE(plan.maxTrackingError, 0.5 * M_PI / 180.0);
    QCOMPARE(plan.desired.samplePeriod, s.controller.samplePeriod);
}

void TestTrialPlanner::unreachablePath_throwsNamingThePoint()
{
    Scenario s;
    s.line.length = 2.0; // leaves the 1.5 m reach
    try {
        const TrialPlanner planner(s, m_model); // refused before any trial is planned
        QFAIL("an unreachable path must not be planned");
    } catch (const Error &e) {
        QVERIFY2(e.message().contains(QStringLiteral("out of reach")), qPrintable(e.message()));
    }
}

QTEST_GUILESS_MAIN(TestTrialPlanner)
#include "tst_trialplanner.moc"
