// DriveNode: one simulated CiA 402 drive seen from a master on the memory bus (DriveNodeRig.h):
// boot-up, the object dictionary over SDO, store and reset, NMT, PDO mapping, the enable walk,
// the SYNC cycle's torque. Its states after a stop and its faults: tst_drivenodestates.
#include "DriveNodeRig.h"
#include "can/EmcyConsumer.h"
#include "can/Pdo.h"
#include "can/SdoAbortCode.h"

using namespace learnid;
using namespace learnid::test::drive;
using canopen::DataType;
using cia402::State;
namespace ob = learnid::objects;

class TestDriveNode : public QObject
{
    Q_OBJECT

private slots:
private slots:
    void bootUp_sendsBootUpMessage_andIsPreOperational();
    void dictionary_readsOverSdo_data();
    void dictionary_readsOverSdo();
    void writes_takeEffect();
    void refusedWrites_abortWithTheirCode_data();
    void refusedWrites_abortWithTheirCode();
    void storeParameters_rightSignatureStores_wrongSignatureAborts();
    void resetNode_restoresTheStoredSet();
    void payload_storedWithTheParameters_restoredByResetNode();
    void nmtCommands_moveTheSlaveStateMachine();
    void masterPdoConfiguration_isAccepted_otherMappingsAreNot();
    void rpdoControlwords_enableTheDrive_oneCommandPerSync();
    void syncCycle_tpdoIsPidPlusOffset_saturatedAndQuantised();
    void interpolationPeriod_setsThePidSamplePeriod();
    void unpowered_appliesNoTorque();
};

void TestDriveNode::bootUp_sendsBootUpMessage_andIsPreOperational()
{
    Drive d;
    d.drive.bootUp();
    d.net.flush();
    QCOMPARE(d.net.framesWithId(0x705).size(), 1);
    QCOMPARE(d.net.framesWithId(0x705).first().payload(), QByteArray(1, '\0'));
    QCOMPARE(d.drive.nmtState(), NmtState::PreOperational);
    QCOMPARE(d.drive.driveState(), State::SwitchOnDisabled);
}

void TestDriveNode::dictionary_readsOverSdo_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::addColumn<int>("type");
    QTest::addColumn<double>("expected");
    const auto row = [](const char *name, int index, int sub, DataType type, double value) {
        QTest::newRow(name) << index << sub << int(type) << value;
    };
    row("device type", 0x1000, 0, DataType::Unsigned32, 0x00020192);
    row("error register", 0x1001, 0, DataType::Unsigned8, 0);
    row("COB-ID SYNC", 0x1005, 0, DataType::Unsigned32, 0x80);
    row("cycle period", 0x1006, 0, DataType::Unsigned32, 2000);
    row("heartbeat off", 0x1017, 0, DataType::Unsigned16, 0);
    row("SYNC overflow", 0x1019, 0, DataType::Unsigned8, 240);
    row("RPDO1 COB-ID", 0x1400, 1, DataType::Unsigned32, 0x205);
    row("TPDO1 COB-ID", 0x1800, 1, DataType::Unsigned32, 0x185);
    row("TPDO1 type", 0x1800, 2, DataType::Unsigned8, 1);
    row("TPDO1 map 1", 0x1A00, 1, DataType::Unsigned32, 0x60640020);
    row("kp", 0x2100, 1, DataType::Real32, 4500);
    row("lambda", 0x2100, 4, DataType::Real32, 200);
    row("parameter count", 0x2200, 0, DataType::Unsigned8, 0);
    row("torque limit", 0x2300, 0, DataType::Real32, 8);
    row("statusword", 0x6041, 0, DataType::Unsigned16, 0x0240);
    row("mode", 0x6060, 0, DataType::Integer8, 8);
    row("mode display", 0x6061, 0, DataType::Integer8, 8);
    row("rated torque = limit / 25", 0x6076, 0, DataType::Unsigned32, 320);
    row("encoder increments", 0x608F, 1, DataType::Unsigned32, increments);
    row("motor revolutions", 0x608F, 2, DataType::Unsigned32, 1);
    row("interpolation value", 0x60C2, 1, DataType::Unsigned8, 2);
    row("interpolation exponent", 0x60C2, 2, DataType::Integer8, -3);
}

