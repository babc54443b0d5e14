// The timeouts of a CAN trial in SYNC periods with a floor in milliseconds (docs/can-protocol.md
// §8.2), at the SYNC periods the tool runs at: 2 ms (the paper scenario), 5 and 10 ms (a loaded
// machine, the VM of scripts/test-socketcan), and 20 ms.
#include "can/CanTimeouts.h"

#include <QTest>

using namespace learnid;

class TestCanTimeouts : public QObject
{
    Q_OBJECT

private slots:
    void periodsWithFloor_data();
    void periodsWithFloor();
    void floor_isPeriodsTimesTsOrTheFloor();
};

void TestCanTimeouts::periodsWithFloor_data()
{
    QTest::addColumn<double>("ts");
    QTest::addColumn<int>("syncMs");
    QTest::addColumn<int>("setpointSyncs");
    QTest::addColumn<int>("heartbeatMs");
    QTest::addColumn<int>("stopMs");
    // sync: max(10 Ts, 50 ms); set-point: the SYNCs covering max(3 Ts, 50 ms);
    // heartbeat: max(10 Ts, 100 ms); stop: max(20 Ts, 100 ms).
    QTest::newRow("2 ms") << 0.002 << 50 << 25 << 100 << 100;
    QTest::newRow("5 ms") << 0.005 << 50 << 10 << 100 << 100;
    QTest::newRow("10 ms") << 0.010 << 100 << 5 << 100 << 200;
    QTest::newRow("20 ms") << 0.020 << 200 << 3 << 200 << 400;
    QTest::newRow("3 ms") << 0.003 << 50 << 17 << 100 << 100; // 17 x 3 = 51 >= 50
}

void TestCanTimeouts::periodsWithFloor()
{
    QFETCH(double, ts);
    QFETCH(int, syncMs);
    QFETCH(int, setpointSyncs);
    QFETCH(int, heartbeatMs);
    QFETCH(int, stopMs);
    QCOMPARE(cantimeouts::syncTimeoutMs(ts), syncMs);
    QCOMPARE(cantimeouts::setpointTimeoutSyncs(ts), setpointSyncs);
    QCOMPARE(cantimeouts::heartbeatPeriodMs(ts), heartbeatMs);
    QCOMPARE(cantimeouts::stopBoundMs(ts), stopMs);
    // The set-point timeout covers the floor, one SYNC fewer does not (unless 3 periods do).
    QVERIFY(setpointSyncs * ts * 1000 >= cantimeouts::setpointTimeoutFloorMs - 1e-9 ||
            setpointSyncs == cantimeouts::setpointTimeoutPeriods);
    QVERIFY((setpointSyncs - 1) * ts * 1000 < cantimeouts::setpointTimeoutFloorMs - 1e-9 ||
            setpointSyncs == cantimeouts::setpointTimeoutPeriods);
    // The quick stop (12 SYNCs with the drive of docs/can-protocol.md §5.3) ends within the bound.
    QVERIFY(12 * ts * 1000 < stopMs);
}

void TestCanTimeouts::floor_isPeriodsTimesTsOrTheFloor()
{
    QCOMPARE(cantimeouts::periodsWithFloorMs(0.004, 10, 0), 40);  // not 41 by rounding
    QCOMPARE(cantimeouts::periodsWithFloorMs(0.0041, 10, 0), 41); // rounded up
    QCOMPARE(cantimeouts::periodsWithFloorMs(0.004, 10, 45), 45);
    QCOMPARE(cantimeouts::periodsWithFloorMs(0.0, 10, 45), 45); // no period: the floor
    QCOMPARE(cantimeouts::heartbeatPeriodMs(10.0), 65535);      // 0x1017 is UNSIGNED16
}

QTEST_GUILESS_MAIN(TestCanTimeouts)
#include "tst_cantimeouts.moc"
