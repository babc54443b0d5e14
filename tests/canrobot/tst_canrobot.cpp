// CanRobot, the threaded front, against the robot simulator (learnid_cansim) over the memory
// bus: a session on it identifies what the same session on SimulatedRobot identifies, and a
// trial's candump log replayed gives the very same record and estimate.
#include "../support/RotorScenario.h"
#include "CanSimRig.h"
#include "canrobot/CanRobot.h"
#include "canrobot/CandumpReplayDevice.h"
#include "model/ModelFactory.h"
#include "session/CommissioningSession.h"
#include "session/ScenarioRobot.h"
#include "session/ScenarioRobotJoints.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

using namespace learnid;

namespace {

Scenario shortScenario()
{
    Scenario s;
    s.iterations = 2;
    return s;
}

CanRobotOptions memoryOptions(const QString &logDir = {})
{
    CanRobotOptions o;
    o.plugin = QStringLiteral("memory");
    o.interface = QStringLiteral("can0");
    o.candumpDir = logDir;
    return o;
}

double largestRelativeDifference(const Eigen::VectorXd &a, const Eigen::VectorXd &b)
{
    return ((a - b).cwiseAbs().array() / b.cwiseAbs().array()).maxCoeff();
}

} // namespace

class TestCanRobot : public QObject
{
    Q_OBJECT

private slots:
    void session_identifiesAsOnSimulatedRobot();
    void jointTorqueSensor_learnsTheRotorAsOnSimulatedRobot();
    void replay_asRecordedPausedOrSilent_endsAsRecorded_data();
    void replay_asRecordedPausedOrSilent_endsAsRecorded();
    void unreachableDevice_failsWithinTheConnectTimeout();
};

void TestCanRobot::session_identifiesAsOnSimulatedRobot()
{
    const Scenario scenario = shortScenario();
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    const QList<int> nodes{1, 2};
    auto can = std::make_shared<CanRobot>(
        model, memoryOptions(), test::canSimFactory(canArmSettings(scenario, model, nodes)));
    CommissioningSession onCan(scenario, model, can);
    QVERIFY2(onCan.runTrials(scenario.iterations), qPrintable(onCan.history().constLast().message));
    CommissioningSession onSim(scenario, model, makeSimulatedRobot(scenario, model));
    QVERIFY(onSim.runTrials(scenario.iterations));
    const Eigen::VectorXd phiCan = onCan.currentEstimate();
    const Eigen::VectorXd phiSim = onSim.currentEstimate();
    qInfo("CAN %.6f %.6f %.6f, sim %.6f %.6f %.6f, largest difference %.3g %%", phiCan[0],
          phiCan[1], phiCan[2], phiSim[0], phiSim[1], phiSim[2],
          100 * largestRelativeDifference(phiCan, phiSim));
    // The bus quantises positions to 2^24 increments and torques to limit / 25000; the
    // estimate moves by far less than 0.5 % for that (docs/can-protocol.md, "Master side").
    QVERIFY(largestRelativeDifference(phiCan, phiSim) < 5e-3);
    QVERIFY(!can->trueParameters().has_value());
    QCOMPARE(can->lastTrialStatistics().lateSetpoints, 0);
}

void TestCanRobot::jointTorqueSensor_learnsTheRotorAsOnSimulatedRobot()
{
    // The drives run the PIDs the tool reconstructs the command with, on the angles they report;
    // the offset reaches them rounded to per mille of the rated torque.
    Scenario scenario = test::behindAJointSensor(1.0);
    scenario.estimator.jointTorqueSensor = true;
    scenario.iterations = 2;
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    scenario = withRobotDefaults(scenario, *model);
    const Eigen::VectorXd rotor = simulatedJoints(scenario, *model).armature;
    auto can = std::make_shared<CanRobot>(
        model, memoryOptions(), test::canSimFactory(canArmSettings(scenario, model, {1, 2})));
    CommissioningSession onCan(scenario, model, can);
    QVERIFY2(onCan.runTrials(scenario.iterations), qPrintable(onCan.history().constLast().message));
    CommissioningSession onSim(scenario, model, makeSimulatedRobot(scenario, model));
    QVERIFY(onSim.runTrials(scenario.iterations));
    const TrialPlan &plan = onSim.history().constLast().plan();
    const double errorCan = test::motorTorqueError(*model, plan, onCan.currentEstimate(),
                                                   scenario.simulation.trueParameters, rotor);
    const double errorSim = test::motorTorqueError(*model, plan, onSim.currentEstimate(),
                                                   scenario.simulation.trueParameters, rotor);
    qInfo("motor-torque error on the path: CAN %.3f %%, simulated robot %.3f %%", 100 * errorCan,
          100 * errorSim);
    QVERIFY(errorSim < 0.01);
    QVERIFY(errorCan < 0.02);
}

