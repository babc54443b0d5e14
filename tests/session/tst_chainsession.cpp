// Learning on URDF robots, whole sessions on the simulated robot: the built-in double pendulum
// (gravity, friction), the built-in Franka Emika Panda and the KUKA LWR4+ from ../shared/data
// (7 axes each), the real robot the CAD one perturbed by 30 %. Judged against the simulation's
// truth: the path-torque error (how well the feedforward matches the robot on its path) and the
// tracking error, trial 0 against the last; and the robot defaults a URDF scenario leaves to the
// robot.

#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "session/CommissioningSession.h"
#include "session/ConvergenceFigures.h"
#include "session/EstimateConsistency.h"
#include "session/SafetyCheck.h"
#include "session/ScenarioRobot.h"
#include "session/TrialPlanner.h"

#include <QTest>

using namespace learnid;

namespace {

Scenario doublePendulum()
{
    Scenario s;
    s.model = QStringLiteral("double-pendulum");
    s.torqueLimits.resize(0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.path.kind = PathKind::Waypoints;
    s.path.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1.2, -0.8),
                        Eigen::Vector2d(-0.6, 1.0), Eigen::Vector2d(0, 0)};
    s.planningFraction = 0.5;
    s.controller.kp = Eigen::Vector2d(20, 8);
    s.controller.ki = Eigen::Vector2d(2, 1);
    s.controller.kd = Eigen::Vector2d(1.5, 0.6);
    s.controller.lambda = 1000;
    s.maxTrackingErrorDeg = 5;
    s.simulation.inertiaPerturbation = 0.3;
    s.simulation.seed = 2;
    return s;
}

struct Outcome
{
    std::vector<double> pathTorqueErrorPercent; ///< of estimate k on the last trial's path
    std::vector<Eigen::VectorXd> maxTrackingErrorDeg;
};

Outcome runSession(const Scenario &requested, int learnings)
{
    const auto model = makeRobotModel(requested.model, requested.urdf);
    const Scenario s = withRobotDefaults(requested, *model);
    auto robot = makeSimulatedRobot(s, model);
    CommissioningSession session(s, model, robot);
    Outcome out;
    for (int k = 0; k <= learnings; ++k) {
        const TrialResult &result = session.runTrial();
        if (!result.record.completed())
            QTest::qFail(qPrintable(result.message), __FILE__, __LINE__);
        out.maxTrackingErrorDeg.push_back(result.maxTrackingErrorDeg);
    }
    const JointTrajectory &path = session.history().constLast().plan().desired;
    for (const Eigen::VectorXd &phi : session.estimates())
        out.pathTorqueErrorPercent.push_back(
            pathTorqueErrorPercent(*model, path, phi, s.simulation.trueParameters));
    return out;
}

// The largest CAD inertia M_jj each joint sees at the waypoints and halfway between them.
Eigen::VectorXd largestCadInertia(const RobotModel &model, const std::vector<Eigen::VectorXd> &path)
{
    const auto &chain = dynamic_cast<const ChainModel &>(model);
    const Eigen::VectorXd cad = chain.baseFromStandard(chain.cadStandard());
    Eigen::VectorXd inertia = Eigen::VectorXd::Zero(model.dof());
    Eigen::MatrixXd mass(model.dof(), model.dof());
    for (size_t w = 0; w < path.size(); ++w) {
        const Eigen::VectorXd &next = path[(w + 1) % path.size()];
        for (const Eigen::VectorXd &q : {path[w], Eigen::VectorXd(0.5 * (path[w] + next))}) {
            model.massMatrix(q, cad, mass);
            inertia = inertia.cwiseMax(mass.diagonal());
        }
    }
    return inertia;
}

} // namespace

class TestChainSession : public QObject
{
    Q_OBJECT

private slots:
    void urdfScenario_takesLimitsEstimateAndTruthFromTheRobot();
    void realUrdf_mustHaveTheRobotsJoints();
    void realUrdf_ownCadOrImplausibleIdentified();
    void doublePendulum_learnsThePathTorquesFromThePerturbedCad();
    void kukaLwr4_learnsThePathTorquesOfSevenAxes();
    void panda_learnsThePathTorquesOfSevenAxes();
    void inconsistentEstimate_isReportedAndItsNearestConsistentOneKeepsThePathTorques();
    void pathBeyondTheUrdfsJointLimits_isRefusedBeforeMotion();
    void identifiability_namesWhatThePathCannotSee();
    void gravityAloneBeyondTheLimit_isRefusedWithTheFigures();
};

