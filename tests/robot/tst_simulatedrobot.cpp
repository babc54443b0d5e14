#include "model/TwoLinkArm.h"
#include "robot/SimulatedRobot.h"
#include "session/TrialPlanner.h"

#include <QTest>
#include <atomic>
#include <cmath>

using namespace learnid;

class TestSimulatedRobot : public QObject
{
    Q_OBJECT

private slots:
    void firstSample_followsForwardDynamicsOfHeldTorque();
    void exactFeedforward_tracksWithinMicroradians();
    void encoder_quantisesMeasuredAngles();
    void torqueNoise_isMeasurementOnlyWithRequestedLevel();
    void sameSeed_reproducesTrial();
    void commands_saturateAtLimits();
    void driveFault_endsTrialWithPartialRecord();
    void disturbance_abortsOnTrackingErrorNamingJoint();
    void cancel_stopsAtNextSample();
    void repeatedPlan_recordsWhatANewSimulationRecords();
    void repeatedAbortOrStop_endsWhereANewSimulationEnds();
    void apply_storesOrRefusesWithoutChange();

private:
    TrialPlan paperPlan(const Eigen::VectorXd &phi) const { return m_planner.plan(phi); }
    std::shared_ptr<TwoLinkArm> m_model = std::make_shared<TwoLinkArm>();
    Eigen::VectorXd m_truth = Eigen::Vector3d(20, 5, 8);
    Scenario m_scenario;
    TrialPlanner m_planner{m_scenario, m_model};
};

// Over the first sample the plant integrates qdd = M^-1 (tau - h) from rest with the torque
// held: q(Ts) - q(0) = qdd Ts^2 / 2 + O(Ts^3). Zero gains make the torque the feedforward alone.
void TestSimulatedRobot::firstSample_followsForwardDynamicsOfHeldTorque()
{
    TrialPlan plan = paperPlan(m_truth);
    plan.controller.kp.setZero();
    plan.controller.ki.setZero();
    plan.controller.kd.setZero();
    const double ts = plan.desired.samplePeriod;
    const Eigen::Vector2d tau(1.5, -0.7);
    plan.feedforward.setZero();
    plan.feedforward.col(0) = tau;
    SimulatedRobot robot(m_model, m_truth);
    const TrialRecord r = robot.runTrial(plan, {});
    const Eigen::VectorXd q0 = plan.desired.q.col(0);
    Eigen::VectorXd qdd(2);
    m_model->forwardDynamics(q0, Eigen::Vector2d::Zero(), tau, m_truth, qdd);
    const Eigen::VectorXd expected = q0 + 0.5 * ts * ts * qdd;
    QVERIFY((r.q.col(1) - expected).cwiseAbs().maxCoeff() < 1e-9);
    QCOMPARE(r.tau(0, 0), tau[0]);
}

void TestSimulatedRobot::exactFeedforward_tracksWithinMicroradians()
{
    SimulatedRobot robot(m_model, m_truth);
    const TrialPlan plan = paperPlan(m_truth);
    const TrialRecord r = robot.runTrial(plan, {});
    QVERIFY(r.completed());
    QCOMPARE(r.samples(), plan.samples());
    // Only the hold of the torque over each sample separates plant and plan.
    const double worst = (plan.desired.q - r.q).cwiseAbs().maxCoeff();
    QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
}

void TestSimulatedRobot::encoder_quantisesMeasuredAngles()
{
    MeasurementOptions options;
    options.encoderCounts = 1 << 16;
    SimulatedRobot robot(m_model, m_truth, options);
    const TrialRecord r = robot.runTrial(paperPlan(Eigen::Vector3d(40, 20, 30)), {});
    const double count = 2.0 * M_PI / 65536.0;
    const Eigen::ArrayXXd counts = r.q.array() / count;
    QVERIFY(((counts - counts.round()).abs() < 1e-6).all());
}

void TestSimulatedRobot::torqueNoise_isMeasurementOnlyWithRequestedLevel()
{
    const TrialPlan plan = paperPlan(Eigen::Vector3d(40, 20, 30));
    SimulatedRobot clean(m_model, m_truth);
    MeasurementOptions options;
    options.torqueNoise = 0.01;
    SimulatedRobot noisy(m_model, m_truth, options);
    const TrialRecord a = clean.runTrial(plan, {});
    const TrialRecord b = noisy.runTrial(plan, {});
    QCOMPARE(a.q, b.q); // noise does not reach the plant
    const Eigen::MatrixXd d = b.tau - a.tau;
    for (int j = 0; j < 2; ++j) {
        const double sd = std::sqrt(d.row(j).squaredNorm() / double(d.cols()));
        const double expected = 0.01 * plan.torqueLimit[j];
        QVERIFY2(std::abs(sd / expected - 1.0) < 0.1, qPrintable(QString::number(sd)));
        QVERIFY(std::abs(d.row(j).mean()) < 4.0 * expected / std::sqrt(double(d.cols())));
    }
}

