#include "can/MemoryCanBus.h"
#include "can/MemoryCanDevice.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

class TestMemoryCanDevice : public QObject
{
    Q_OBJECT

private slots:
    void connectDevice_entersConnectedStateAndSignalsIt();
    void connectDevice_refused_staysUnconnectedWithConnectionError();
    void connectDevice_withoutBus_fails();
    void connectDevice_twice_fails();
    void disconnectDevice_entersUnconnectedAndStopsReception();
    void writeFrame_whenUnconnected_failsWithWriteError();
    void writeFrame_canFdOrErrorFrame_isRefused();
    void refuseWrite_failsWithWriteError();
    void receiveOwnKey_deliversOwnFramesToo();
    void rawFilter_passesMatchingFramesOnly();
    void injectError_busOff_reportsAndDisconnects();
    void interpretErrorFrame_describesErrorFramesOnly();
    void deviceInfo_namesPluginAndDevice();
};

void TestMemoryCanDevice::connectDevice_entersConnectedStateAndSignalsIt()
{
    MemoryCanBus bus;
    MemoryCanDevice *d = bus.createDevice("can0");
    QSignalSpy states(d, &QCanBusDevice::stateChanged);
    QCOMPARE(d->state(), QCanBusDevice::UnconnectedState);
    QVERIFY(d->connectDevice());
    QCOMPARE(d->state(), QCanBusDevice::ConnectedState);
    QCOMPARE(states.count(), 2);
    QCOMPARE(states.at(0).at(0).value<QCanBusDevice::CanBusDeviceState>(),
             QCanBusDevice::ConnectingState);
    QCOMPARE(states.at(1).at(0).value<QCanBusDevice::CanBusDeviceState>(),
             QCanBusDevice::ConnectedState);
    QCOMPARE(d->error(), QCanBusDevice::NoError);
}

void TestMemoryCanDevice::connectDevice_refused_staysUnconnectedWithConnectionError()
{
    MemoryCanBus bus;
    MemoryCanDevice *d = bus.createDevice("can0");
    d->setRefuseConnect(true);
    QSignalSpy errors(d, &QCanBusDevice::errorOccurred);
    QVERIFY(!d->connectDevice());
    QCOMPARE(d->state(), QCanBusDevice::UnconnectedState);
    QCOMPARE(errors.count(), 1);
    QCOMPARE(d->error(), QCanBusDevice::ConnectionError);
    QVERIFY(d->errorString().contains("can0"));
    d->setRefuseConnect(false);
    QVERIFY(d->connectDevice());
}

void TestMemoryCanDevice::connectDevice_withoutBus_fails()
{
    MemoryCanDevice d("lonely", nullptr);
    QVERIFY(!d.connectDevice());
    QCOMPARE(d.error(), QCanBusDevice::ConnectionError);
}

void TestMemoryCanDevice::connectDevice_twice_fails()
{
    MemoryCanBus bus;
    MemoryCanDevice *d = bus.createDevice("can0");
    QVERIFY(d->connectDevice());
    QVERIFY(!d->connectDevice());
    QCOMPARE(d->state(), QCanBusDevice::ConnectedState);
}

void TestMemoryCanDevice::disconnectDevice_entersUnconnectedAndStopsReception()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    MemoryCanDevice *c = bus.createDevice("c");
    for (MemoryCanDevice *d : {a, b, c})
        d->connectDevice();
    QSignalSpy states(b, &QCanBusDevice::stateChanged);
    b->disconnectDevice();
    QCOMPARE(b->state(), QCanBusDevice::UnconnectedState);
    QCOMPARE(states.count(), 2); // closing, unconnected
    a->writeFrame(QCanBusFrame(0x5, QByteArray()));
    QTRY_COMPARE_WITH_TIMEOUT(c->framesAvailable(), 1, 1000);
    QCOMPARE(b->framesAvailable(), 0);
    QVERIFY(b->connectDevice()); // and back
    a->writeFrame(QCanBusFrame(0x5, QByteArray()));
    QTRY_COMPARE_WITH_TIMEOUT(b->framesAvailable(), 1, 1000);
}

void TestMemoryCanDevice::writeFrame_whenUnconnected_failsWithWriteError()
{
    MemoryCanBus bus;
    MemoryCanDevice *d = bus.createDevice("can0");
    QVERIFY(!d->writeFrame(QCanBusFrame(0x1, QByteArray())));
    QCOMPARE(d->error(), QCanBusDevice::WriteError);
}

