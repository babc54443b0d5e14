#include "model/Error.h"
#include "model/ModelFactory.h"
#include "model/TwoLinkArm.h"
#include "motion/CartesianLine.h"
#include "session/RobotScenario.h"
#include "session/ScenarioRobot.h"
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
    void midSampleFeedforward_isTheModelHalfASampleLater();
    void midSampleFeedforward_removesTheHoldsFirstOrderError();
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

void TestTrialPlanner::midSampleFeedforward_isTheModelHalfASampleLater()
{
    // The paper's line and a joint path of the built-in double pendulum (gravity, friction).
    Scenario line;
    Scenario joints = scenarioForRobot(QStringLiteral("double-pendulum"));
    for (Scenario *s : {&line, &joints}) {
        const auto model = makeRobotModel(s->model, s->urdf);
        *s = withRobotDefaults(*s, *model);
        const Eigen::VectorXd phi = s->initialParameters * 1.1;
        s->controller.feedforwardTime = FeedforwardTime::SampleInstant;
        const TrialPlan atInstant = TrialPlanner(*s, model).plan(phi);
        s->controller.feedforwardTime = FeedforwardTime::MidSample;
        const TrialPlanner planner(*s, model);
        const TrialPlan plan = planner.plan(phi);
        // The trajectory is that of the sample instants; only the feedforward moves.
        QCOMPARE(plan.desired.q, atInstant.desired.q);
        QCOMPARE(plan.desired.qd, atInstant.desired.qd);
        QCOMPARE(plan.samples(), atInstant.samples());
        const double ts = s->controller.samplePeriod;
        const int n = model->dof();
        Eigen::VectorXd q(n), qd(n), qdd(n), tau(n);
        int compared = 0;
        for (int k = 0; k + 1 < plan.samples(); k += 17) {
            const double t = k * ts + 0.5 * ts - s->restBefore; // motion time of the middle
            if (s->path.kind == PathKind::Line) {
                if (t < 0.0 || t > plan.motionDuration)
                    continue;
                const JointState js = lineStateAt(planner.kinematics(), s->line,
                                                  plan.motionDuration, t, plan.desired.q.col(k));
                q = js.q, qd = js.qd, qdd = js.qdd;
            } else {
                jointPathStateInto(*planner.jointPath(), plan.motionDuration, t, q, qd, qdd);
            }
            model->inverseDynamics(q, qd, qdd, phi, tau);
            QVERIFY2((tau - plan.feedforward.col(k)).cwiseAbs().maxCoeff() <=
                         1e-10 * (1.0 + tau.cwiseAbs().maxCoeff()),
                     qPrintable(QStringLiteral("%1, sample %2").arg(s->model).arg(k)));
            ++compared;
        }
        QVERIFY2(compared > 20,
                 qPrintable(QStringLiteral("%1: %2 samples compared").arg(s->model).arg(compared)));
        // In the motion the two differ by about Ts / 2 times the torque's rate.
        QVERIFY((plan.feedforward - atInstant.feedforward).cwiseAbs().maxCoeff() > 1e-6);
    }
}

namespace {

// The largest tracking error [rad] of one trial of the double pendulum whose feedforward has
// the true parameters, with an ideal encoder and no noise: what the controller's hold leaves.
double holdError(FeedforwardTime time, double samplePeriod)
{
    Scenario s = scenarioForRobot(QStringLiteral("double-pendulum"));
    const auto model = makeRobotModel(s.model, s.urdf);
    s.simulation.encoderCounts = 0;
    s.simulation.torqueNoise = 0.0;
    s.simulation.substeps = 20;
    s.controller.samplePeriod = samplePeriod;
    s.controller.feedforwardTime = time;
    s = withRobotDefaults(s, *model);
    s.initialParameters = s.simulation.trueParameters;
    const TrialPlan plan = TrialPlanner(s, model).plan(s.initialParameters);
    const TrialRecord record = makeSimulatedRobot(s, model)->runTrial(plan, {});
    if (!record.completed())
        return std::numeric_limits<double>::quiet_NaN();
    return (plan.desired.q - record.q).cwiseAbs().maxCoeff();
}

} // namespace

void TestTrialPlanner::midSampleFeedforward_removesTheHoldsFirstOrderError()
{
    // Held over [t_k, t_k + Ts), the torque at t_k comes Ts / 2 early on average: the tracking
    // error it leaves falls in proportion to Ts. The torque at the middle matches the interval's
    // mean to O(Ts^2), and so does the error it leaves: halving Ts quarters it.
    const double instant2 = holdError(FeedforwardTime::SampleInstant, 0.002);
    const double instant1 = holdError(FeedforwardTime::SampleInstant, 0.001);
    const double middle2 = holdError(FeedforwardTime::MidSample, 0.002);
    const double middle1 = holdError(FeedforwardTime::MidSample, 0.001);
    const QString figures = QStringLiteral("instant %1, %2 rad; middle %3, %4 rad")
                                .arg(instant2)
                                .arg(instant1)
                                .arg(middle2)
                                .arg(middle1);
    QVERIFY2(instant2 / instant1 > 1.7 && instant2 / instant1 < 2.3, qPrintable(figures));
    QVERIFY2(middle2 / middle1 > 3.0, qPrintable(figures));
    QVERIFY2(middle2 < 0.05 * instant2, qPrintable(figures));
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