void TestSimulatedRobot::sameSeed_reproducesTrial()
{
    const TrialPlan plan = paperPlan(Eigen::Vector3d(40, 20, 30));
    MeasurementOptions options;
    options.torqueNoise = 0.01;
    options.seed = 7;
    SimulatedRobot a(m_model, m_truth, options), b(m_model, m_truth, options);
    const TrialRecord ra = a.runTrial(plan, {});
    QCOMPARE(ra.tau, b.runTrial(plan, {}).tau);
    QVERIFY(ra.tau != a.runTrial(plan, {}).tau); // the next trial draws new noise
}

void TestSimulatedRobot::commands_saturateAtLimits()
{
    TrialPlan plan = paperPlan(Eigen::Vector3d(40, 20, 30));
    plan.torqueLimit = Eigen::Vector2d(0.5, 0.25);
    plan.maxTrackingError = 1e9; // let it run saturated
    SimulatedRobot robot(m_model, m_truth);
    const TrialRecord r = robot.runTrial(plan, {});
    QVERIFY(r.completed());
    for (int j = 0; j < 2; ++j) {
        QVERIFY(r.tau.row(j).cwiseAbs().maxCoeff() <= plan.torqueLimit[j]);
        QCOMPARE(r.tau.row(j).cwiseAbs().maxCoeff(), plan.torqueLimit[j]); // it does saturate
    }
}

void TestSimulatedRobot::driveFault_endsTrialWithPartialRecord()
{
    SimulatedRobot robot(m_model, m_truth);
    SimulatedFaults faults;
    faults.driveFaultAtSample = 500;
    robot.setFaults(faults);
    const TrialRecord r = robot.runTrial(paperPlan(m_truth), {});
    QCOMPARE(r.status, TrialStatus::Faulted);
    QCOMPARE(r.samples(), 501);
    QVERIFY(r.message.contains(QStringLiteral("fault")));
    QVERIFY(r.q.allFinite() && r.tau.allFinite());
}

void TestSimulatedRobot::disturbance_abortsOnTrackingErrorNamingJoint()
{
    SimulatedRobot robot(m_model, m_truth);
    SimulatedFaults faults;
    faults.disturbanceFromSample = 300;
    faults.disturbanceTorque = Eigen::Vector2d(0.0, 30.0); // a collision on joint 2
    robot.setFaults(faults);
    TrialPlan plan = paperPlan(m_truth);
    plan.maxTrackingError = 0.5 * M_PI / 180.0;
    const TrialRecord r = robot.runTrial(plan, {});
    QCOMPARE(r.status, TrialStatus::Aborted);
    QVERIFY(r.samples() > 300 && r.samples() < plan.samples());
    QVERIFY2(r.message.contains(QStringLiteral("joint 2")), qPrintable(r.message));
    const double last = std::abs(plan.desired.q(1, r.samples() - 1) - r.q(1, r.samples() - 1));
    QVERIFY(last > plan.maxTrackingError);
}

void TestSimulatedRobot::cancel_stopsAtNextSample()
{
    SimulatedRobot robot(m_model, m_truth);
    std::atomic_bool cancel{false};
    TrialMonitor monitor;
    monitor.cancel = &cancel;
    int calls = 0;
    monitor.progress = [&](int done, int) {
        ++calls;
        if (done >= 400)
            cancel.store(true);
    };
    const TrialRecord r = robot.runTrial(paperPlan(m_truth), monitor);
    QCOMPARE(r.status, TrialStatus::Cancelled);
    QCOMPARE(r.samples(), 401);
    QVERIFY(calls >= 4);
}