void TestDriveNode::dictionary_readsOverSdo()
{
    QFETCH(int, index);
    QFETCH(int, sub);
    QFETCH(int, type);
    QFETCH(double, expected);
    Drive d;
    QCOMPARE(d.net.readValue(node, quint16(index), quint8(sub), DataType(type)), expected);
}

void TestDriveNode::writes_takeEffect()
{
    Drive d;
    const SdoResult name = d.net.read(node, 0x1008, 0);
    QVERIFY(name.ok());
    QCOMPARE(name.data, QByteArray("learnid-robot-sim joint 2")); // a segmented upload

    QVERIFY(d.net.write(node, 0x2300, 0, DataType::Real32, 4.0).ok());
    QCOMPARE(d.net.readValue(node, 0x6076, 0, DataType::Unsigned32), 160.0);
    QCOMPARE(d.drive.torqueUnit(), 160e-6);
    QVERIFY(d.net.write(node, 0x2100, 1, DataType::Real32, 1234.5).ok());
    QCOMPARE(d.net.readValue(node, 0x2100, 1, DataType::Real32), 1234.5);

    QVERIFY(d.net.write(node, 0x1017, 0, DataType::Unsigned16, 10).ok());
    QTRY_VERIFY_WITH_TIMEOUT(d.net.framesWithId(0x705).size() >= 2, 1000);
    QCOMPARE(d.net.framesWithId(0x705).last().payload(), QByteArray(1, '\x7F'));
}

void TestDriveNode::refusedWrites_abortWithTheirCode_data()
{
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::addColumn<int>("type");
    QTest::addColumn<double>("value");
    QTest::addColumn<quint32>("code");
    const auto row = [](const char *name, int index, int sub, DataType type, double value,
                        quint32 code) {
        QTest::newRow(name) << index << sub << int(type) << value << code;
    };
    row("mode other than csp", 0x6060, 0, DataType::Integer8, 1, 0x06090030);
    row("read-only device type", 0x1000, 0, DataType::Unsigned32, 1, sdoabort::readOnly);
    row("read-only rated torque", 0x6076, 0, DataType::Unsigned32, 1, sdoabort::readOnly);
    row("missing object", 0x3000, 0, DataType::Unsigned8, 1, sdoabort::objectDoesNotExist);
    row("missing sub-index", 0x2100, 5, DataType::Real32, 1, sdoabort::subIndexDoesNotExist);
    row("negative kp", 0x2100, 1, DataType::Real32, -1, sdoabort::valueTooLow);
    row("infinite kd", 0x2100, 3, DataType::Real32, qInf(), sdoabort::invalidValue);
    row("zero torque limit", 0x2300, 0, DataType::Real32, 0, sdoabort::valueTooLow);
    row("more parameters than the model", 0x2200, 0, DataType::Unsigned8, 4,
        sdoabort::valueTooHigh);
    row("NaN parameter", 0x2200, 1, DataType::Real32, qQNaN(), sdoabort::invalidValue);
    row("interpolation exponent 0", 0x60C2, 2, DataType::Integer8, 0, sdoabort::valueTooHigh);
    row("mapping of a valid PDO", 0x1600, 1, DataType::Unsigned32, 0x60640020,
        sdoabort::cannotStoreDeviceState);
    row("transmission type 255", 0x1800, 2, DataType::Unsigned8, 255, sdoabort::invalidValue);
    row("foreign COB-ID", 0x1800, 1, DataType::Unsigned32, 0x190, sdoabort::invalidValue);
}

