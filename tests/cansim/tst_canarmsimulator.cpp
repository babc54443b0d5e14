// CanArmSimulator: the robot side of the CAN link as a whole, stepped SYNC by SYNC over the memory
// bus; above all, driven with a plan's set-points it measures what SimulatedRobot measures.
#include "CanSimTestBus.h"
#include "can/Cia402.h"
#include "can/EmcyConsumer.h"
#include "can/SdoAbortCode.h"
#include "cansim/CanArmSimulator.h"
#include "cansim/ScenarioCanArm.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "robot/SimulatedRobot.h"
#include "session/ScenarioRobot.h"
#include "session/TrialPlanner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

using namespace learnid;
using canopen::DataType;

namespace {

struct Bus
{
    test::CanSimTestBus net;
    CanArmSimulator sim;

    explicit Bus(const CanArmSettings &settings, const CanSimFaults &faults = {})
        : sim(&net.slaveLink, settings, faults)
    {}
    void cycle()
    {
        sim.syncCycle();
        net.flush();
    }
    /// NMT start and the enable walk of every node, target = the measured position.
    void enable()
    {
        net.nmt(NmtCommand::Start, 0);
        for (const quint16 cw : {0x0006, 0x0007, 0x000F}) {
            for (int j = 0; j < sim.dof(); ++j) {
                const double inc = std::round(sim.arm().q()[j] / sim.node(j)->countAngle());
                net.rpdo(sim.node(j)->node(), inc, 0, cw);
            }
            cycle();
        }
    }
};

CanArmSettings paperSettings(const Scenario &scenario = {})
{
    return canArmSettings(scenario, makeRobotModel(scenario.model, scenario.urdf), {1, 2});
}

/// q [rad] and tau [N m] of every plan sample as the bus reports them: before SYNC k the
/// master sends sample k's target and feedforward; TPDO k answers.
TrialRecord runPlanOnBus(const Scenario &scenario, const TrialPlan &plan)
{
    CanArmSettings settings = paperSettings(scenario);
    settings.initialPose = plan.desired.q.col(0);
    Bus bus(settings);
    bus.enable();
    const int n = bus.sim.dof();
    const qsizetype before = bus.net.framesWithId(0x181).size();
    TrialRecord r;
    r.samplePeriod = plan.desired.samplePeriod;
    r.q.resize(n, plan.samples());
    r.tau.resize(n, plan.samples());
    for (int k = 0; k < plan.samples(); ++k) {
        for (int j = 0; j < n; ++j) {
            const DriveNode *d = bus.sim.node(j);
            bus.net.rpdo(d->node(), std::round(plan.desired.q(j, k) / d->countAngle()),
                         std::round(plan.feedforward(j, k) / d->torqueUnit()), 0x000F);
        }
        bus.cycle();
        for (int j = 0; j < n; ++j) {
            const DriveNode *d = bus.sim.node(j);
            const QList<double> tpdo = bus.net.lastTpdo(d->node());
            r.q(j, k) = tpdo.value(0) * d->countAngle();
            r.tau(j, k) = tpdo.value(1) * d->torqueUnit();
            if (!(quint16(tpdo.value(2)) & 0x1000))
                r.status = TrialStatus::Faulted; // a set-point not followed
        }
    }
    if (bus.net.framesWithId(0x181).size() - before != plan.samples())
        r.status = TrialStatus::Aborted;
    return r;
}

} // namespace

class TestCanArmSimulator : public QObject
{
    Q_OBJECT

private slots:
    void syncCounter_runsOneTo240AndWraps();
    void settings_startAtRestAtThePathStart();
    void syncCycle_sendsSyncFirstThenEachTpdo();
    void planOnTheEncoderGrid_measuresExactlyWhatSimulatedRobotMeasures();
    void realisticJoints_busMeasuresWhatSimulatedRobotMeasures();
    void paperPlan_matchesSimulatedRobotWithinTheBusResolution();
    void unpoweredJoint_isHeldByItsBrake();
    void dropFraction_losesThatShareOfTpdos_reproducibly();
    void silentAfter_sendsExactlyNFramesThenNothing();
    void emcyAtSample_faultsTheFirstNodeAtTheKthEnabledSync();
    void refusedSdo_abortsWritesThereOnEveryNode();
    void stateJson_listsEachNodesStoredParameters();
    void settingsThatDoNotFit_areRejected();
};

