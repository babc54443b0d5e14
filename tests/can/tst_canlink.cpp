#include "CanTestBus.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

class TestCanLink : public QObject
{
    Q_OBJECT

private slots:
    void receivedFrame_reachesEverySubscriber();
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
