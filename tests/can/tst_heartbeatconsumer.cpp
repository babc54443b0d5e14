#include "CanTestBus.h"
#include "can/HeartbeatConsumer.h"
#include "can/HeartbeatProducer.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

namespace {

constexpr quint8 node = 2;

struct HeartbeatSetup
{
    test::CanTestBus net;
    HeartbeatConsumer consumer{&net.masterLink};
    HeartbeatProducer producer{&net.slaveLink, node};
};

} // namespace

class TestHeartbeatConsumer : public QObject
{
    Q_OBJECT

private slots:
    void regularHeartbeats_keepTheNodeAlive();
    void silentNode_isReportedLostOnceWithTimeSinceLastHeartbeat();
    void noHeartbeatAtAll_isReportedLostCountingFromMonitorStart();
    void heartbeatAfterLoss_isReportedResumed();
    void bootUpNotOrdered_isReportedUnexpected();
    void bootUpAfterOrderedReset_isReportedExpected();
    void stateChange_isReportedOnce();
    void unmonitoredNodes_andStoppedMonitoring_areIgnored();
};

void TestHeartbeatConsumer::regularHeartbeats_keepTheNodeAlive()
{
    HeartbeatSetup s;
    QSignalSpy lost(&s.consumer, &HeartbeatConsumer::heartbeatLost);
    QSignalSpy received(&s.consumer, &HeartbeatConsumer::heartbeatReceived);
    s.consumer.monitor(node, 400);
    s.producer.setState(NmtState::Operational);
    s.producer.setPeriod(5);
    QTRY_VERIFY_WITH_TIMEOUT(received.count() >= 10, 1000);
    QCOMPARE(lost.count(), 0);
    QVERIFY(s.consumer.isAlive(node));
    QCOMPARE(s.consumer.lastState(node), std::optional<NmtState>(NmtState::Operational));
    QCOMPARE(received.last().at(1).value<NmtState>(), NmtState::Operational);
}

void TestHeartbeatConsumer::silentNode_isReportedLostOnceWithTimeSinceLastHeartbeat()
{
    HeartbeatSetup s;
    QSignalSpy lost(&s.consumer, &HeartbeatConsumer::heartbeatLost);
    QSignalSpy received(&s.consumer, &HeartbeatConsumer::heartbeatReceived);
    s.consumer.monitor(node, 40);
    s.producer.setPeriod(5);
    QVERIFY(received.wait(1000));
    s.producer.setSilent(true);
    QVERIFY(lost.wait(1000));
    QCOMPARE(lost.at(0).at(0).value<quint8>(), node);
    QVERIFY(lost.at(0).at(1).toLongLong() >= 40);
    QVERIFY(!s.consumer.isAlive(node));
    QVERIFY(!lost.wait(120)); // reported once, not every timeout
    QCOMPARE(lost.count(), 1);
}

void TestHeartbeatConsumer::noHeartbeatAtAll_isReportedLostCountingFromMonitorStart()
{
    HeartbeatSetup s;
    QSignalSpy lost(&s.consumer, &HeartbeatConsumer::heartbeatLost);
    s.consumer.monitor(node, 30);
    QVERIFY(!s.consumer.isAlive(node));
    QVERIFY(lost.wait(1000));
    QVERIFY(lost.at(0).at(1).toLongLong() >= 30);
    QCOMPARE(s.consumer.lastState(node), std::nullopt);
}

void TestHeartbeatConsumer::heartbeatAfterLoss_isReportedResumed()
{
    HeartbeatSetup s;
    QSignalSpy lost(&s.consumer, &HeartbeatConsumer::heartbeatLost);
    QSignalSpy resumed(&s.consumer, &HeartbeatConsumer::heartbeatResumed);
    s.consumer.monitor(node, 30);
    QVERIFY(lost.wait(1000));
    s.producer.setPeriod(5);
    QVERIFY(resumed.wait(1000));
    QCOMPARE(resumed.count(), 1);
    QVERIFY(s.consumer.isAlive(node));
}

void TestHeartbeatConsumer::bootUpNotOrdered_isReportedUnexpected()
{
    HeartbeatSetup s;
    QSignalSpy unexpected(&s.consumer, &HeartbeatConsumer::unexpectedBootUp);
    QSignalSpy expected(&s.consumer, &HeartbeatConsumer::bootUp);
    s.consumer.monitor(node, 1000);
    s.producer.sendBootUp();
    QVERIFY(unexpected.wait(1000));
    QCOMPARE(unexpected.at(0).at(0).value<quint8>(), node);
    QCOMPARE(expected.count(), 0);
    QCOMPARE(s.consumer.lastState(node), std::optional<NmtState>(NmtState::BootUp));
}

void TestHeartbeatConsumer::bootUpAfterOrderedReset_isReportedExpected()
{
    HeartbeatSetup s;
    QSignalSpy unexpected(&s.consumer, &HeartbeatConsumer::unexpectedBootUp);
    QSignalSpy expected(&s.consumer, &HeartbeatConsumer::bootUp);
    s.consumer.monitor(node, 1000);
    s.consumer.expectBootUp(node);
    s.producer.sendBootUp();
    QVERIFY(expected.wait(1000));
    QCOMPARE(unexpected.count(), 0);
    s.producer.sendBootUp(); // a second one was not ordered
    QVERIFY(unexpected.wait(1000));
}

void TestHeartbeatConsumer::stateChange_isReportedOnce()
{
    HeartbeatSetup s;
    QSignalSpy changed(&s.consumer, &HeartbeatConsumer::stateChanged);
    QSignalSpy received(&s.consumer, &HeartbeatConsumer::heartbeatReceived);
    s.consumer.monitor(node, 1000);
    s.producer.setPeriod(5);
    QTRY_VERIFY_WITH_TIMEOUT(received.count() >= 3, 1000);
    s.producer.setState(NmtState::Operational);
    const qsizetype before = received.count();
    QTRY_VERIFY_WITH_TIMEOUT(received.count() >= before + 3, 1000);
    QCOMPARE(changed.count(), 2);
    QCOMPARE(changed.at(0).at(1).value<NmtState>(), NmtState::PreOperational);
    QCOMPARE(changed.at(1).at(1).value<NmtState>(), NmtState::Operational);
}

void TestHeartbeatConsumer::unmonitoredNodes_andStoppedMonitoring_areIgnored()
{
    HeartbeatSetup s;
    QSignalSpy lost(&s.consumer, &HeartbeatConsumer::heartbeatLost);
    QSignalSpy unexpected(&s.consumer, &HeartbeatConsumer::unexpectedBootUp);
    s.producer.sendBootUp(); // node 2 not monitored
    s.consumer.monitor(9, 20);
    QVERIFY(s.consumer.isMonitoring(9));
    s.consumer.stopMonitoring(9);
    QVERIFY(!s.consumer.isMonitoring(9));
    QVERIFY(!lost.wait(80));
    QCOMPARE(unexpected.count(), 0);
}

QTEST_GUILESS_MAIN(TestHeartbeatConsumer)
#include "tst_heartbeatconsumer.moc"