void TestChainSession::urdfScenario_takesLimitsEstimateAndTruthFromTheRobot()
{
    const Scenario requested = doublePendulum();
    const auto model = makeRobotModel(requested.model, requested.urdf);
    const auto *chain = dynamic_cast<const ChainModel *>(model.get());
    QVERIFY(chain);
    const Scenario s = withRobotDefaults(requested, *model);
    LEARNID_COMPARE_MATRIX(s.torqueLimits, Eigen::Vector2d(10, 10), 0.0); // the URDF's efforts
    LEARNID_COMPARE_MATRIX(s.initialParameters, chain->baseFromStandard(chain->cadStandard()), 0.0);
    // The truth differs from the CAD by at most 30 % per standard parameter, and not by 0.
    QCOMPARE(s.simulation.trueParameters.size(), model->parameterCount());
    QVERIFY((s.simulation.trueParameters - s.initialParameters).norm() > 0.0);
    // Given vectors stay.
    Scenario given = requested;
    given.torqueLimits = Eigen::Vector2d(3, 2);
    QCOMPARE(withRobotDefaults(given, *model).torqueLimits, given.torqueLimits);
}

void TestChainSession::realUrdf_mustHaveTheRobotsJoints()
{
    Scenario s = doublePendulum();
    s.simulation.realUrdf = QStringLiteral(":/robots/puma560.urdf");
    const auto model = makeRobotModel(s.model, s.urdf);
    try {
        withRobotDefaults(s, *model);
        QFAIL("a 6-axis real robot for a 2-axis model was accepted");
    } catch (const Error &e) {
        QVERIFY2(e.message().startsWith(QLatin1String("simulation.realUrdf: ")) &&
                     e.message().contains(QLatin1String("6 moving joints")),
                 qPrintable(e.message()));
    }
    // Its own URDF as the real robot is refused: link 2's published inertia (negative about
    // the joint's own centre of mass) is no body, link 1 is a needle.
    s.simulation.realUrdf = QStringLiteral(":/robots/double-pendulum.urdf");
    try {
        withRobotDefaults(s, *model);
        QFAIL("the double pendulum's negative inertia was accepted as a real robot");
    } catch (const Error &e) {
        QVERIFY2(e.message().startsWith(QLatin1String("simulation.realUrdf: :/robots/"
                                                      "double-pendulum.urdf is not a robot that "
                                                      "could be built: ")) &&
                     e.message().contains(QLatin1String("link 2 (link2): no mass distribution "
                                                        "has its inertia")) &&
                     e.message().contains(QLatin1String("link 1 (link1): its smallest principal "
                                                        "moment")),
                 qPrintable(e.message()));
    }
}

