// The master's timeouts at the SYNC periods of docs/can-protocol.md §8.2 (2, 5 and 10 ms), over
// the memory bus: a robot side that stops sending SYNC mid-trial is detected max(10 Ts, 50 ms)
// after its last SYNC and the stop ends max(20 Ts, 100 ms) later; the master's own pause
// (planning the return move) is not counted as the robot's.
#include "WorkerSetup.h"
#include "can/CanLink.h"
#include "can/EmcyConsumer.h"
#include "can/HeartbeatConsumer.h"
#include "can/MemoryCanBus.h"
#include "canrobot/TrialWatchdog.h"

#include <QElapsedTimer>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>
#include <QThread>

using namespace learnid;

class TestTimeouts : public QObject
{
    Q_OBJECT

private slots:
    void silentRobot_detectedAfterTheSyncTimeout_stopWithinItsBound_data();
    void silentRobot_detectedAfterTheSyncTimeout_stopWithinItsBound();
    void mastersOwnPause_syncGapCountsFromItsEnd();
};

void TestTimeouts::silentRobot_detectedAfterTheSyncTimeout_stopWithinItsBound_data()
{
    QTest::addColumn<int>("periodMs");
    QTest::addColumn<int>("syncTimeoutMs");     // max(10 Ts, 50 ms)
    QTest::addColumn<int>("stopBoundMs");       // max(20 Ts, 100 ms)
    QTest::newRow("2 ms") << 2 << 50 << 100;    // the floors: 10 Ts would be 20 ms
    QTest::newRow("5 ms") << 5 << 50 << 100;    // 10 Ts = the floor; 2 Ts (10 ms) was too short
    QTest::newRow("10 ms") << 10 << 100 << 200; // 10 and 20 periods
}

void TestTimeouts::silentRobot_detectedAfterTheSyncTimeout_stopWithinItsBound()
{
    QFETCH(int, periodMs);
    QFETCH(int, syncTimeoutMs);
    QFETCH(int, stopBoundMs);
    test::WorkerSetup s;
    for (const int node : {1, 2}) // the robot's SYNC period, which the master checks
        s.drives.node(node).od.setValue(0x1006, 0, periodMs * 1000.0);
    TrialPlan plan = test::testPlan(1000);
    plan.desired.samplePeriod = periodMs / 1000.0;
    plan.controller.samplePeriod = plan.desired.samplePeriod;
    plan.motionDuration = (plan.samples() - 1) * plan.desired.samplePeriod;

    // The robot side's clock stops after 20 SYNCs with the drives enabled (in the return move).
    QElapsedTimer sinceLastSync;
    int enabledSyncs = 0;
    s.drives.onSync = [&](qint64) {
        if (s.drives.node(1).drive.state() != cia402::State::OperationEnabled ||
            ++enabledSyncs != 20)
            return;
        sinceLastSync.start();
        // Queued: the SYNC timer is started again after this call.
        QMetaObject::invokeMethod(
            &s.drives, [&s] { s.drives.stopSync(); }, Qt::QueuedConnection);
    };
    s.drives.startSync(periodMs);
    const TrialRecord r = s.run(plan);
    const qint64 total = sinceLastSync.elapsed();

    QVERIFY2(r.status == TrialStatus::Aborted, qPrintable(r.message));
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("no SYNC for (\\d+) ms")).match(r.message);
    QVERIFY2(m.hasMatch(), qPrintable(r.message));
    const int detectedMs = m.captured(1).toInt();
    // Not before the timeout of the formula; on time within what a loaded machine delays a
    // precise timer.
    QVERIFY2(detectedMs >= syncTimeoutMs, qPrintable(r.message));
    QVERIFY2(detectedMs < syncTimeoutMs + 50, qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("at SYNC")), qPrintable(r.message));
    QVERIFY(s.drives.controlwords.contains(0x0002)); // quick stop sent
    // No SYNC comes to end the stop: its bound does (a coarse timer, up to 5 % early, and the
    // watchdog's clock and this test's start a SYNC's handling apart: 144 ms against 145 was
    // seen at 2 ms, so 10 % is allowed), and the whole takes less than a second from the
    // robot's last SYNC.
    QVERIFY2(total >= syncTimeoutMs + stopBoundMs * 90 / 100, qPrintable(QString::number(total)));
    QVERIFY2(total < 1000, qPrintable(QString::number(total)));
}

// The CAN thread plans the return move between two SYNCs (150 ms in the VM of
// scripts/test-socketcan); the SYNCs of that time wait in the socket. Without restartClocks()
// the watchdog reports the master's pause as the robot's silence at once; with it the gap
// counts from the end of the pause.
void TestTimeouts::mastersOwnPause_syncGapCountsFromItsEnd()
{
    MemoryCanBus bus;
    MemoryCanDevice *device = bus.createDevice(QStringLiteral("master"));
    device->connectDevice();
    CanLink link(device);
    HeartbeatConsumer heartbeat(&link);
    EmcyConsumer emcy(&link);
    const int gapMs = 50;
    for (const bool restart : {false, true}) {
        TrialWatchdog watchdog(&heartbeat, &emcy);
        QSignalSpy faults(&watchdog, &TrialWatchdog::fault);
        watchdog.start({1, 2}, 10000, gapMs);
        QThread::msleep(2 * gapMs); // the pause: this thread reads no frame
        QElapsedTimer sincePause;
        sincePause.start();
        if (restart)
            watchdog.restartClocks();
        QVERIFY(faults.wait(1000));
        const qint64 ms = sincePause.elapsed();
        const QString message = faults.first().at(1).toString();
        QVERIFY2(message.contains(QLatin1String("no SYNC for")), qPrintable(message));
        if (restart)
            QVERIFY2(ms >= gapMs, qPrintable(QString::number(ms))); // counted from the pause's end
        else
            QVERIFY2(ms < gapMs, qPrintable(QString::number(ms))); // the pause taken for silence
    }
}

QTEST_GUILESS_MAIN(TestTimeouts)
#include "tst_timeouts.moc"
