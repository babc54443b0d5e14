// The smallest change of a payload session's path that lets it measure what it misses
// (smallestPayloadPathChange, docs/payload.md "Identifiability before motion"), on the simulated
// Panda whose flange points straight down (its ready pose):
//  - only joint 7 turns: the payload turns about the vertical flange axis, so gravity never
//    acts across m cz, and tilting the wrist a little is enough;
//  - only the base turns: what is missing is the inertia about the flange's horizontal axes,
//    which no single joint's change at one waypoint measures above the noise in the first,
//    gentle trial.
#include "PayloadScenarios.h"
#include "model/ModelFactory.h"
#include "session/PayloadSession.h"
#include "session/ScenarioRobot.h"

#include <QTest>

using namespace learnid;

namespace {

// pandaWithPayload() on two waypoints of the ready pose that differ in joint `joint` only.
Scenario turningOnly(int joint, double from, double to)
{
    Scenario s = test::pandaWithPayload();
    const Eigen::VectorXd ready = test::jointValues({0, -0.785, 0, -2.356, 0, 1.571, 0.785});
    s.path.waypoints = {ready, ready};
    s.path.waypoints[0][joint] = from;
    s.path.waypoints[1][joint] = to;
    return s;
}

std::unique_ptr<PayloadSession> sessionFor(Scenario s)
{
    const auto model = makeRobotModel(s.model, s.urdf);
    s = withRobotDefaults(s, *model);
    return std::make_unique<PayloadSession>(s, model, makeSimulatedRobot(s, model));
}

// Parameter p identified by the session's next path and predicted to within its scale at 1 %
// torque noise.
bool measures(const PayloadSession &session, int p)
{
    const Eigen::Matrix<double, 10, 1> errors =
        payloadPredictedStdErrors(session.payloadModel(), session.checkNextTrial().plan.desired,
                                  0.01 * session.scenario().torqueLimits);
    return session.observability().identified(p) &&
           errors[p] <= payloadParameterScale(session.prior())[p];
}

} // namespace

class TestPayloadPathChange : public QObject
{
    Q_OBJECT

private slots:
    void wristTurn_isOfferedTheSmallestTiltThatMeasuresTheCentreOfMass()
    {
        const Scenario s = turningOnly(6, -0.4, 1.6);
        const auto session = sessionFor(s);
        const PayloadObservability before = session->observability();
        QVERIFY(!before.identified(3)); // m cz: along the vertical flange axis
        QVERIFY(!measures(*session, 3));
        const PayloadPathChange change = session->pathChange();
        QVERIFY(change.valid());
        QVERIFY(change.measured[3]);
        const ChainJoint &joint =
            session->payloadModel().arm().chain().joints[size_t(change.joint)];
        QVERIFY(change.joint >= 4); // one of the three joints nearest the flange link
        QCOMPARE(change.value,
                 s.path.waypoints[size_t(change.waypoint)][change.joint] + change.change);
        QVERIFY(change.value > joint.lower + 0.05 && change.value < joint.upper - 0.05);
        qInfo("%s", qPrintable(change.describe(session->payloadModel().arm())));
        QVERIFY(change.describe(session->payloadModel().arm())
                    .startsWith(QStringLiteral("moving %1 at waypoint %2 by %3 rad (to %4 rad, "
                                               "inside its limits) would let the trials measure ")
                                    .arg(joint.name)
                                    .arg(change.waypoint + 1)
                                    .arg(change.change, 0, 'f', 2)
                                    .arg(change.value, 0, 'f', 3)));

        // The changed scenario, planned anew by a session of its own, measures m cz; run, it
        // learns the centre of mass to within 3 mm, its standard error within that scale.
        Scenario changed = s;
        changed.path.waypoints[size_t(change.waypoint)][change.joint] = change.value;
        const auto after = sessionFor(changed);
        QVERIFY(measures(*after, 3));
        QVERIFY2(after->runTrials(3), qPrintable(after->history().back().message));
        const PayloadEstimate &e = after->history().back().fit->estimate;
        QVERIFY(e.bodyIdentified[3]);
        QVERIFY2(std::abs(e.body.com.z() - 0.08) < 0.003,
                 qPrintable(QString::number(e.body.com.z())));
        QVERIFY2(e.bodyStandardError[3] < 0.003,
                 qPrintable(QString::number(e.bodyStandardError[3])));
        // No smaller step of the search, of any of the three joints at either waypoint, does.
        for (double step : {0.05, 0.1, 0.2, 0.3, 0.5}) {
            if (step >= std::abs(change.change))
                break;
            for (int j = 4; j < 7; ++j) {
                const ChainJoint &limits = session->payloadModel().arm().chain().joints[size_t(j)];
                for (size_t w = 0; w < 2; ++w) {
                    for (double d : {-step, step}) {
                        Scenario smaller = s;
                        smaller.path.waypoints[w][j] += d;
                        const double v = smaller.path.waypoints[w][j];
                        if (v < limits.lower + 0.05 || v > limits.upper - 0.05)
                            continue;
                        QVERIFY2(!measures(*sessionFor(smaller), 3),
                                 qPrintable(QStringLiteral("joint %1, waypoint %2, %3 rad")
                                                .arg(j)
                                                .arg(w)
                                                .arg(d)));
                    }
                }
            }
        }
    }

    void baseTurn_isOfferedNothing_asNoJointAloneMeasuresTheInertia()
    {
        const Scenario s = turningOnly(0, -0.6, 0.6);
        const auto session = sessionFor(s);
        const PayloadObservability before = session->observability();
        for (int p : {4, 5, 6}) // Ixx, Ixy, Iyy about the flange
            QVERIFY(!before.identified(p));
        for (int p : {0, 1, 2, 3})
            QVERIFY(before.identified(p));
        QVERIFY(!session->pathChange().valid());
        // The largest changes searched, each of the three joints by a full radian either way at
        // either waypoint, measure none of them above the noise (the first trial is a gentle
        // one, at half speed).
        for (int j = 4; j < 7; ++j) {
            const ChainJoint &limits = session->payloadModel().arm().chain().joints[size_t(j)];
            for (size_t w = 0; w < 2; ++w) {
                for (double d : {-1.0, 1.0}) {
                    Scenario tilted = s;
                    tilted.path.waypoints[w][j] += d;
                    const double v = tilted.path.waypoints[w][j];
                    if (v < limits.lower + 0.05 || v > limits.upper - 0.05)
                        continue;
                    const auto other = sessionFor(tilted);
                    for (int p : {4, 5, 6})
                        QVERIFY2(!measures(*other, p),
                                 qPrintable(QStringLiteral("joint %1, waypoint %2, %3 rad: %4")
                                                .arg(j)
                                                .arg(w)
                                                .arg(d)
                                                .arg(p)));
                }
            }
        }
    }

    void aPathThatSeesAll_isOfferedNothing()
    {
        const auto session = sessionFor(test::pandaWithPayload());
        QCOMPARE(session->observability().rank, 10);
        QVERIFY(!session->pathChange().valid());
    }
};

QTEST_GUILESS_MAIN(TestPayloadPathChange)
#include "tst_payloadpathchange.moc"
