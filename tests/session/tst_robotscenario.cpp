// The scenario the window starts from when the technician picks a robot (RobotScenario.h):
// for every built-in URDF robot it is a valid scenario whose path stays within the joint
// limits, whose first trial passes the pre-trial check, and whose session learns the path
// torques of the simulated real robot (the CAD one perturbed by 30 %). And waypoints beyond a
// joint limit are named by key, joint and limit.

#include "io/ScenarioFile.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "session/CommissioningSession.h"
#include "session/ConvergenceFigures.h"
#include "session/EstimateConsistency.h"
#include "session/RobotScenario.h"
#include "session/ScenarioRobot.h"

#include <QTest>

using namespace learnid;

class TestRobotScenario : public QObject
{
    Q_OBJECT

private slots:
    void builtInRobot_learnsFromItsDefaultScenario_data();
    void builtInRobot_learnsFromItsDefaultScenario();
    void paperArm_isThePaperScenario();
    void waypointBeyondALimit_isNamedWithJointAndLimit();
    void unknownModel_isRefused();
    void clockOf2ms_keepsTheRulesGains();
};

void TestRobotScenario::builtInRobot_learnsFromItsDefaultScenario_data()
{
    QTest::addColumn<QString>("model");
    for (const QString &id : knownRobotModels())
        if (isUrdfModel(id) && id != QLatin1String("urdf"))
            QTest::newRow(qPrintable(id)) << id;
}

void TestRobotScenario::builtInRobot_learnsFromItsDefaultScenario()
{
    QFETCH(QString, model);
    const Scenario requested = scenarioForRobot(model);
    validateScenario(requested); // throws on anything the scenario file would refuse
    const auto robotModel = makeRobotModel(model, requested.urdf);
    QCOMPARE(waypointLimitError(*robotModel, requested.path.waypoints), QString());
    QVERIFY((requested.controller.kp.array() > 0).all());
    QVERIFY((requested.controller.kd.array() > 0).all());
    QCOMPARE(requested.controller.feedforwardTime, FeedforwardTime::MidSample);

    const Scenario s = withRobotDefaults(requested, *robotModel);
    CommissioningSession session(s, robotModel, makeSimulatedRobot(s, robotModel));
    const PreTrialCheck check = session.checkNextTrial();
    QVERIFY2(check.passed(), qPrintable(check.reason()));
    // The check's gravity figure: the regressor's torque at rest along the plan (W phi with
    // qd = qdd = 0; the check computes it by recursive Newton-Euler).
    Eigen::VectorXd gravity = Eigen::VectorXd::Zero(robotModel->dof());
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(robotModel->dof());
    for (int k = 0; k < check.plan.samples(); ++k)
        gravity = gravity.cwiseMax(
            robotModel->torqueAt(check.plan.desired.q.col(k), zero, zero, s.initialParameters)
                .cwiseAbs());
    // Where the CAD is no real body (the double pendulum's link 2), the check linearises its
    // nearest consistent estimate, whose torques on the path differ by a fraction of a percent.
    const bool consistent =
        checkEstimateConsistency(*robotModel, s.initialParameters, JointTrajectory()).consistent;
    const double tolerance = consistent ? 1e-9 * (1.0 + gravity.norm()) : 1e-2 * gravity.norm();
    QVERIFY2((check.verdict.peakGravityTorque - gravity).norm() <= tolerance,
             qPrintable(QString::number((check.verdict.peakGravityTorque - gravity).norm())));
    for (int k = 0; k <= 2; ++k) {
        const TrialResult &result = session.runTrial();
        QVERIFY2(result.record.completed(),
                 qPrintable(QStringLiteral("trial %1: %2").arg(k).arg(result.message)));
    }
    const JointTrajectory &path = session.history().constLast().plan().desired;
    const double before = pathTorqueErrorPercent(*robotModel, path, session.estimates().front(),
                                                 s.simulation.trueParameters);
    const double after = pathTorqueErrorPercent(*robotModel, path, session.estimates().back(),
                                                s.simulation.trueParameters);
    // The path-torque error of every estimate equals the definition evaluated here with the
    // feedforward torques along the path: ||tau(phi_k) - tau(phi)|| / ||tau(phi)||.
    const QVector<double> batch = pathTorqueErrorsPercent(*robotModel, path, session.estimates(),
                                                          s.simulation.trueParameters);
    QCOMPARE(batch.size(), session.estimates().size());
    const Eigen::MatrixXd truthTorque =
        feedforwardTorque(*robotModel, path, s.simulation.trueParameters);
    for (int k = 0; k < batch.size(); ++k) {
        const double expected =
            100.0 *
            (feedforwardTorque(*robotModel, path, session.estimates()[k]) - truthTorque).norm() /
            truthTorque.norm();
        QVERIFY2(std::abs(batch[k] - expected) <= 1e-9 * expected, qPrintable(QString::number(k)));
    }
    qInfo("%s: path-torque error %.3f %% -> %.3f %%", qPrintable(model), before, after);
    QVERIFY2(before > 2.0, "the perturbation must matter");
    QVERIFY2(after < 1.5 && after < before / 10.0, qPrintable(QString::number(after)));
}

