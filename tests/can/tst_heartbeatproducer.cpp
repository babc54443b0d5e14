#include "CanTestBus.h"
#include "can/HeartbeatProducer.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

class TestHeartbeatProducer : public QObject
{
    Q_OBJECT

private slots:
    void period_sendsTheStateOnTheNodesHeartbeatId();
    void bootUp_sendsZeroThenPreOperational();
    void zeroPeriod_orSilence_sendsNothing();
};

void TestHeartbeatProducer::period_sendsTheStateOnTheNodesHeartbeatId()
{
    test::CanTestBus net;
    HeartbeatProducer producer(&net.slaveLink, 4);
    producer.setState(NmtState::Operational);
    producer.setPeriod(5);
    QCOMPARE(producer.period(), 5);
    QTRY_VERIFY_WITH_TIMEOUT(net.wire.size() >= 3, 1000);
    for (const QCanBusFrame &f : net.wire) {
        QCOMPARE(f.frameId(), 0x704u);
        QCOMPARE(f.payload(), QByteArray(1, '\x05'));
    }
}

void TestHeartbeatProducer::bootUp_sendsZeroThenPreOperational()
{
    test::CanTestBus net;
    HeartbeatProducer producer(&net.slaveLink, 4);
    producer.setState(NmtState::Stopped);
    producer.sendBootUp();
    QCOMPARE(producer.state(), NmtState::PreOperational);
    producer.setPeriod(5);
    QTRY_VERIFY_WITH_TIMEOUT(net.wire.size() >= 2, 1000);
    QCOMPARE(net.wire[0].payload(), QByteArray(1, '\0'));
    QCOMPARE(net.wire[1].payload(), QByteArray(1, '\x7F'));
}

void TestHeartbeatProducer::zeroPeriod_orSilence_sendsNothing()
{
    test::CanTestBus net;
    HeartbeatProducer producer(&net.slaveLink, 4);
    QSignalSpy transmitted(&net.bus, &MemoryCanBus::frameTransmitted);
    producer.setPeriod(5);
    QVERIFY(transmitted.wait(1000));
    producer.setPeriod(0);
    transmitted.clear();
    QVERIFY(!transmitted.wait(40));
    producer.setPeriod(5);
    producer.setSilent(true);
    producer.sendBootUp();
    QVERIFY(!transmitted.wait(40));
}

QTEST_GUILESS_MAIN(TestHeartbeatProducer)
#include "tst_heartbeatproducer.moc"