void TestMemoryCanDevice::writeFrame_canFdOrErrorFrame_isRefused()
{
    MemoryCanBus bus;
    MemoryCanDevice *d = bus.createDevice("can0");
    d->connectDevice();
    QCanBusFrame fd(0x1, QByteArray(12, '\0'));
    fd.setFlexibleDataRateFormat(true);
    QVERIFY(!d->writeFrame(fd));
    QCanBusFrame error(QCanBusFrame::ErrorFrame);
    error.setError(QCanBusFrame::BusOffError);
    QVERIFY(!d->writeFrame(error));
    QCOMPARE(d->error(), QCanBusDevice::WriteError);
    QVERIFY(d->writeFrame(QCanBusFrame(0x1, QByteArray(8, '\0'))));
}

void TestMemoryCanDevice::refuseWrite_failsWithWriteError()
{
    MemoryCanBus bus;
    MemoryCanDevice *d = bus.createDevice("can0");
    d->connectDevice();
    d->setRefuseWrite(true);
    QSignalSpy errors(d, &QCanBusDevice::errorOccurred);
    QVERIFY(!d->writeFrame(QCanBusFrame(0x1, QByteArray())));
    QCOMPARE(errors.count(), 1);
    QCOMPARE(d->error(), QCanBusDevice::WriteError);
}

void TestMemoryCanDevice::receiveOwnKey_deliversOwnFramesToo()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    a->setConfigurationParameter(QCanBusDevice::ReceiveOwnKey, true);
    a->connectDevice();
    a->writeFrame(QCanBusFrame(0x7, QByteArray(1, '\x07')));
    QTRY_COMPARE_WITH_TIMEOUT(a->framesAvailable(), 1, 1000);
}

void TestMemoryCanDevice::rawFilter_passesMatchingFramesOnly()
{
    MemoryCanBus bus;
    MemoryCanDevice *a = bus.createDevice("a");
    MemoryCanDevice *b = bus.createDevice("b");
    QCanBusDevice::Filter sdoAnswers;
    sdoAnswers.frameId = 0x580;
    sdoAnswers.frameIdMask = 0x780;
    sdoAnswers.format = QCanBusDevice::Filter::MatchBaseFormat;
    b->setConfigurationParameter(QCanBusDevice::RawFilterKey,
                                 QVariant::fromValue(QList<QCanBusDevice::Filter>{sdoAnswers}));
    a->connectDevice();
    b->connectDevice();
    a->writeFrame(QCanBusFrame(0x181, QByteArray()));
    a->writeFrame(QCanBusFrame(0x583, QByteArray()));
    QCanBusFrame extended(0x583, QByteArray());
    extended.setExtendedFrameFormat(true);
    a->writeFrame(extended);
    a->writeFrame(QCanBusFrame(0x5FF, QByteArray()));
    QSignalSpy written(a, &QCanBusDevice::framesWritten);
    QTRY_COMPARE_WITH_TIMEOUT(written.count(), 4, 1000);
    QCOMPARE(b->framesAvailable(), 2);
    QCOMPARE(b->readFrame().frameId(), 0x583u);
    QCOMPARE(b->readFrame().frameId(), 0x5FFu);
}

void TestMemoryCanDevice::injectError_busOff_reportsAndDisconnects()
{
    MemoryCanBus bus;
    MemoryCanDevice *d = bus.createDevice("can0");
    d->connectDevice();
    QSignalSpy errors(d, &QCanBusDevice::errorOccurred);
    d->injectError("bus off", QCanBusDevice::ConnectionError, true);
    QCOMPARE(errors.count(), 1);
    QCOMPARE(d->errorString(), QString("bus off"));
    QCOMPARE(d->state(), QCanBusDevice::UnconnectedState);
}

void TestMemoryCanDevice::interpretErrorFrame_describesErrorFramesOnly()
{
    MemoryCanDevice d("x", nullptr);
    QVERIFY(d.interpretErrorFrame(QCanBusFrame(0x1, QByteArray())).isEmpty());
    QCanBusFrame error(QCanBusFrame::ErrorFrame);
    error.setError(QCanBusFrame::BusOffError);
    QVERIFY(d.interpretErrorFrame(error).contains("0x40"));
}

void TestMemoryCanDevice::deviceInfo_namesPluginAndDevice()
{
    MemoryCanDevice d("vcan7", nullptr);
    QCOMPARE(d.deviceInfo().name(), QString("vcan7"));
    QCOMPARE(d.deviceInfo().plugin(), QString("memory"));
    QVERIFY(d.deviceInfo().isVirtual());
}

QTEST_GUILESS_MAIN(TestMemoryCanDevice)
#include "tst_memorycandevice.moc"