void TestCanRobot::replay_asRecordedPausedOrSilent_endsAsRecorded_data()
{
    QTest::addColumn<qint64>("silentAfterFrames");
    QTest::addColumn<int>("stallAtWrite");
    // A recorded session replayed: the very same records and estimate.
    QTest::newRow("as recorded") << qint64(-1) << -1;
    // The recorded session completes; its replay's master pauses 1 s mid-trial (the live waits:
    // heartbeat 300 ms, SYNC 50 ms), as a loaded machine once did to a replay in the VM of
    // scripts/test-socketcan.
    QTest::newRow("master paused") << qint64(-1) << 1500;
    // The robot side fell silent in trial 0: the replay ends there as the session did.
    QTest::newRow("robot silent") << qint64(2500) << -1;
}

void TestCanRobot::replay_asRecordedPausedOrSilent_endsAsRecorded()
{
    QFETCH(qint64, silentAfterFrames);
    QFETCH(int, stallAtWrite);
    QTemporaryDir dir;
    const Scenario scenario = shortScenario();
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    CanSimFaults faults;
    faults.silentAfterFrames = silentAfterFrames;
    auto live = std::make_shared<CanRobot>(
        model, memoryOptions(dir.path()),
        test::canSimFactory(canArmSettings(scenario, model, {1, 2}), faults));
    CommissioningSession recorded(scenario, model, live);
    const bool completed = recorded.runTrials(scenario.iterations);
    QCOMPARE(completed, silentAfterFrames < 0);
    const QString ending = recorded.history().constLast().message;
    QVERIFY2(completed || ending.contains(QLatin1String("no SYNC")), qPrintable(ending));

    QList<CandumpEntry> entries;
    for (int k = 0; k < recorded.history().size(); ++k)
        entries += candump::readFile(
            dir.filePath(QStringLiteral("trial-%1.log").arg(k, 3, 10, QLatin1Char('0'))));
    QVERIFY(entries.size() > (completed ? 10000 : 1000));
    // The master's thread stops for 1 s in its stallAtWrite-th frame.
    class Pausing : public CandumpReplayDevice
    {
    public:
        Pausing(QList<CandumpEntry> entries, int pauseAt)
            : CandumpReplayDevice(std::move(entries))
            , m_pauseAt(pauseAt)
        {}
        bool writeFrame(const QCanBusFrame &frame) override
        {
            if (++m_writes == m_pauseAt)
                QThread::msleep(1000);
            return CandumpReplayDevice::writeFrame(frame);
        }

    private:
        int m_pauseAt;
        int m_writes = 0;
    };
    auto replay = std::make_shared<CanRobot>(
        model, replayOptions(memoryOptions()),
        [entries, stallAtWrite](QString *) { return new Pausing(entries, stallAtWrite); });
    CommissioningSession replayed(scenario, model, replay);
    QCOMPARE(replayed.runTrials(scenario.iterations), completed);
    QCOMPARE(replayed.history().size(), recorded.history().size());
    for (int k = 0; k < recorded.history().size(); ++k) {
        QCOMPARE(replayed.history()[k].record.status, recorded.history()[k].record.status);
        QCOMPARE(replayed.history()[k].record.q, recorded.history()[k].record.q);
        QCOMPARE(replayed.history()[k].record.tau, recorded.history()[k].record.tau);
    }
    const QString replayEnding = replayed.history().constLast().message;
    QVERIFY2(completed || replayEnding.contains(QLatin1String("no SYNC")),
             qPrintable(replayEnding));
    QCOMPARE(replayed.currentEstimate(), recorded.currentEstimate());
}

void TestCanRobot::unreachableDevice_failsWithinTheConnectTimeout()
{
    // A device that stays "connecting", as virtualcan does on an unreachable host.
    class NeverConnects : public QCanBusDevice
    {
    public:
        bool writeFrame(const QCanBusFrame &) override { return false; }
        QString interpretErrorFrame(const QCanBusFrame &) override { return {}; }

    protected:
        bool open() override { return true; }
        void close() override { setState(UnconnectedState); }
    };
    CanRobotOptions options = memoryOptions();
    options.connectTimeoutMs = 300;
    CanRobot robot(makeRobotModel(QStringLiteral("paper-2link")), options,
                   [](QString *) { return new NeverConnects; });
    QElapsedTimer clock;
    clock.start();
    const QString error = robot.connectBus();
    QVERIFY2(error.contains(QLatin1String("did not connect within 300 ms")), qPrintable(error));
    QVERIFY2(clock.elapsed() >= 290 && clock.elapsed() < 2000,
             qPrintable(QString::number(clock.elapsed())));
}

QTEST_GUILESS_MAIN(TestCanRobot)
#include "tst_canrobot.moc"