void TestCanArmSimulator::syncCounter_runsOneTo240AndWraps()
{
    SyncProducer sync;
    QCOMPARE(sync.counter(), quint8(0));
    for (int i = 1; i <= 240; ++i)
        QCOMPARE(sync.advance(), quint8(i));
    QCOMPARE(sync.advance(), quint8(1));
    const QCanBusFrame f = SyncProducer::frame(7);
    QCOMPARE(f.frameId(), 0x80u);
    QCOMPARE(f.payload(), QByteArray(1, '\x07'));
}

void TestCanArmSimulator::settings_startAtRestAtThePathStart()
{
    const Scenario scenario;
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    const CanArmSettings s = canArmSettings(scenario, model, {3, 4});
    const TrialPlan plan = TrialPlanner(scenario, model).plan(scenario.initialParameters);
    QVERIFY((s.initialPose - plan.desired.q.col(0)).cwiseAbs().maxCoeff() < 1e-15);
    Bus bus(s);
    QCOMPARE(bus.sim.node(0)->node(), quint8(3));
    QCOMPARE(bus.sim.arm().qd().norm(), 0.0);
    QCOMPARE(bus.sim.syncPeriodUs(), 2000u);
    QCOMPARE(bus.sim.node(1)->countAngle(), 2.0 * M_PI / double(1 << 24)); // ideal: 2^24
}

void TestCanArmSimulator::syncCycle_sendsSyncFirstThenEachTpdo()
{
    Bus bus(paperSettings());
    bus.sim.bootUp();
    bus.enable();
    bus.net.wire.clear();
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j)
            bus.net.rpdo(quint8(j + 1), 0, 0, 0x000F);
        bus.cycle();
    }
    QList<quint32> ids;
    for (const QCanBusFrame &f : bus.net.wire)
        ids << f.frameId();
    QCOMPARE(ids,
             (QList<quint32>{0x201, 0x202, 0x80, 0x181, 0x182, 0x201, 0x202, 0x80, 0x181, 0x182}));
    QCOMPARE(bus.net.framesWithId(0x80).last().payload(), QByteArray(1, '\x05')); // 3 enable SYNCs
    QCOMPARE(bus.sim.syncCount(), qint64(5));
}

void TestCanArmSimulator::planOnTheEncoderGrid_measuresExactlyWhatSimulatedRobotMeasures()
{
    // A plan whose targets and feedforward sit on the bus's integer grid: the bus adds no
    // rounding of its own, so the measured angles agree to the count and the torques to the
    // TPDO's resolution (half a per mille of rated torque).
    Scenario scenario;
    scenario.simulation.encoderCounts = qint64(1) << 24;
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    TrialPlan plan = TrialPlanner(scenario, model).plan(scenario.initialParameters);
    const double ca = 2.0 * M_PI / double(scenario.simulation.encoderCounts);
    plan.desired.q = (plan.desired.q / ca).array().round() * ca;
    for (int j = 0; j < 2; ++j) {
        const double unit = cansim::ratedTorqueFor(scenario.torqueLimits[j]) * 1e-6;
        plan.feedforward.row(j) = (plan.feedforward.row(j) / unit).array().round() * unit;
    }
    const TrialRecord expected = makeSimulatedRobot(scenario, model)->runTrial(plan, {});
    const TrialRecord bus = runPlanOnBus(scenario, plan);
    QVERIFY(expected.completed());
    QCOMPARE(bus.status, TrialStatus::Completed);
    QCOMPARE(bus.samples(), expected.samples());
    const double qDiff = (bus.q - expected.q).cwiseAbs().maxCoeff();
    const Eigen::Vector2d tauDiff = (bus.tau - expected.tau).cwiseAbs().rowwise().maxCoeff();
    qInfo("grid plan, %d samples: max |q diff| = %.3g counts, max |tau diff| = %.3g / %.3g mN m",
          bus.samples(), qDiff / ca, 1e3 * tauDiff[0], 1e3 * tauDiff[1]);
    QVERIFY(qDiff <= ca * 1.000001);
    QVERIFY(tauDiff[0] <= 0.5 * 320e-6 + 1e-9);
    QVERIFY(tauDiff[1] <= 0.5 * 160e-6 + 1e-9);
}

