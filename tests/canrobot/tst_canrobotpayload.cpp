// A payload session (PayloadSession) on CanRobot, the threaded front of the CAN robot, against
// the robot simulator (learnid_cansim) on the memory bus, the simulated drives carrying the
// scenario's payload (canArmSettings: simulation.payload on its link's body): the Panda with
// 1.5 kg 5 cm off the flange axis learns the same payload over CAN as the same session on
// SimulatedRobot, and the payload itself within the 1 % and 3 mm.
#include "../session/PayloadScenarios.h"
#include "CanSimRig.h"
#include "canrobot/CanRobot.h"
#include "model/ModelFactory.h"
#include "session/PayloadSession.h"
#include "session/ScenarioRobot.h"

#include <QTest>

using namespace learnid;

namespace {

CanRobotOptions memoryOptions(const QList<int> &nodes)
{
    CanRobotOptions o;
    o.plugin = QStringLiteral("memory");
    o.interface = QStringLiteral("can0");
    o.nodes = nodes;
    return o;
}

const PayloadBody &lastBody(const PayloadSession &session)
{
    return session.history().back().fit->estimate.body;
}

} // namespace

class TestCanRobotPayload : public QObject
{
    Q_OBJECT

private slots:
    void payloadSession_learnsOverCanAsOnTheSimulatedRobot()
    {
        // SYNC every 4 ms: seven nodes at 2 ms would need 98 % of a 1 Mbit/s bus.
        Scenario given = test::pandaWithPayload();
        given.controller.samplePeriod = 0.004;
        const auto model = makeRobotModel(given.model, given.urdf);
        QVERIFY(model);
        const Scenario scenario = withRobotDefaults(given, *model);
        const QList<int> nodes{1, 2, 3, 4, 5, 6, 7};
        CanRobotOptions options = memoryOptions(nodes);
        setSyncPeriod(options, scenario.controller.samplePeriod);
        auto can = std::make_shared<CanRobot>(
            model, options, test::canSimFactory(canArmSettings(scenario, model, nodes)));
        PayloadSession onCan(scenario, model, can);
        QVERIFY2(onCan.runTrials(scenario.iterations), qPrintable(onCan.history().back().message));
        PayloadSession onSim(scenario, model, makeSimulatedRobot(scenario, model));
        QVERIFY(onSim.runTrials(scenario.iterations));

        const PayloadBody &c = lastBody(onCan);
        const PayloadBody &s = lastBody(onSim);
        qInfo("CAN %.4f kg, CoM (%.2f, %.2f, %.2f) mm; simulated %.4f kg, (%.2f, %.2f, %.2f) mm",
              c.mass, 1e3 * c.com.x(), 1e3 * c.com.y(), 1e3 * c.com.z(), s.mass, 1e3 * s.com.x(),
              1e3 * s.com.y(), 1e3 * s.com.z());
        // The drives' payload is the scenario's: the CAN session learns it as the simulated one
        // does, mass and centre of mass within four standard errors of the difference (the
        // fits' own; the two robots' noise draws and the bus's quantisation differ).
        const PayloadEstimate &ce = onCan.history().back().fit->estimate;
        const PayloadEstimate &se = onSim.history().back().fit->estimate;
        for (int i = 0; i < 4; ++i) {
            const double sigma = std::hypot(ce.bodyStandardError[i], se.bodyStandardError[i]);
            QVERIFY2(sigma > 0.0 && std::abs(ce.bodyValue[i] - se.bodyValue[i]) < 4.0 * sigma,
                     qPrintable(QStringLiteral("%1: %2 against %3 (sigma %4)")
                                    .arg(PayloadEstimate::bodyNames()[i])
                                    .arg(ce.bodyValue[i])
                                    .arg(se.bodyValue[i])
                                    .arg(sigma)));
        }
        // ... and the payload the drives carry.
        const SimulatedPayload &real = scenario.simulation.payload;
        QVERIFY2(std::abs(c.mass - real.mass) < 0.01 * real.mass,
                 qPrintable(QString::number(c.mass)));
        QVERIFY2((c.com - real.com).norm() < 3e-3, qPrintable(QString::number(c.com.x())));
        QCOMPARE(can->lastTrialStatistics().lateSetpoints, 0);
        QVERIFY(!can->trueParameters().has_value());
    }
};

QTEST_GUILESS_MAIN(TestCanRobotPayload)
#include "tst_canrobotpayload.moc"
