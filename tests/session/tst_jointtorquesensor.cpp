// estimator.jointTorqueSensor (identify/RotorTorque.h): the drive's command reconstructed from a
// record is the torque the simulated drives applied; behind a joint torque sensor (elastic
// joints: the sensor measures the spring) the rotor's inertia is fitted from the command minus
// the measurement, and a session learns it as the armature term, which it cannot without; a
// sensor's lag undone gives the torque it was given.
#include "../support/RotorScenario.h"
#include "identify/FilteringEstimator.h"
#include "identify/LearningLaw.h"
#include "identify/RotorTorque.h"
#include "identify/SensorLag.h"
#include "model/ModelFactory.h"
#include "session/CommissioningSession.h"
#include "session/ScenarioRobot.h"
#include "session/ScenarioRobotJoints.h"
#include "session/TrialPlanner.h"

#include <QTest>

using namespace learnid;
using namespace learnid::test;

class TestJointTorqueSensor : public QObject
{
    Q_OBJECT

private slots:
    void driveCommand_isWhatTheSimulatedDrivesApplied();
    void rotorTorque_fitsTheRotorBehindTheSensor();
    void session_learnsTheRotorOnlyWithTheSetting();
    void withoutSensorLag_isTheTorqueTheSensorWasGiven();
};

void TestJointTorqueSensor::driveCommand_isWhatTheSimulatedDrivesApplied()
{
    // A rigid robot's torque reading is the command it applied. Limits below the planned
    // torque make the commands saturate; a quantised encoder feeds the PIDs the recorded angles.
    Scenario s = rotorDoublePendulum();
    s.simulation.encoderCounts = 1 << 16;
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    TrialPlan plan = TrialPlanner(s, model).plan(s.initialParameters);
    plan.torqueLimit = 0.7 * plan.feedforward.cwiseAbs().rowwise().maxCoeff();
    plan.maxTrackingError = 1.0;
    const TrialRecord record = makeSimulatedRobot(s, model)->runTrial(plan, TrialMonitor{});
    QVERIFY2(record.completed(), qPrintable(record.message));
    const Eigen::MatrixXd command = driveCommand(plan, record);
    QCOMPARE(command.cols(), record.tau.cols());
    const Eigen::ArrayXXd limit = plan.torqueLimit.replicate(1, command.cols()).array();
    QVERIFY2((command.array().abs() >= limit).any(), "no command saturated");
    QVERIFY((command - record.tau).cwiseAbs().maxCoeff() <= 1e-12 * limit.maxCoeff());
    // The feedforward alone is not it: the PIDs' part is there.
    QVERIFY((plan.feedforward - record.tau).cwiseAbs().maxCoeff() > 1e-3);
}

void TestJointTorqueSensor::rotorTorque_fitsTheRotorBehindTheSensor()
{
    for (const double factor : {0.5, 2.0}) {
        Scenario s = behindAJointSensor(factor);
        const auto model = makeRobotModel(s.model, s.urdf);
        s = withRobotDefaults(s, *model);
        const Eigen::VectorXd rotor = simulatedJoints(s, *model).armature;
        CommissioningSession session(s, model, makeSimulatedRobot(s, model));
        const TrialResult &result = session.runTrial();
        QVERIFY2(result.record.completed(), qPrintable(result.message));
        const FilteringEstimator filter(s.estimator.rho, result.record.samplePeriod);
        const JointStateEstimate hat =
            estimateJointStates(filter, result.plan(), result.record, true);
        Eigen::VectorXd inertia;
        const Eigen::MatrixXd torque =
            rotorTorque(filter, result.plan(), result.record, result.record.tau, hat.qdd,
                        result.record.samples() - 1, &inertia);
        QCOMPARE(torque.rows(), Eigen::Index(result.record.samples() - 1));
        qInfo("rotor x%g: fitted %.6g, %.6g kg m^2; simulated %.6g, %.6g", factor, inertia[0],
              inertia[1], rotor[0], rotor[1]);
        for (int j = 0; j < 2; ++j) {
            QVERIFY2(std::abs(inertia[j] - rotor[j]) < 0.06 * rotor[j],
                     qPrintable(QStringLiteral("factor %1, joint %2: fitted %3, simulated %4")
                                    .arg(factor)
                                    .arg(j + 1)
                                    .arg(inertia[j])
                                    .arg(rotor[j])));
            QVERIFY(torque.col(j).isApprox(
                inertia[j] * 0.5 *
                    (hat.qdd.row(j).head(torque.rows()) + hat.qdd.row(j).tail(torque.rows()))
                        .transpose(),
                1e-12));
        }
    }
}

void TestJointTorqueSensor::session_learnsTheRotorOnlyWithTheSetting()
{
    double errors[2] = {0.0, 0.0};
    for (const bool sensor : {false, true}) {
        Scenario s = behindAJointSensor(1.0);
        s.estimator.jointTorqueSensor = sensor;
        const auto model = makeRobotModel(s.model, s.urdf);
        s = withRobotDefaults(s, *model);
        const Eigen::VectorXd rotor = simulatedJoints(s, *model).armature;
        CommissioningSession session(s, model, makeSimulatedRobot(s, model));
        for (int k = 0; k < 2; ++k)
            QVERIFY2(session.runTrial().learned(), "a trial was not learned from");
        errors[sensor] =
            motorTorqueError(*model, session.history().constLast().plan(),
                             session.estimates().constLast(), s.simulation.trueParameters, rotor);
    }
    qInfo("motor-torque error on the path: %.3f %% without the setting, %.3f %% with it",
          100.0 * errors[0], 100.0 * errors[1]);
    QVERIFY2(errors[1] < 0.01, "the rotor's torque is not learned");
    QVERIFY2(errors[0] > 5.0 * errors[1], "without the setting the rotor is learned anyway");
}

void TestJointTorqueSensor::withoutSensorLag_isTheTorqueTheSensorWasGiven()
{
    // A rigid robot's sensor is given the drives' command; with a 5 ms lag it reads it late.
    Scenario s = rotorDoublePendulum();
    s.simulation.torqueSensorLag = 0.005;
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    CommissioningSession session(s, model, makeSimulatedRobot(s, model));
    const TrialResult &result = session.runTrial();
    QVERIFY2(result.record.completed(), qPrintable(result.message));
    const TrialRecord &record = result.record;
    const Eigen::MatrixXd command = driveCommand(result.plan(), record);
    const double scale = command.cwiseAbs().maxCoeff();
    QVERIFY((record.tau - command).cwiseAbs().maxCoeff() > 0.01 * scale);
    const Eigen::MatrixXd given =
        withoutSensorLag(record.tau, record.samplePeriod, s.simulation.torqueSensorLag);
    QVERIFY((given - command).cwiseAbs().maxCoeff() <= 1e-9 * scale);
    QCOMPARE(withoutSensorLag(record.tau, record.samplePeriod, 0.0), record.tau);
}

QTEST_GUILESS_MAIN(TestJointTorqueSensor)
#include "tst_jointtorquesensor.moc"