// A run of the plan run last reuses the motion (SimulatedRobot.h): its record must be the one a
// robot that simulates it afresh, drawing the same noise stream, records, to the bit.
void TestSimulatedRobot::repeatedPlan_recordsWhatANewSimulationRecords()
{
    MeasurementOptions options;
    options.torqueNoise = 0.01;
    options.encoderCounts = 1 << 16;
    options.seed = 3;
    MeasurementOptions second = options; // trial 1 of the first robot draws stream 1
    second.firstNoiseStream = 1;
    const TrialPlan plan = paperPlan(Eigen::Vector3d(40, 20, 30));
    SimulatedRobot robot(m_model, m_truth, options);
    const TrialRecord first = robot.runTrial(plan, {});
    const TrialRecord again = robot.runTrial(plan, {});
    const TrialRecord fresh = SimulatedRobot(m_model, m_truth, second).runTrial(plan, {});
    QVERIFY(again.completed());
    QCOMPARE(again.q, fresh.q);
    QCOMPARE(again.tau, fresh.tau);
    QCOMPARE(again.q, first.q);
    QVERIFY(again.tau != first.tau); // its own noise
    // Another plan (other gains) moves the arm otherwise: simulated, not reused.
    TrialPlan stiffer = plan;
    stiffer.controller.kp *= 2.0;
    MeasurementOptions third = options;
    third.firstNoiseStream = 2;
    const TrialRecord other = robot.runTrial(stiffer, {});
    QCOMPARE(other.q, SimulatedRobot(m_model, m_truth, third).runTrial(stiffer, {}).q);
    QVERIFY(other.q != first.q);
}

void TestSimulatedRobot::repeatedAbortOrStop_endsWhereANewSimulationEnds()
{
    MeasurementOptions options;
    options.torqueNoise = 0.01;
    MeasurementOptions second = options;
    second.firstNoiseStream = 1;
    TrialPlan plan = paperPlan(Eigen::Vector3d(40, 20, 30)); // far off the truth
    const TrialRecord unlimited = SimulatedRobot(m_model, m_truth).runTrial(plan, {});
    plan.maxTrackingError = 0.5 * (plan.desired.q - unlimited.q).cwiseAbs().maxCoeff();
    SimulatedRobot robot(m_model, m_truth, options);
    const TrialRecord first = robot.runTrial(plan, {});
    QCOMPARE(first.status, TrialStatus::Aborted);
    const TrialRecord again = robot.runTrial(plan, {});
    const TrialRecord fresh = SimulatedRobot(m_model, m_truth, second).runTrial(plan, {});
    QCOMPARE(again.status, TrialStatus::Aborted);
    QCOMPARE(again.message, fresh.message);
    QCOMPARE(again.tau, fresh.tau);

    // Stop during a repeated run ends it at the same sample as during a simulated one.
    plan.maxTrackingError = 1e9;
    std::atomic_bool cancel{false};
    TrialMonitor monitor;
    monitor.cancel = &cancel;
    monitor.progress = [&](int done, int) {
        if (done >= 400)
            cancel.store(true);
    };
    const TrialRecord whole = robot.runTrial(plan, {});
    const TrialRecord stopped = robot.runTrial(plan, monitor);
    QCOMPARE(stopped.status, TrialStatus::Cancelled);
    QCOMPARE(stopped.stopCause, TrialStopCause::Operator);
    QCOMPARE(stopped.samples(), 401);
    QCOMPARE(stopped.q, whole.q.leftCols(401).eval());
    cancel.store(false);
    const TrialRecord after = robot.runTrial(plan, {}); // the stop did not spoil the reuse
    QCOMPARE(after.q, whole.q);
    QCOMPARE(after.status, TrialStatus::Completed);
}

void TestSimulatedRobot::apply_storesOrRefusesWithoutChange()
{
    SimulatedRobot robot(m_model, m_truth);
    QVERIFY(robot.storedParameters().size() == 0);
    QVERIFY(robot.applyParameters(Eigen::Vector3d(21, 5, 8)).isEmpty());
    QCOMPARE(robot.storedParameters(), Eigen::VectorXd(Eigen::Vector3d(21, 5, 8)));
    QVERIFY(!robot.applyParameters(Eigen::Vector2d(1, 2)).isEmpty());
    QVERIFY(!robot.applyParameters(Eigen::Vector3d(NAN, 5, 8)).isEmpty());
    SimulatedFaults faults;
    faults.refuseApply = true;
    robot.setFaults(faults);
    QVERIFY(!robot.applyParameters(Eigen::Vector3d(22, 5, 8)).isEmpty());
    QCOMPARE(robot.storedParameters(), Eigen::VectorXd(Eigen::Vector3d(21, 5, 8)));
}

QTEST_GUILESS_MAIN(TestSimulatedRobot)
#include "tst_simulatedrobot.moc"