void TestRobotScenario::paperArm_isThePaperScenario()
{
    const Scenario s = scenarioForRobot(QStringLiteral("paper-2link"));
    const Scenario paper;
    QCOMPARE(s.model, paper.model);
    QCOMPARE(s.path.kind, PathKind::Line);
    QCOMPARE(s.controller.kp, paper.controller.kp);
    QCOMPARE(s.initialParameters, paper.initialParameters);
    QCOMPARE(s.controller.feedforwardTime, FeedforwardTime::SampleInstant);
}

void TestRobotScenario::waypointBeyondALimit_isNamedWithJointAndLimit()
{
    const auto model = makeRobotModel(QStringLiteral("puma560"));
    const auto *chain = dynamic_cast<const ChainModel *>(model.get());
    QVERIFY(chain);
    Scenario s = scenarioForRobot(QStringLiteral("puma560"));
    const ChainJoint &joint3 = chain->chain().joints[2];
    s.path.waypoints[1][2] = joint3.upper + 0.01;
    const QString error = waypointLimitError(*model, s.path.waypoints);
    const QString expected =
        QStringLiteral("path.waypoints[1][2]: %1 deg is above joint 3 (%2)'s upper limit %3 deg")
            .arg((joint3.upper + 0.01) * 180.0 / M_PI, 0, 'f', 2)
            .arg(joint3.name)
            .arg(joint3.upper * 180.0 / M_PI, 0, 'f', 2);
    QCOMPARE(error, expected);
    s.path.waypoints[1][2] = joint3.lower - 0.01;
    QVERIFY2(waypointLimitError(*model, s.path.waypoints).contains(QLatin1String("lower limit")),
             qPrintable(waypointLimitError(*model, s.path.waypoints)));
    // The paper's arm has no joint limits.
    const auto paper = makeRobotModel(QStringLiteral("paper-2link"));
    QCOMPARE(waypointLimitError(*paper, {Eigen::Vector2d(100, -100)}), QString());
}

void TestRobotScenario::unknownModel_isRefused()
{
    try {
        scenarioForRobot(QStringLiteral("no-such-robot"));
        QFAIL("an unknown model was accepted");
    } catch (const Error &e) {
        QCOMPARE(e.message(), QStringLiteral("robot.model: unknown model \"no-such-robot\""));
    }
}

void TestRobotScenario::clockOf2ms_keepsTheRulesGains()
{
    // The clock step of the design (scenarioForRobot's samplePeriod) lowers gains only where the
    // pre-trial check finds the loop unstable: at 2 ms every built-in robot, bare or carrying
    // 1 kg, keeps the gains it has at a clock four times faster (where the rule's hold).
    PayloadSettings payload;
    payload.enabled = true;
    payload.mass = 1.0;
    payload.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    for (const QString &robot : knownRobotModels()) {
        if (!isUrdfModel(robot) || robot == QLatin1String("urdf"))
            continue;
        for (const PayloadSettings &p : {PayloadSettings(), payload}) {
            const ControllerSettings at2ms = scenarioForRobot(robot, {}, p, 0.002).controller;
            const ControllerSettings fast = scenarioForRobot(robot, {}, p, 0.0005).controller;
            QVERIFY2(at2ms.kd == fast.kd && at2ms.kp == fast.kp,
                     qPrintable(robot + (p.enabled ? QStringLiteral(" with 1 kg") : QString())));
            QCOMPARE(at2ms.samplePeriod, 0.002);
        }
    }
}

QTEST_GUILESS_MAIN(TestRobotScenario)
#include "tst_robotscenario.moc"