void TestCanArmSimulator::realisticJoints_busMeasuresWhatSimulatedRobotMeasures()
{
    // learnid-robot-sim serves the scenario's realistic joints (elastic, rotor inertia, sensor
    // offset and lag): on the grid plan the bus measures what SimulatedRobot measures, the
    // torque reading being the spring's and not the command.
    Scenario scenario;
    scenario.simulation.encoderCounts = qint64(1) << 24;
    scenario.simulation.armature = Eigen::Vector2d(2.0, 1.0);
    scenario.simulation.jointStiffness = Eigen::Vector2d(20000, 10000);
    scenario.simulation.jointDamping = Eigen::Vector2d(20, 10);
    scenario.simulation.torqueSensorOffset = Eigen::Vector2d(0.05, -0.02);
    scenario.simulation.torqueSensorLag = 0.001;
    scenario.simulation.linkSideEncoder = false; // the collocated loop: PID on the motor angle
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    TrialPlan plan = TrialPlanner(scenario, model).plan(scenario.initialParameters);
    const double ca = 2.0 * M_PI / double(scenario.simulation.encoderCounts);
    plan.desired.q = (plan.desired.q / ca).array().round() * ca;
    for (int j = 0; j < 2; ++j) {
        const double unit = cansim::ratedTorqueFor(scenario.torqueLimits[j]) * 1e-6;
        plan.feedforward.row(j) = (plan.feedforward.row(j) / unit).array().round() * unit;
    }
    const TrialRecord expected = makeSimulatedRobot(scenario, model)->runTrial(plan, {});
    const TrialRecord rigid = makeSimulatedRobot(Scenario{}, model)->runTrial(plan, {});
    const TrialRecord bus = runPlanOnBus(scenario, plan);
    QVERIFY(expected.completed());
    QCOMPARE(bus.status, TrialStatus::Completed);
    QCOMPARE(bus.samples(), expected.samples());
    const double qDiff = (bus.q - expected.q).cwiseAbs().maxCoeff();
    const Eigen::Vector2d tauDiff = (bus.tau - expected.tau).cwiseAbs().rowwise().maxCoeff();
    qInfo("elastic grid plan: max |q diff| = %.3g counts, max |tau diff| = %.3g / %.3g mN m",
          qDiff / ca, 1e3 * tauDiff[0], 1e3 * tauDiff[1]);
    QVERIFY(qDiff <= ca * 1.000001);
    QVERIFY(tauDiff[0] <= 0.5 * 320e-6 + 1e-9);
    QVERIFY(tauDiff[1] <= 0.5 * 160e-6 + 1e-9);
    // The reading carries the offset at rest (sample 0: the spring holds nothing on the
    // horizontal arm), so it is not the command the rigid robot records.
    QVERIFY(std::abs(expected.tau(0, 0) - 0.05) < 1e-9);
    QVERIFY((expected.tau - rigid.tau.leftCols(expected.samples())).cwiseAbs().maxCoeff() > 1e-3);
}