void TestDriveNode::refusedWrites_abortWithTheirCode()
{
    QFETCH(int, index);
    QFETCH(int, sub);
    QFETCH(int, type);
    QFETCH(double, value);
    QFETCH(quint32, code);
    Drive d;
    QByteArray raw;
    if (DataType(type) == DataType::Real32) {
        const float f = float(value);
        raw = QByteArray(reinterpret_cast<const char *>(&f), 4); // NaN and inf as they are
    } else {
        raw = canopen::encodeValue(DataType(type), value);
    }
    const SdoResult r = d.net.writeRaw(node, quint16(index), quint8(sub), raw);
    QVERIFY(!r.ok());
    QCOMPARE(r.abortCode, code);
    QVERIFY(r.abortedByServer);
}

void TestDriveNode::storeParameters_rightSignatureStores_wrongSignatureAborts()
{
    Drive d;
    QSignalSpy stored(&d.drive, &DriveNode::parametersStored);
    QCOMPARE(d.net.read(node, 0x1010, 1).abortCode, sdoabort::writeOnly);
    QVERIFY(d.net.write(node, 0x2200, 0, DataType::Unsigned8, 3).ok());
    const double phi[] = {20.1, 5.2, 7.9};
    for (int i = 0; i < 3; ++i)
        QVERIFY(d.net.write(node, 0x2200, quint8(i + 1), DataType::Real32, float(phi[i])).ok());

    const SdoResult wrong = d.net.write(node, 0x1010, 1, DataType::Unsigned32, 0x65766174);
    QCOMPARE(wrong.abortCode, sdoabort::cannotStore);
    QCOMPARE(stored.size(), 0);
    QCOMPARE(d.drive.storedParameters().size(), 0);

    QVERIFY(d.net.write(node, 0x1010, 1, DataType::Unsigned32, 0x65766173).ok()); // "save"
    QCOMPARE(stored.size(), 1);
    const Eigen::VectorXd s = d.drive.storedParameters();
    QCOMPARE(s.size(), 3);
    for (int i = 0; i < 3; ++i)
        QCOMPARE(s[i], double(float(phi[i])));
}

void TestDriveNode::resetNode_restoresTheStoredSet()
{
    Drive d;
    QVERIFY(d.net.write(node, 0x2200, 0, DataType::Unsigned8, 1).ok());
    QVERIFY(d.net.write(node, 0x2200, 1, DataType::Real32, 20).ok());
    QVERIFY(d.net.write(node, 0x2300, 0, DataType::Real32, 6).ok());
    QVERIFY(d.net.write(node, 0x1010, 1, DataType::Unsigned32, 0x65766173).ok());
    QVERIFY(d.net.write(node, 0x2200, 1, DataType::Real32, 99).ok());
    QVERIFY(d.net.write(node, 0x2300, 0, DataType::Real32, 2).ok());
    QVERIFY(d.net.write(node, 0x1017, 0, DataType::Unsigned16, 1000).ok());
    d.net.nmt(NmtCommand::ResetNode, node);
    QCOMPARE(d.net.readValue(node, 0x2200, 1, DataType::Real32), 20.0);
    QCOMPARE(d.net.readValue(node, 0x2300, 0, DataType::Real32), 6.0);
    QCOMPARE(d.net.readValue(node, 0x6076, 0, DataType::Unsigned32), 240.0);
    QCOMPARE(d.net.readValue(node, 0x1017, 0, DataType::Unsigned16), 0.0); // communication reset
}

