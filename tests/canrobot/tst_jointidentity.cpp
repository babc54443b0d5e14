// The joint-to-drive identity over the memory bus (docs/can-protocol.md §2.4): before any motion
// the master reads every node's 0x1018 and 0x2400 and refuses a node that is not the drive of
// the joint it is listed for, naming node and joint; a drive never commissioned is refused
// unless the technician confirmed the node list (commissioning), and apply then stores the
// joint identity; a drive other than the one a parameter file recorded is refused.
#include "CanSimRig.h"
#include "TestPlan.h"
#include "can/JointIdentity.h"
#include "can/ManufacturerObjects.h"
#include "canrobot/CanRobot.h"
#include "canrobot/JointIdentityCheck.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

// The simulator of the paper arm (nodes {1, 2}) as CanRobot's device; *rig is set once the
// CAN thread has built it.
CanDeviceFactory rigFactory(const CanArmSettings &settings, test::CanSimRig **rig)
{
    return [settings, rig](QString *) -> QCanBusDevice * {
        auto *bus = new MemoryCanBus;
        auto *master = new MemoryCanDevice(QStringLiteral("master"), bus);
        *rig = new test::CanSimRig(bus, settings, {});
        bus->setParent(master);
        return master;
    };
}

CanArmSettings paperArm(bool commissioned)
{
    Scenario scenario;
    CanArmSettings s = canArmSettings(scenario, test::testModel(), {1, 2});
    if (!commissioned)
        s.robotIdentity = 0;
    return s;
}

CanRobotOptions options(const QList<int> &nodes, const QString &logDir)
{
    CanRobotOptions o;
    o.plugin = QStringLiteral("memory");
    o.interface = QStringLiteral("can0");
    o.nodes = nodes;
    o.candumpDir = logDir;
    return o;
}

} // namespace

class TestJointIdentity : public QObject
{
    Q_OBJECT

private slots:
    void swappedNodeList_refusedBeforeAnyMotion_namingNodeAndJoint();
    void neverCommissioned_refused_commissioningRunsAndApplyStoresTheIdentity();
    void driveOtherThanRecorded_refused();
    void robotIdentity_isTheCrc32OfTheModelId();
};

void TestJointIdentity::swappedNodeList_refusedBeforeAnyMotion_namingNodeAndJoint()
{
    QTemporaryDir logs;
    test::CanSimRig *rig = nullptr;
    // Drives wired joint 1 = node 1, joint 2 = node 2; the master told --nodes 2,1.
    CanRobot robot(test::testModel(), options({2, 1}, logs.path()),
                   rigFactory(paperArm(true), &rig));
    const TrialRecord r = robot.runTrial(test::testPlan(200), {});
    QCOMPARE(r.status, TrialStatus::Refused);
    QVERIFY2(r.message.contains(QLatin1String("before any motion")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("node 2 is listed for joint 1 but is the drive of "
                                              "joint 2")),
             qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("--nodes 1,2")), qPrintable(r.message));
    QCOMPARE(r.samples(), 0);
    // Nothing after the reads: no NMT command, no write (the trial's log starts at its NMT).
    QVERIFY(QDir(logs.path()).entryList(QDir::Files).isEmpty());
    QVERIFY(rig);
    for (int j = 0; j < 2; ++j)
        QCOMPARE(rig->simulator().node(j)->dictionary().value(objects::gains, objects::gainKp),
                 j == 0 ? 4500.0 : 5000.0); // the gains were not written either
    // Apply is refused the same way, before any write.
    const QString applied = robot.applyParameters(Eigen::Vector3d(20, 5, 8));
    QVERIFY2(applied.contains(QLatin1String("nothing was stored")), qPrintable(applied));
    QCOMPARE(robot.storedParameters().size(), 0);
}

void TestJointIdentity::neverCommissioned_refused_commissioningRunsAndApplyStoresTheIdentity()
{
    test::CanSimRig *rig = nullptr;
    CanRobot refused(test::testModel(), options({1, 2}, {}), rigFactory(paperArm(false), &rig));
    const TrialRecord r = refused.runTrial(test::testPlan(200), {});
    QCOMPARE(r.status, TrialStatus::Refused);
    QVERIFY2(r.message.contains(QLatin1String("node 1 (joint 1) has never been commissioned")),
             qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("serial 1001")), qPrintable(r.message));

    CanRobotOptions first = options({1, 2}, {});
    first.commissioning = true; // the technician checked serials 1001 and 1002 on the arm
    CanRobot robot(test::testModel(), first, rigFactory(paperArm(false), &rig));
    TrialPlan plan = test::testPlan(200);
    plan.maxTrackingError = M_PI / 6; // the plan's feedforward is not the arm's
    const TrialRecord ran = robot.runTrial(plan, {});
    QVERIFY2(ran.completed(), qPrintable(ran.message));
    const QList<DriveIdentity> drives = robot.driveIdentities();
    QCOMPARE(drives.size(), 2);
    QCOMPARE(drives[0], cansim::driveIdentityOfJoint(1));
    QCOMPARE(drives[1].serialNumber, 1002u);
    QCOMPARE(robot.applyParameters(Eigen::Vector3d(20, 5, 8)), QString());
    const quint32 paper = objects::robotIdentityOf(QStringLiteral("paper-2link"));
    for (int j = 0; j < 2; ++j) {
        const ObjectDictionary &od = rig->simulator().node(j)->dictionary();
        QCOMPARE(quint32(od.value(objects::jointIdentity, objects::jointIdentityRobot)), paper);
        QCOMPARE(int(od.value(objects::jointIdentity, objects::jointIdentityJoint)), j + 1);
    }
}

void TestJointIdentity::driveOtherThanRecorded_refused()
{
    test::CanSimRig *rig = nullptr;
    CanRobotOptions o = options({1, 2}, {});
    // A parameter file recorded serials 1001, 1003: joint 2's drive was exchanged since.
    o.recordedDrives = {cansim::driveIdentityOfJoint(1), cansim::driveIdentityOfJoint(3)};
    CanRobot robot(test::testModel(), o, rigFactory(paperArm(true), &rig));
    const TrialRecord r = robot.runTrial(test::testPlan(200), {});
    QCOMPARE(r.status, TrialStatus::Refused);
    QVERIFY2(r.message.contains(QLatin1String("node 2 (joint 2) is not the drive the parameter "
                                              "file records")) &&
                 r.message.contains(QLatin1String("serial 1002")) &&
                 r.message.contains(QLatin1String("serial 1003")),
             qPrintable(r.message));
}

void TestJointIdentity::robotIdentity_isTheCrc32OfTheModelId()
{
    // CRC-32 (IEEE) check value of "123456789" is 0xCBF43926.
    QCOMPARE(objects::robotIdentityOf(QStringLiteral("123456789")), 0xCBF43926u);
    QVERIFY(objects::robotIdentityOf(QString()) != 0);
}

QTEST_GUILESS_MAIN(TestJointIdentity)
#include "tst_jointidentity.moc"