void TestCanArmSimulator::paperPlan_matchesSimulatedRobotWithinTheBusResolution()
{
    // The paper scenario as it is: an ideal encoder in SimulatedRobot, 2^24 increments on the
    // bus; targets and measured angles rounded to increments, feedforward to per mille. Every
    // rounding of the error e = target - q (up to one increment, 3.7e-7 rad) passes through the
    // PID, whose feedthrough kp + ki T/2 + kd lambda^2 (2/T)/(2/T + lambda)^2 = 21,167 N m/rad
    // (the filtered derivative dominates) turns one increment into 7.9 mN m. The arm averages
    // these steps out: the angles agree to about a count, the torques to a few such steps.
    const Scenario scenario;
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    const TrialPlan plan = TrialPlanner(scenario, model).plan(scenario.initialParameters);
    const TrialRecord expected = makeSimulatedRobot(scenario, model)->runTrial(plan, {});
    const TrialRecord bus = runPlanOnBus(scenario, plan);
    QCOMPARE(bus.status, TrialStatus::Completed);
    const double ca = 2.0 * M_PI / double(1 << 24);
    const double qDiff = (bus.q - expected.q).cwiseAbs().maxCoeff();
    const double tauDiff = (bus.tau - expected.tau).cwiseAbs().maxCoeff();
    const double tauRms = std::sqrt((bus.tau - expected.tau).squaredNorm() / bus.tau.size());
    qInfo("paper plan: max |q diff| = %.3g rad (%.2f counts), max |tau diff| = %.3g mN m, "
          "rms %.3g mN m",
          qDiff, qDiff / ca, 1e3 * tauDiff, 1e3 * tauRms);
    const double k0 = 4500 + 30 * 0.001 + 600 * 200.0 * 200.0 * 1000.0 / (1200.0 * 1200.0);
    const double step = k0 * ca; // torque of one increment of error [N m]
    QVERIFY(qDiff <= 2 * ca);
    QVERIFY(tauDiff < 4 * step);
    QVERIFY(tauRms < step);
}

void TestCanArmSimulator::unpoweredJoint_isHeldByItsBrake()
{
    Bus bus(paperSettings());
    const Eigen::Vector2d q0 = bus.sim.arm().q();
    bus.net.nmt(NmtCommand::Start, 0);
    for (const quint16 cw : {0x0006, 0x0007, 0x000F}) {
        bus.net.rpdo(1, std::round(q0[0] / bus.sim.node(0)->countAngle()), 0, cw);
        bus.cycle();
    }
    for (int k = 0; k < 50; ++k) { // joint 1 pushes with 2 N m; joint 2 is never enabled
        bus.net.rpdo(1, std::round(q0[0] / bus.sim.node(0)->countAngle()), 6250, 0x000F);
        bus.cycle();
    }
    QVERIFY(std::abs(bus.sim.arm().q()[0] - q0[0]) > 1e-4);
    QCOMPARE(bus.sim.arm().q()[1], q0[1]);
    QCOMPARE(bus.sim.arm().qd()[1], 0.0);
    QCOMPARE(bus.net.lastTpdo(2).value(1), 0.0);
}

void TestCanArmSimulator::dropFraction_losesThatShareOfTpdos_reproducibly()
{
    CanSimFaults faults;
    faults.dropFraction = 0.25;
    QList<int> received;
    for (int run = 0; run < 2; ++run) {
        Bus bus(paperSettings(), faults);
        bus.net.nmt(NmtCommand::Start, 0);
        for (int k = 0; k < 400; ++k)
            bus.cycle();
        QCOMPARE(bus.net.framesWithId(0x80).size(), 400);
        received << int(bus.net.framesWithId(0x181).size() + bus.net.framesWithId(0x182).size());
    }
    QVERIFY2(received[0] > 520 && received[0] < 680, qPrintable(QString::number(received[0])));
    QCOMPARE(received[1], received[0]); // seeded by the scenario
}

void TestCanArmSimulator::silentAfter_sendsExactlyNFramesThenNothing()
{
    CanSimFaults faults;
    faults.silentAfterFrames = 9;
    Bus bus(paperSettings(), faults);
    QSignalSpy silenced(&bus.sim, &CanArmSimulator::silenced);
    bus.sim.bootUp(); // 2 boot-ups
    bus.net.nmt(NmtCommand::Start, 0);
    for (int k = 0; k < 5; ++k) // 3 frames each: the 9th frame is the third SYNC
        bus.cycle();
    QCOMPARE(bus.sim.framesSent(), qint64(9));
    QCOMPARE(silenced.size(), 1);
    QVERIFY(bus.sim.isSilent());
    QCOMPARE(bus.net.framesWithId(0x80).size(), 3);
    QCOMPARE(bus.net.framesWithId(0x181).size(), 2);
    QCOMPARE(bus.net.framesWithId(0x182).size(), 2);
    bus.net.sdo.setTimeout(50);
    QCOMPARE(bus.net.read(1, 0x1000, 0).abortCode, sdoabort::protocolTimeout);
}

