#include "can/MemoryCanBus.h"
#include "can/MemoryCanDevice.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

class TestMemoryCanBus : public QObject
{
    Q_OBJECT

private slots:
    void writeFrame_deliversToOtherDevicesButNotToSender();
    void writeFrame_deliversThroughTheEventLoopOnly();
    void frames_arriveInWriteOrder();
    void threeDevices_everyOtherDeviceReceives();
    void deliveredFrame_carriesBusTimestamp();
    void answerWrittenDuringDelivery_arrivesAfterTheRequest();
    void dropPredicate_losesMatchingFramesOnly();
    void droppedFrame_isStillConfirmedWrittenToSender();
    void deviceDestroyedWhileFramePending_isSkipped();
};

void TestMemoryCanBus::writeFrame_deliversToOtherDevicesButNotToSender()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    QVERIFY(a->connectDevice());
    QVERIFY(b->connectDevice());
    QSignalSpy received(b, &QCanBusDevice::framesReceived);
    QSignalSpy own(a, &QCanBusDevice::framesReceived);
    QVERIFY(a->writeFrame(QCanBusFrame(0x123, QByteArray::fromHex("DEADBEEF"))));
    QVERIFY(received.wait(1000));
    const QCanBusFrame f = b->readFrame();
    QCOMPARE(f.frameId(), 0x123u);
    QCOMPARE(f.payload(), QByteArray::fromHex("DEADBEEF"));
    QCOMPARE(own.count(), 0);
    QCOMPARE(a->framesAvailable(), 0);
    QCOMPARE(bus.deliveredFrames(), 1);
}

void TestMemoryCanBus::writeFrame_deliversThroughTheEventLoopOnly()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    a->connectDevice();
    b->connectDevice();
    QSignalSpy received(b, &QCanBusDevice::framesReceived);
    a->writeFrame(QCanBusFrame(0x1, QByteArray(1, '\x01')));
    QCOMPARE(received.count(), 0); // not inside writeFrame()
    QCOMPARE(b->framesAvailable(), 0);
    QVERIFY(received.wait(1000));
    QCOMPARE(b->framesAvailable(), 1);
}

void TestMemoryCanBus::frames_arriveInWriteOrder()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    a->connectDevice();
    b->connectDevice();
    QSignalSpy transmitted(&bus, &MemoryCanBus::frameTransmitted);
    for (int i = 0; i < 20; ++i)
        a->writeFrame(QCanBusFrame(quint32(0x100 + i), QByteArray(1, char(i))));
    QTRY_COMPARE_WITH_TIMEOUT(b->framesAvailable(), 20, 1000);
    for (int i = 0; i < 20; ++i)
        QCOMPARE(b->readFrame().frameId(), quint32(0x100 + i));
    QCOMPARE(transmitted.count(), 20);
}

void TestMemoryCanBus::threeDevices_everyOtherDeviceReceives()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    MemoryCanDevice *c = bus.createDevice("c");
    for (MemoryCanDevice *d : {a, b, c})
        d->connectDevice();
    QCOMPARE(bus.devices().size(), 3);
    QSignalSpy written(b, &QCanBusDevice::framesWritten);
    b->writeFrame(QCanBusFrame(0x80, QByteArray()));
    QVERIFY(written.wait(1000));
    QCOMPARE(a->framesAvailable(), 1);
    QCOMPARE(b->framesAvailable(), 0);
    QCOMPARE(c->framesAvailable(), 1);
    QCOMPARE(written.at(0).at(0).toLongLong(), 1);
}

void TestMemoryCanBus::deliveredFrame_carriesBusTimestamp()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    a->connectDevice();
    b->connectDevice();
    const qint64 before = QDateTime::currentSecsSinceEpoch();
    a->writeFrame(QCanBusFrame(0x2, QByteArray()));
    QTRY_COMPARE_WITH_TIMEOUT(b->framesAvailable(), 1, 1000);
    const QCanBusFrame::TimeStamp t = b->readFrame().timeStamp();
    QVERIFY(t.seconds() >= before && t.seconds() <= before + 2);
}

void TestMemoryCanBus::answerWrittenDuringDelivery_arrivesAfterTheRequest()
{
    MemoryCanBus bus;
    MemoryCanDevice *client = bus.createDevice("client");
    MemoryCanDevice *server = bus.createDevice("server");
    client->connectDevice();
    server->connectDevice();
    connect(server, &QCanBusDevice::framesReceived, server, [server] {
        for (const QCanBusFrame &f : server->readAllFrames())
            server->writeFrame(QCanBusFrame(f.frameId() + 1, f.payload()));
    });
    QSignalSpy transmitted(&bus, &MemoryCanBus::frameTransmitted);
    client->writeFrame(QCanBusFrame(0x600, QByteArray(8, '\0')));
    QTRY_COMPARE_WITH_TIMEOUT(client->framesAvailable(), 1, 1000);
    QCOMPARE(transmitted.count(), 2);
    QCOMPARE(transmitted.at(0).at(0).value<QCanBusFrame>().frameId(), 0x600u);
    QCOMPARE(transmitted.at(1).at(0).value<QCanBusFrame>().frameId(), 0x601u);
}

void TestMemoryCanBus::dropPredicate_losesMatchingFramesOnly()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    a->connectDevice();
    b->connectDevice();
    bus.setDropPredicate([](const QCanBusFrame &f) { return f.frameId() == 0x181; });
    QSignalSpy dropped(&bus, &MemoryCanBus::frameDropped);
    a->writeFrame(QCanBusFrame(0x181, QByteArray(8, '\x01')));
    a->writeFrame(QCanBusFrame(0x182, QByteArray(8, '\x02')));
    QTRY_COMPARE_WITH_TIMEOUT(b->framesAvailable(), 1, 1000);
    QCOMPARE(b->readFrame().frameId(), 0x182u);
    QCOMPARE(dropped.count(), 1);
    QCOMPARE(bus.droppedFrames(), 1);
    QCOMPARE(bus.deliveredFrames(), 1);

    bus.clearDropPredicate();
    a->writeFrame(QCanBusFrame(0x181, QByteArray(8, '\x01')));
    QTRY_COMPARE_WITH_TIMEOUT(b->framesAvailable(), 1, 1000);
}

void TestMemoryCanBus::droppedFrame_isStillConfirmedWrittenToSender()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    a->connectDevice();
    b->connectDevice();
    bus.setDropPredicate([](const QCanBusFrame &) { return true; });
    QSignalSpy written(a, &QCanBusDevice::framesWritten);
    a->writeFrame(QCanBusFrame(0x181, QByteArray(2, '\0')));
    QVERIFY(written.wait(1000));
    QCOMPARE(b->framesAvailable(), 0);
}

void TestMemoryCanBus::deviceDestroyedWhileFramePending_isSkipped()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    MemoryCanDevice *c = bus.createDevice("c");
    for (MemoryCanDevice *d : {a, b, c})
        d->connectDevice();
    QSignalSpy transmitted(&bus, &MemoryCanBus::frameTransmitted);
    a->writeFrame(QCanBusFrame(0x10, QByteArray()));
    delete a; // the writer
    delete b; // a receiver
    QVERIFY(transmitted.wait(1000));
    QCOMPARE(c->framesAvailable(), 1);
    QCOMPARE(bus.devices().size(), 1);
}

QTEST_GUILESS_MAIN(TestMemoryCanBus)
#include "tst_memorycanbus.moc"
