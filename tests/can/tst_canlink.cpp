#include "CanTestBus.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

class TestCanLink : public QObject
{
    Q_OBJECT

private slots:
    void receivedFrame_reachesEverySubscriber();
    void errorFrame_isKeptApartFromTheProtocolFrames();
    void send_reportsTheFrameSent();
    void send_whenDeviceUnconnected_failsWithReason();
    void send_whenDeviceRefuses_failsWithDeviceError();
};

void TestCanLink::receivedFrame_reachesEverySubscriber()
{
    test::CanTestBus net;
    QList<quint32> first, second;
    connect(&net.slaveLink, &CanLink::frameReceived, this,
            [&](const QCanBusFrame &f) { first.append(f.frameId()); });
    connect(&net.slaveLink, &CanLink::frameReceived, this,
            [&](const QCanBusFrame &f) { second.append(f.frameId()); });
    QVERIFY(net.masterLink.send(QCanBusFrame(0x601, QByteArray(8, '\0'))));
    QVERIFY(net.masterLink.send(QCanBusFrame(0x000, QByteArray(2, '\0'))));
    QTRY_COMPARE_WITH_TIMEOUT(first.size(), 2, 1000);
    QCOMPARE(first, (QList<quint32>{0x601, 0x000}));
    QCOMPARE(second, first);
    QCOMPARE(net.slave->framesAvailable(), 0); // the link took them
}

// CAN_ERR_BUSERROR is 0x080, the SYNC's COB-ID: a unit that took the error frame for a frame
// of the bus would see a SYNC.
void TestCanLink::errorFrame_isKeptApartFromTheProtocolFrames()
{
    test::CanTestBus net;
    QList<quint32> frames, errors;
    connect(&net.slaveLink, &CanLink::frameReceived, this,
            [&](const QCanBusFrame &f) { frames.append(f.frameId()); });
    connect(&net.slaveLink, &CanLink::errorFrameReceived, this,
            [&](const QCanBusFrame &f) { errors.append(quint32(f.error().toInt())); });
    QCanBusFrame error(QCanBusFrame::ErrorFrame);
    error.setError(QCanBusFrame::BusError);
    error.setPayload(QByteArray(8, '\0'));
    net.slave->injectErrorFrame(error);
    QVERIFY(net.masterLink.send(QCanBusFrame(0x080, QByteArray())));
    QTRY_COMPARE_WITH_TIMEOUT(frames.size(), 1, 1000);
    QCOMPARE(frames, QList<quint32>{0x080});
    QCOMPARE(errors, QList<quint32>{0x080});
    QCOMPARE(net.wire.size(), 1); // the error frame is not on the wire
}

void TestCanLink::send_reportsTheFrameSent()
{
    test::CanTestBus net;
    QSignalSpy sent(&net.masterLink, &CanLink::frameSent);
    QVERIFY(net.masterLink.send(QCanBusFrame(0x80, QByteArray())));
    QCOMPARE(sent.count(), 1);
    QVERIFY(net.masterLink.isConnected());
}

void TestCanLink::send_whenDeviceUnconnected_failsWithReason()
{
    test::CanTestBus net;
    net.master->disconnectDevice();
    QSignalSpy failed(&net.masterLink, &CanLink::sendFailed);
    QVERIFY(!net.masterLink.send(QCanBusFrame(0x80, QByteArray())));
    QCOMPARE(failed.count(), 1);
    QVERIFY(net.masterLink.lastError().contains("not connected"));
    QVERIFY(!net.masterLink.isConnected());
}

void TestCanLink::send_whenDeviceRefuses_failsWithDeviceError()
{
    test::CanTestBus net;
    net.master->setRefuseWrite(true);
    QVERIFY(!net.masterLink.send(QCanBusFrame(0x80, QByteArray())));
    QVERIFY(net.masterLink.lastError().contains("failed to write"));
}

QTEST_GUILESS_MAIN(TestCanLink)
#include "tst_canlink.moc"