void TestCanArmSimulator::emcyAtSample_faultsTheFirstNodeAtTheKthEnabledSync()
{
    CanSimFaults faults;
    faults.emcyAtSample = 6;
    Bus bus(paperSettings(), faults);
    EmcyConsumer emcy(&bus.net.masterLink);
    QSignalSpy emergencies(&emcy, &EmcyConsumer::emergency);
    bus.enable(); // enabled SYNC 1
    for (int k = 2; k <= 6; ++k) {
        QCOMPARE(emergencies.size(), 0);
        for (quint8 node : {1, 2})
            bus.net.rpdo(node,
                         std::round(bus.sim.arm().q()[node - 1] / bus.sim.node(0)->countAngle()), 0,
                         0x000F);
        bus.cycle();
    }
    QCOMPARE(emergencies.size(), 1);
    const EmcyMessage m = emergencies.at(0).at(0).value<EmcyMessage>();
    QCOMPARE(m.node, quint8(1));
    QCOMPARE(m.errorCode, quint16(0x8611));
    QCOMPARE(bus.sim.node(0)->driveState(), cia402::State::Fault);
    QCOMPARE(bus.sim.node(1)->driveState(), cia402::State::OperationEnabled);
    QCOMPARE(cia402::stateFromStatusword(quint16(bus.net.lastTpdo(1).value(2))),
             cia402::State::Fault);
}

void TestCanArmSimulator::refusedSdo_abortsWritesThereOnEveryNode()
{
    CanSimFaults faults;
    faults.refusedWrite = qMakePair(quint16(0x2200), quint8(1));
    Bus bus(paperSettings(), faults);
    for (quint8 node : {1, 2}) {
        QCOMPARE(bus.net.write(node, 0x2200, 1, DataType::Real32, 20).abortCode,
                 sdoabort::cannotStore);
        QVERIFY(bus.net.read(node, 0x2200, 1).ok());
        QVERIFY(bus.net.write(node, 0x2200, 2, DataType::Real32, 5).ok());
    }
}

void TestCanArmSimulator::stateJson_listsEachNodesStoredParameters()
{
    Bus bus(paperSettings());
    QSignalSpy stored(&bus.sim, &CanArmSimulator::parametersStored);
    const SdoWriteSequence writes =
        objects::parameterWriteSequence({2}, Eigen::Vector3d(20, 5.5, 8));
    for (const SdoWrite &w : writes)
        QVERIFY(bus.net.writeRaw(w.node, w.index, w.subIndex, w.raw).ok());
    QCOMPARE(stored.size(), 1);
    const QJsonObject nodes =
        QJsonDocument::fromJson(simulatorStateJson(bus.sim)).object().value("nodes").toObject();
    QCOMPARE(nodes.value("1").toObject().value("storedParameters").toArray(), QJsonArray());
    QCOMPARE(nodes.value("2").toObject().value("storedParameters").toArray(),
             (QJsonArray{20, 5.5, 8}));
}

void TestCanArmSimulator::settingsThatDoNotFit_areRejected()
{
    test::CanSimTestBus net;
    CanArmSettings s = paperSettings();
    s.nodes = {1, 2, 3};
    QVERIFY_THROWS_EXCEPTION(Error, CanArmSimulator sim(&net.slaveLink, s));
    s.nodes = {4, 4};
    QVERIFY_THROWS_EXCEPTION(Error, CanArmSimulator sim(&net.slaveLink, s));
    s.nodes = {1, 128};
    QVERIFY_THROWS_EXCEPTION(Error, CanArmSimulator sim(&net.slaveLink, s));
}

QTEST_GUILESS_MAIN(TestCanArmSimulator)
#include "tst_canarmsimulator.moc"
