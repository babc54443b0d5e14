// DriveNode (DriveNodeRig.h) after a stop and under faults: quick stop SYNC by SYNC, leaving
// Operational, statusword bit 12, missed set-points, injected faults and EMCY, a silent node.
#include "DriveNodeRig.h"
#include "can/EmcyConsumer.h"
#include "can/Pdo.h"
#include "can/SdoAbortCode.h"

using namespace learnid;
using namespace learnid::test::drive;
using canopen::DataType;
using cia402::State;
namespace ob = learnid::objects;

class TestDriveNodeStates : public QObject
{
    Q_OBJECT

private slots:
    void quickStop_holdsThenSwitchesOnDisabledAfterTenSyncs();
    void leavingOperational_whileEnabled_quickStops();
    void statuswordBit12_onlyInOperationEnabled_afterResetOrSdoControlword();
    void threeMissedSetPoints_faultWithEmcy_faultResetClearsIt();
    void injectedFault_atTheKthEnabledSync_sendsEmcy8611();
    void silentNode_sendsAndAnswersNothing();
};

void TestDriveNodeStates::quickStop_holdsThenSwitchesOnDisabledAfterTenSyncs()
{
    Drive d;
    d.enable(0.0);
    d.net.rpdo(node, 0, 0, 0x0002);
    const double q = 10 * countAngle; // the arm at 10 increments when the quick stop comes
    for (int i = 0; i < 10; ++i) {
        const DriveSyncOutput out = d.sync(q);
        QVERIFY2(out.powered, qPrintable(QString::number(i)));
        QCOMPARE(d.drive.driveState(), State::QuickStopActive);
        if (i == 0)
            QCOMPARE(out.torque, 0.0); // holds where it is: no error
    }
    const DriveSyncOutput out = d.sync(q);
    QVERIFY(!out.powered);
    QCOMPARE(d.drive.driveState(), State::SwitchOnDisabled);
}

void TestDriveNodeStates::leavingOperational_whileEnabled_quickStops()
{
    Drive d;
    d.enable(0.0);
    d.net.nmt(NmtCommand::EnterPreOperational, node);
    QCOMPARE(d.drive.driveState(), State::QuickStopActive);
}

// Bit 12 (set-point followed) belongs to Operation enabled: a state left between SYNCs, by NMT
// reset node or an SDO write of the controlword, must not report it (docs/can-protocol.md §5.2).
void TestDriveNodeStates::statuswordBit12_onlyInOperationEnabled_afterResetOrSdoControlword()
{
    Drive d;
    d.enable(0.0);
    QCOMPARE(d.net.readValue(node, 0x6041, 0, DataType::Unsigned16), double(0x1237));
    QVERIFY(d.net.write(node, 0x6040, 0, DataType::Unsigned16, 0x0002).ok()); // quick stop
    QCOMPARE(d.net.readValue(node, 0x6041, 0, DataType::Unsigned16), double(0x0217));

    Drive r;
    r.enable(0.0);
    r.net.nmt(NmtCommand::ResetNode, node);
    QCOMPARE(r.net.readValue(node, 0x6041, 0, DataType::Unsigned16), double(0x0240));
}

void TestDriveNodeStates::threeMissedSetPoints_faultWithEmcy_faultResetClearsIt()
{
    Drive d;
    EmcyConsumer emcy(&d.net.masterLink);
    QSignalSpy emergencies(&emcy, &EmcyConsumer::emergency);
    d.enable(0.0);
    for (int missed = 1; missed <= 2; ++missed) {
        QVERIFY(d.sync(0.0).powered);
        QCOMPARE(d.tpdoState(), State::OperationEnabled);
        QVERIFY(!(quint16(d.net.lastTpdo(node).value(2)) & 0x1000)); // not following: no set-point
    }
    QCOMPARE(emergencies.size(), 0);
    QVERIFY(!d.sync(0.0).powered);
    QCOMPARE(d.tpdoState(), State::Fault);
    QCOMPARE(emergencies.size(), 1);
    EmcyMessage m = emergencies.at(0).at(0).value<EmcyMessage>();
    QCOMPARE(m.node, node);
    QCOMPARE(m.errorCode, quint16(0x8100));
    QCOMPARE(m.errorRegister, quint8(0x11));
    QCOMPARE(d.net.readValue(node, 0x1001, 0, DataType::Unsigned8), 17.0);

    d.net.rpdo(node, 0, 0, 0x0080); // fault reset
    d.sync(0.0);
    QCOMPARE(d.tpdoState(), State::SwitchOnDisabled);
    QCOMPARE(emergencies.size(), 2);
    QCOMPARE(emergencies.at(1).at(0).value<EmcyMessage>().errorCode, quint16(0));
}

void TestDriveNodeStates::injectedFault_atTheKthEnabledSync_sendsEmcy8611()
{
    Drive d;
    d.drive.setFaultAtEnabledSync(4, 0x8611);
    EmcyConsumer emcy(&d.net.masterLink);
    QSignalSpy emergencies(&emcy, &EmcyConsumer::emergency);
    d.enable(0.0); // the enabling SYNC is the first in Operation enabled
    for (int k = 2; k <= 3; ++k) {
        d.net.rpdo(node, 0, 0, 0x000F);
        QVERIFY(d.sync(0.0).powered);
    }
    QCOMPARE(emergencies.size(), 0);
    d.net.rpdo(node, 0, 0, 0x000F);
    QVERIFY(!d.sync(0.0).powered);
    QCOMPARE(d.tpdoState(), State::Fault);
    QCOMPARE(emergencies.size(), 1);
    const EmcyMessage m = emergencies.at(0).at(0).value<EmcyMessage>();
    QCOMPARE(m.errorCode, quint16(0x8611));
    QCOMPARE(m.errorRegister, quint8(0x21));
}

void TestDriveNodeStates::silentNode_sendsAndAnswersNothing()
{
    Drive d;
    d.drive.setSilent(true);
    d.drive.bootUp();
    d.net.sdo.setTimeout(50);
    QCOMPARE(d.net.read(node, 0x1000, 0).abortCode, sdoabort::protocolTimeout);
    d.net.nmt(NmtCommand::Start, node);
    d.sync(0.0);
    const int slaveFrames = int(d.net.wire.size()) - int(d.net.framesWithId(0x605).size()) -
                            int(d.net.framesWithId(0x000).size());
    QCOMPARE(slaveFrames, 0);
}

QTEST_GUILESS_MAIN(TestDriveNodeStates)
#include "tst_drivenodestates.moc"