void TestDriveNode::payload_storedWithTheParameters_restoredByResetNode()
{
    // 0x2500 (docs/can-protocol.md §2.5): none at power-on; what "save" stores reset node
    // restores; a value that is not a finite REAL32, or a joint beyond 127, is refused.
    Drive d;
    QCOMPARE(d.net.readValue(node, 0x2500, 0, DataType::Unsigned8), 11.0);
    QCOMPARE(d.net.readValue(node, 0x2500, 1, DataType::Unsigned8), 0.0);
    QVERIFY(d.drive.storedSet().payloadParameters().size() == 0);
    QVERIFY(d.net.write(node, 0x2500, 1, DataType::Unsigned8, 7).ok());
    for (quint8 sub = 2; sub <= 11; ++sub)
        QVERIFY(d.net.write(node, 0x2500, sub, DataType::Real32, 0.25 * sub).ok());
    QCOMPARE(d.net.writeRaw(node, 0x2500, 3, QByteArray::fromHex("0000C07F")).abortCode, // NaN
             sdoabort::invalidValue);
    QVERIFY(d.net.write(node, 0x2500, 1, DataType::Unsigned8, 128).abortCode != 0);
    QVERIFY(d.net.write(node, 0x1010, 1, DataType::Unsigned32, 0x65766173).ok()); // "save"
    QVERIFY(d.net.write(node, 0x2500, 1, DataType::Unsigned8, 2).ok());
    QVERIFY(d.net.write(node, 0x2500, 2, DataType::Real32, 99).ok());
    d.net.nmt(NmtCommand::ResetNode, node);
    QCOMPARE(d.net.readValue(node, 0x2500, 1, DataType::Unsigned8), 7.0);
    QCOMPARE(d.net.readValue(node, 0x2500, 2, DataType::Real32), 0.5);
    QCOMPARE(d.drive.storedSet().payloadJoint(), 7);
    const Eigen::VectorXd body = d.drive.storedSet().payloadParameters();
    QCOMPARE(body.size(), 10);
    for (int i = 0; i < 10; ++i)
        QCOMPARE(body[i], 0.25 * (i + 2));
}

void TestDriveNode::nmtCommands_moveTheSlaveStateMachine()
{
    Drive d;
    d.drive.bootUp();
    d.net.nmt(NmtCommand::Start, node + 1); // another node: ignored
    QCOMPARE(d.drive.nmtState(), NmtState::PreOperational);
    d.net.nmt(NmtCommand::Start, 0); // all nodes
    QCOMPARE(d.drive.nmtState(), NmtState::Operational);
    d.net.nmt(NmtCommand::Stop, node);
    QCOMPARE(d.drive.nmtState(), NmtState::Stopped);
    d.net.sdo.setTimeout(50);
    QCOMPARE(d.net.read(node, 0x1000, 0).abortCode,
             sdoabort::protocolTimeout); // no SDO when stopped
    d.net.nmt(NmtCommand::EnterPreOperational, node);
    QCOMPARE(d.drive.nmtState(), NmtState::PreOperational);
    QVERIFY(d.net.read(node, 0x1000, 0).ok());
    d.net.nmt(NmtCommand::Start, node);
    d.net.nmt(NmtCommand::ResetCommunication, node);
    QCOMPARE(d.drive.nmtState(), NmtState::PreOperational);
    d.net.nmt(NmtCommand::ResetNode, node);
    const QList<QCanBusFrame> bootUps = d.net.framesWithId(0x705);
    QCOMPARE(bootUps.size(), 3); // start, reset communication, reset node
    for (const QCanBusFrame &f : bootUps)
        QCOMPARE(f.payload(), QByteArray(1, '\0'));
}

void TestDriveNode::masterPdoConfiguration_isAccepted_otherMappingsAreNot()
{
    Drive d;
    SdoWriteSequence writes =
        pdoConfigurationWrites(node, PdoDirection::Receive, 1, ob::trialRpdoMapping());
    writes << pdoConfigurationWrites(node, PdoDirection::Transmit, 1, ob::trialTpdoMapping());
    for (const SdoWrite &w : writes)
        QVERIFY2(d.net.writeRaw(node, w.index, w.subIndex, w.raw).ok(), qPrintable(w.toString()));

    // An RPDO mapping of position actual: the drive cannot take it.
    QVERIFY(d.net.write(node, 0x1400, 1, DataType::Unsigned32, 0x80000205).ok());
    QVERIFY(d.net.write(node, 0x1600, 0, DataType::Unsigned8, 0).ok());
    QCOMPARE(d.net.write(node, 0x1600, 1, DataType::Unsigned32, 0x60640020).abortCode,
             sdoabort::cannotBeMapped);
}

