#include "CanTestBus.h"
#include "can/EmcyConsumer.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

class TestEmcyConsumer : public QObject
{
    Q_OBJECT

private slots:
    void decode_splitsCodeRegisterAndManufacturerBytes();
    void errorCodes_areNamedExactlyOrByClass_data();
    void errorCodes_areNamedExactlyOrByClass();
    void errorRegister_namesEverySetBit();
    void text_tellsTheTechnicianEverything();
    void syncAndOtherFrames_areNotEmergencies();
    void shortFrame_isPaddedWhenCodeAndRegisterArePresent();
    void encode_roundTripsThroughDecode();
    void consumer_reportsEmergenciesFromTheBus();
};

void TestEmcyConsumer::decode_splitsCodeRegisterAndManufacturerBytes()
{
    const auto m = decodeEmcy(QCanBusFrame(0x082, QByteArray::fromHex("1186210102030405")));
    QVERIFY(m);
    QCOMPARE(m->node, quint8(2));
    QCOMPARE(m->errorCode, quint16(0x8611));
    QCOMPARE(m->errorRegister, quint8(0x21));
    QCOMPARE(m->manufacturerData, QByteArray::fromHex("0102030405"));
    QVERIFY(!m->isErrorReset());
}

void TestEmcyConsumer::errorCodes_areNamedExactlyOrByClass_data()
{
    QTest::addColumn<quint16>("code");
    QTest::addColumn<QString>("text");
    QTest::newRow("reset") << quint16(0x0000) << "error reset or no error";
    QTest::newRow("following error") << quint16(0x8611) << "following error";
    QTest::newRow("heartbeat") << quint16(0x8130) << "life guard or heartbeat error";
    QTest::newRow("sub-class 0x2311") << quint16(0x2311) << "current, device output side";
    QTest::newRow("sub-class 0x8612") << quint16(0x8612) << "positioning controller";
    QTest::newRow("class 0x4321") << quint16(0x4321) << "temperature";
    QTest::newRow("device specific") << quint16(0xFF42) << "device specific";
    QTest::newRow("unknown") << quint16(0xA123) << "unknown error code";
    QTest::newRow("not reset") << quint16(0x0042) << "unknown error code";
}

void TestEmcyConsumer::errorCodes_areNamedExactlyOrByClass()
{
    QFETCH(quint16, code);
    QFETCH(QString, text);
    QCOMPARE(emcyErrorCodeText(code), text);
}

void TestEmcyConsumer::errorRegister_namesEverySetBit()
{
    QCOMPARE(errorRegisterText(0x00), QString("no error"));
    QCOMPARE(errorRegisterText(0x21), QString("generic, device profile"));
    QCOMPARE(errorRegisterText(0x9A), QString("current, temperature, communication, manufacturer"));
}

void TestEmcyConsumer::text_tellsTheTechnicianEverything()
{
    EmcyMessage m;
    m.node = 2;
    m.errorCode = 0x8611;
    m.errorRegister = 0x21;
    m.manufacturerData = QByteArray::fromHex("0102030405");
    QCOMPARE(m.text(), QString("Node 2 emergency 0x8611: following error; error register 0x21: "
                               "generic, device profile; manufacturer data 01 02 03 04 05"));
}

void TestEmcyConsumer::syncAndOtherFrames_areNotEmergencies()
{
    QVERIFY(!decodeEmcy(QCanBusFrame(0x080, QByteArray())));
    QVERIFY(!decodeEmcy(QCanBusFrame(0x080, QByteArray(8, '\0'))));
    QVERIFY(!decodeEmcy(QCanBusFrame(0x181, QByteArray(8, '\0'))));
    QVERIFY(!decodeEmcy(QCanBusFrame(0x082, QByteArray(2, '\0'))));
    QCanBusFrame remote(0x082, QByteArray(8, '\0'));
    remote.setFrameType(QCanBusFrame::RemoteRequestFrame);
    QVERIFY(!decodeEmcy(remote));
}

void TestEmcyConsumer::shortFrame_isPaddedWhenCodeAndRegisterArePresent()
{
    const auto m = decodeEmcy(QCanBusFrame(0x0FF, QByteArray::fromHex("103201AA")));
    QVERIFY(m);
    QCOMPARE(m->node, quint8(127));
    QCOMPARE(m->errorCode, quint16(0x3210));
    QCOMPARE(m->manufacturerData, QByteArray::fromHex("AA00000000"));
}

void TestEmcyConsumer::encode_roundTripsThroughDecode()
{
    EmcyMessage m;
    m.node = 9;
    m.errorCode = 0x2310;
    m.errorRegister = 0x03;
    m.manufacturerData = QByteArray::fromHex("0A0B");
    const QCanBusFrame f = encodeEmcy(m);
    QCOMPARE(f.frameId(), 0x089u);
    QCOMPARE(f.payload(), QByteArray::fromHex("1023030A0B000000"));
    const auto back = decodeEmcy(f);
    QVERIFY(back);
    QCOMPARE(back->errorCode, m.errorCode);
    QCOMPARE(back->manufacturerData, QByteArray::fromHex("0A0B000000"));
}

void TestEmcyConsumer::consumer_reportsEmergenciesFromTheBus()
{
    test::CanTestBus net;
    EmcyConsumer consumer(&net.masterLink);
    QSignalSpy emergency(&consumer, &EmcyConsumer::emergency);
    net.slaveLink.send(QCanBusFrame(0x080, QByteArray())); // SYNC
    EmcyMessage m;
    m.node = 1;
    m.errorCode = 0x8611;
    m.errorRegister = 0x01;
    net.slaveLink.send(encodeEmcy(m));
    QVERIFY(emergency.wait(1000));
    QCOMPARE(emergency.count(), 1);
    const EmcyMessage got = emergency.at(0).at(0).value<EmcyMessage>();
    QCOMPARE(got.node, quint8(1));
    QCOMPARE(got.errorCode, quint16(0x8611));
}

QTEST_GUILESS_MAIN(TestEmcyConsumer)
#include "tst_emcyconsumer.moc"