void TestChainSession::realUrdf_ownCadOrImplausibleIdentified()
{
    const QString cad = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    const QString flobaroid =
        test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4_identified.urdf"));
    if (cad.isEmpty() || flobaroid.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    Scenario s = doublePendulum();
    s.model = QStringLiteral("urdf");
    s.urdf.file = cad;
    const auto model = makeRobotModel(s.model, s.urdf);
    // The CAD robot as its own real robot: plausible, the truth is the CAD.
    s.simulation.realUrdf = cad;
    const Scenario resolved = withRobotDefaults(s, *model);
    LEARNID_COMPARE_MATRIX(resolved.simulation.trueParameters, resolved.initialParameters, 0.0);
    // FloBaRoID's identification: inertias no mass distribution has (written about the centre
    // of mass, they break the triangle inequality) and negative Coulomb friction, each named.
    s.simulation.realUrdf = flobaroid;
    try {
        withRobotDefaults(s, *model);
        QFAIL("FloBaRoID's implausible URDF was accepted as a real robot");
    } catch (const Error &e) {
        const QString m = e.message();
        QVERIFY2(m.startsWith(QLatin1String("simulation.realUrdf: ")) &&
                     m.contains(QLatin1String("is not a robot that could be built")) &&
                     m.contains(QLatin1String("link 1 (lwr_1_link): no mass distribution has "
                                              "its inertia")) &&
                     m.contains(QLatin1String("joint 4 (lwr_3_joint): <dynamics friction> is "
                                              "-0.39, negative")),
                 qPrintable(m));
    }
}

void TestChainSession::doublePendulum_learnsThePathTorquesFromThePerturbedCad()
{
    const Outcome o = runSession(doublePendulum(), 3);
    QVERIFY2(o.pathTorqueErrorPercent[0] > 5.0, "the perturbation must matter");
    QVERIFY2(o.pathTorqueErrorPercent[3] < 0.5,
             qPrintable(QString::number(o.pathTorqueErrorPercent[3])));
    for (int j = 0; j < 2; ++j)
        QVERIFY(o.maxTrackingErrorDeg[3][j] < 0.1 * o.maxTrackingErrorDeg[0][j]);
}

void TestChainSession::kukaLwr4_learnsThePathTorquesOfSevenAxes()
{
    const QString urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (urdf.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    Scenario s = doublePendulum();
    s.model = QStringLiteral("urdf");
    s.urdf.file = urdf;
    s.path.waypoints = {(Eigen::VectorXd(7) << 0, 0.3, 0, -1.2, 0, 0.5, 0).finished(),
                        (Eigen::VectorXd(7) << 0.8, 0.8, 0.5, -0.6, 0.6, -0.4, 0.9).finished(),
                        (Eigen::VectorXd(7) << -0.4, 0.5, -0.5, -1.4, -0.5, 0.6, -0.7).finished()};
    s.planningFraction = 0.3;
    // PID from the CAD inertia along the path, about 15 rad/s, damped.
    s.controller.kp = (Eigen::VectorXd(7) << 340, 600, 100, 140, 15, 14, 11).finished();
    s.controller.ki = s.controller.kp / 10.0;
    s.controller.kd = (Eigen::VectorXd(7) << 45, 80, 14, 19, 2, 1.9, 1.5).finished();
    s.simulation.seed = 3;
    const Outcome o = runSession(s, 2);
    QVERIFY2(o.pathTorqueErrorPercent[0] > 5.0, "the perturbation must matter");
    QVERIFY2(o.pathTorqueErrorPercent[2] < 1.0,
             qPrintable(QString::number(o.pathTorqueErrorPercent[2])));
    QVERIFY(o.maxTrackingErrorDeg[2].maxCoeff() < 0.3 * o.maxTrackingErrorDeg[0].maxCoeff());
}

void TestChainSession::panda_learnsThePathTorquesOfSevenAxes()
{
    // The built-in Panda from Franka's ready pose through two poses within its limits. The
    // shoulder (joint 2) stays leaned back: at q2 = 0 joints 1 and 3 line up, and gains from the
    // inertia's diagonal overdrive the coupled direction (a path through q2 = 0.5 is refused as
    // unstable). The bent elbow (joint 4) keeps gravity at the shoulder within the planning
    // fraction of its 87 N m; wrist joint 6 stays near pi/2, away from 0 and pi where joints 5
    // and 7 line up. PID from the CAD inertia along the path at 15 rad/s, critically damped.
    Scenario s = doublePendulum();
    s.model = QStringLiteral("panda");
    s.path.waypoints = {
        (Eigen::VectorXd(7) << 0, -M_PI / 4, 0, -3 * M_PI / 4, 0, M_PI / 2, M_PI / 4).finished(),
        (Eigen::VectorXd(7) << 0.6, -0.45, 0.4, -2.0, 0.5, 1.4, -0.2).finished(),
        (Eigen::VectorXd(7) << -0.6, -1.0, -0.4, -2.7, -0.5, 1.9, 1.4).finished()};
    s.planningFraction = 0.3;
    const Eigen::VectorXd inertia =
        largestCadInertia(*makeRobotModel(s.model, s.urdf), s.path.waypoints);
    s.controller.kp = inertia * 15.0 * 15.0;
    s.controller.ki = s.controller.kp / 10.0;
    s.controller.kd = inertia * 2.0 * 15.0;
    s.simulation.seed = 3;
    const Outcome o = runSession(s, 2);
    qInfo("panda: path-torque error %.3f %% -> %.3f %% -> %.3f %%, tracking %.4f -> %.4f deg",
          o.pathTorqueErrorPercent[0], o.pathTorqueErrorPercent[1], o.pathTorqueErrorPercent[2],
          o.maxTrackingErrorDeg[0].maxCoeff(), o.maxTrackingErrorDeg[2].maxCoeff());
    QVERIFY2(o.pathTorqueErrorPercent[0] > 5.0, "the perturbation must matter");
    QVERIFY2(o.pathTorqueErrorPercent[2] < 1.0,
             qPrintable(QString::number(o.pathTorqueErrorPercent[2])));
    QVERIFY(o.maxTrackingErrorDeg[2].maxCoeff() < 0.3 * o.maxTrackingErrorDeg[0].maxCoeff());
}

void TestChainSession::
    inconsistentEstimate_isReportedAndItsNearestConsistentOneKeepsThePathTorques()
{
    // The PUMA 560 along a waypoint path; the estimate: the CAD with link 3's inertia about x
    // made far too large (no body has Ixx > Iyy + Izz about its centre of mass).
    Scenario s = doublePendulum();
    s.model = QStringLiteral("puma560");
    s.path.waypoints = {Eigen::VectorXd::Zero(6), Eigen::VectorXd::Constant(6, 0.6)};
    const auto model = makeRobotModel(s.model, s.urdf);
    const auto *chain = dynamic_cast<const ChainModel *>(model.get());
    QVERIFY(chain);
    const TrialPlanner planner(withRobotDefaults(s, *model), model);
    const JointTrajectory path =
        planner.plan(chain->baseFromStandard(chain->cadStandard())).desired;

    Eigen::VectorXd pi = chain->cadStandard();
    pi[0] = 1.0; // the published link 1 has no mass: give it one so that only link 3 is wrong
    const Eigen::VectorXd consistentPhi = chain->baseFromStandard(pi);
    pi[24] += 5.0; // Ixx of link 3
    const Eigen::VectorXd phi = chain->baseFromStandard(pi);

    const EstimateConsistency bad = checkEstimateConsistency(*model, phi, path);
    QVERIFY(bad.applicable);
    QVERIFY(!bad.consistent);
    QVERIFY2(bad.nearestError.isEmpty(), qPrintable(bad.nearestError));
    const QStringList lines = bad.describe(*model);
    QVERIFY2(lines.join(QLatin1Char(' ')).contains(QLatin1String("link 3 (link3)")),
             qPrintable(lines.join(QLatin1Char('|'))));
    // The nearest estimate describes real bodies: standard parameters with its base parameters
    // whose every link is consistent ...
    LEARNID_COMPARE_MATRIX(chain->baseFromStandard(bad.nearestStandard), bad.nearest, 1e-12);
    for (const LinkConsistency &l : checkConsistency(bad.nearestStandard, 6, 1e-9))
        QVERIFY2(l.consistent, qPrintable(QString::number(l.link)));
    QVERIFY(negativeJointTerms(bad.nearestStandard, chain->nonnegativeStandard()).empty());
    // ... and its torques on the path are no further from phi's than the consistent
    // estimate we broke (an independent consistent candidate).
    const auto pathError = [&](const Eigen::VectorXd &x) {
        return pathTorqueErrorPercent(*model, path, x, phi);
    };
    QVERIFY2(
        pathError(bad.nearest) <= pathError(consistentPhi) + 1e-9,
        qPrintable(
            QStringLiteral("%1 vs %2").arg(pathError(bad.nearest)).arg(pathError(consistentPhi))));
    LEARNID_COMPARE_NEAR(bad.pathTorqueChangePercent, pathError(bad.nearest), 1e-6);
    // A consistent estimate is reported so, and kept.
    const EstimateConsistency good = checkEstimateConsistency(*model, consistentPhi, path);
    QVERIFY(good.consistent);
    LEARNID_COMPARE_MATRIX(good.nearest, consistentPhi, 0.0);
}

void TestChainSession::pathBeyondTheUrdfsJointLimits_isRefusedBeforeMotion()
{
    // The PUMA 560's joint 1 turns +-160 deg (2.7925 rad, its URDF): a waypoint at 2.9 rad is
    // refused, naming the joint; inside the limits the same check passes them.
    Scenario s = doublePendulum();
    s.model = QStringLiteral("puma560");
    s.controller.kp = Eigen::VectorXd::Constant(6, 200.0);
    s.controller.ki = Eigen::VectorXd::Constant(6, 10.0);
    s.controller.kd = Eigen::VectorXd::Constant(6, 20.0);
    const auto model = makeRobotModel(s.model, s.urdf);
    Eigen::VectorXd far = Eigen::VectorXd::Zero(6);
    far[0] = 2.9;
    s.path.waypoints = {Eigen::VectorXd::Zero(6), far};
    s = withRobotDefaults(s, *model);
    const TrialPlan beyond = TrialPlanner(s, model).plan(s.initialParameters);
    LEARNID_COMPARE_NEAR(beyond.positionUpper[0], 160.0 * M_PI / 180.0, 1e-4);
    const SafetyVerdict refused = checkTrial(*model, s.initialParameters, beyond);
    QVERIFY(!refused.withinJointLimits);
    QVERIFY(!refused.passed());
    QVERIFY2(refused.reason.startsWith(QLatin1String("joint 1 would reach ")) &&
                 refused.reason.contains(QLatin1String("outside its limits -2.7925 to 2.7925")),
             qPrintable(refused.reason));

    far[0] = 2.7;
    s.path.waypoints = {Eigen::VectorXd::Zero(6), far};
    TrialPlan inside = TrialPlanner(s, model).plan(s.initialParameters);
    QVERIFY(checkTrial(*model, s.initialParameters, inside).withinJointLimits);
    // A speed limit below the planned peak speed of joint 1 is refused the same way.
    const double peak = inside.desired.qd.row(0).cwiseAbs().maxCoeff();
    inside.velocityLimit[0] = 0.9 * peak;
    const SafetyVerdict tooFast = checkTrial(*model, s.initialParameters, inside);
    QVERIFY2(tooFast.reason.startsWith(QLatin1String("joint 1 would move at ")) &&
                 tooFast.reason.contains(QLatin1String("above its speed limit")),
             qPrintable(tooFast.reason));
}

void TestChainSession::identifiability_namesWhatThePathCannotSee()
{
    // The double pendulum with its elbow held: the elbow's friction never acts (q2' = 0), so
    // the path cannot see it; the shoulder's Coulomb friction it sees.
    Scenario s = doublePendulum();
    s.path.waypoints = {Eigen::Vector2d(0, 0.3), Eigen::Vector2d(1.0, 0.3),
                        Eigen::Vector2d(-0.5, 0.3)};
    const auto model = makeRobotModel(s.model, s.urdf);
    const Scenario resolved = withRobotDefaults(s, *model);
    const CommissioningSession session(resolved, model, makeSimulatedRobot(resolved, model));
    const PathIdentifiability id = session.identifiability();
    QCOMPARE(id.parameters, model->parameterCount());
    QVERIFY(id.rank > 0 && id.rank < id.parameters);
    QStringList unseen;
    for (const int i : id.unseen())
        unseen << model->parameters()[i].name;
    QVERIFY2(unseen.contains(QStringLiteral("fc₂")), qPrintable(unseen.join(QLatin1Char(','))));
    QVERIFY2(!unseen.contains(QStringLiteral("fc₁")), qPrintable(unseen.join(QLatin1Char(','))));
    QVERIFY(id.describe(*model).join(QLatin1Char(' ')).contains(QStringLiteral("fc₂")));
}

void TestChainSession::gravityAloneBeyondTheLimit_isRefusedWithTheFigures()
{
    // The double pendulum held out horizontally: its shoulder must hold m1 g r1 + m2 g (l1 + r2)
    // (the lab's figures, written out here), more than half of a 1 N m limit at any speed.
    Scenario s = doublePendulum();
    s.path.waypoints = {Eigen::Vector2d(M_PI / 2, 0), Eigen::Vector2d(M_PI / 2 + 0.1, 0)};
    s.torqueLimits = Eigen::Vector2d(1, 1);
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    const double holding =
        0.6416937799349799 * 9.81 * 0.2 + 0.563935954099688 * 9.81 * (0.2 + 0.3212669909674605);
    try {
        TrialPlanner(s, model).plan(s.initialParameters);
        QFAIL("a path gravity alone cannot hold was planned");
    } catch (const Error &e) {
        QVERIFY2(e.message().startsWith(QLatin1String("gravity alone needs ")) &&
                     e.message().contains(QLatin1String("at joint 1 on this path, more than 50 % "
                                                        "of its 1 N m limit")),
                 qPrintable(e.message()));
        const double stated = e.message().section(QLatin1Char(' '), 3, 3).toDouble();
        LEARNID_COMPARE_NEAR(stated, holding, 0.02 * holding); // the CAD's figure, at +-0.05 rad
    }
}

QTEST_GUILESS_MAIN(TestChainSession)
#include "tst_chainsession.moc"