void TestDriveNode::rpdoControlwords_enableTheDrive_oneCommandPerSync()
{
    Drive d;
    const double q = 0.3;
    d.net.nmt(NmtCommand::Start, node);
    const QList<QPair<quint16, State>> walk = {{0x0006, State::ReadyToSwitchOn},
                                               {0x0007, State::SwitchedOn},
                                               {0x000F, State::OperationEnabled}};
    for (const auto &[cw, state] : walk) {
        const State before = d.drive.driveState();
        d.net.rpdo(node, std::round(q / countAngle), 0, cw);
        QCOMPARE(d.drive.driveState(), before); // the RPDO takes effect at the SYNC
        d.sync(q);
        QCOMPARE(d.tpdoState(), state);
    }
    const quint16 status = quint16(d.net.lastTpdo(node).value(2));
    QVERIFY(status & 0x1000); // following the set-point
    QCOMPARE(d.net.lastTpdo(node).value(0), std::round(q / countAngle));
}

void TestDriveNode::syncCycle_tpdoIsPidPlusOffset_saturatedAndQuantised()
{
    Drive d;
    const double q = std::round(0.3 / countAngle) * countAngle; // on the encoder grid
    d.enable(q);
    const double unit = 320e-6; // N m per per mille at 8 N m
    const double k0 = pidFeedthrough(4500, 30, 600, 200, 0.002);

    d.net.rpdo(node, std::round(q / countAngle) + 40, 500, 0x000F);
    DriveSyncOutput out = d.sync(q);
    const double expected = 500 * unit + k0 * 40 * countAngle;
    QVERIFY(out.powered);
    QVERIFY(std::abs(out.torque - expected) < 1e-9);
    QCOMPARE(d.net.lastTpdo(node).value(1), std::round(expected / unit));
    QCOMPARE(d.net.lastTpdo(node).value(0), std::round(q / countAngle));

    Drive s; // a large error saturates at the torque limit, 25,000 per mille
    s.enable(q);
    s.net.rpdo(node, std::round(q / countAngle) + 2000, 0, 0x000F);
    out = s.sync(q);
    QCOMPARE(out.torque, 8.0);
    QCOMPARE(s.net.lastTpdo(node).value(1), 25000.0);
    s.net.rpdo(node, std::round(q / countAngle) - 4000, 0, 0x000F);
    QCOMPARE(s.sync(q).torque, -8.0);
}

void TestDriveNode::interpolationPeriod_setsThePidSamplePeriod()
{
    Drive d;
    QVERIFY(d.net.write(node, 0x60C2, 1, DataType::Unsigned8, 5).ok());
    QVERIFY(d.net.write(node, 0x60C2, 2, DataType::Integer8, -4).ok()); // 0.5 ms
    QVERIFY(d.net.write(node, 0x2100, 3, DataType::Real32, 100).ok());
    const double q = 0.0;
    d.enable(q);
    d.net.rpdo(node, 100, 0, 0x000F);
    const double expected = pidFeedthrough(4500, 30, 100, 200, 0.0005) * 100 * countAngle;
    QVERIFY(std::abs(d.sync(q).torque - expected) < 1e-9);
}

void TestDriveNode::unpowered_appliesNoTorque()
{
    Drive d;
    d.net.nmt(NmtCommand::Start, node);
    for (const quint16 cw : {0x0000, 0x0006, 0x0007}) {
        d.net.rpdo(node, 1000, 3000, cw);
        const DriveSyncOutput out = d.sync(0.0);
        QVERIFY(!out.powered);
        QCOMPARE(out.torque, 0.0);
        QCOMPARE(d.net.lastTpdo(node).value(1), 0.0);
    }
}

QTEST_GUILESS_MAIN(TestDriveNode)
#include "tst_drivenode.moc"
