// CanRobotWorker over the memory bus and a scripted robot side: configuration, the trial
// streamed by SYNC, every abort path, apply.
#include "ScriptedDrives.h"
#include "TestPlan.h"
#include "WorkerSetup.h"
#include "can/MemoryCanBus.h"
#include "canrobot/CanRobotWorker.h"
#include "canrobot/DriveScaling.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QPointer>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <optional>

using namespace learnid;

namespace {

using test::WorkerSetup;

const DriveScaling scaling{1u << 20, 1, 320};

} // namespace

class TestCanRobotWorker : public QObject
{
    Q_OBJECT

private slots:
    void trial_collectsSamplesBySyncAcrossCounterWrap();
    void lateSetpoints_countedInTheRecord();
    void configurationAbort_namesObjectAndCode_nothingMoves();
    void missingTpdo_abortsWithQuickStop();
    void emcy_abortsFaultedWithQuickStop();
    void heartbeatLoss_aborts();
    void cancel_stopsAtNextSync();
    void deviceLost_endsTheTrialNamingTheDevice();
    void errorFrame_fatalStopsNamingTheError_otherIsOnlyLogged_data();
    void errorFrame_fatalStopsNamingTheError_otherIsOnlyLogged();
    void apply_writesReadsBackAndStores();
    void apply_readBackMismatch_storesNothing();
    void apply_abort_storesNothing();
    void lostConnection_failedReconnect_trialAndApplyEndWithTheError();
    void apply_silentNode_saysSoInOneSentence();
    void busLoadAtThePlansPeriod_refusedBeforeAnyFrame_offeredPeriodPasses();
};

void TestCanRobotWorker::trial_collectsSamplesBySyncAcrossCounterWrap()
{
    WorkerSetup s;
    s.drives.setCounter(200); // the plan's samples straddle the wrap 240 -> 1
    s.drives.startSync();
    const TrialPlan plan = test::testPlan(300);
    const TrialRecord r = s.run(plan);
    QVERIFY2(r.completed(), qPrintable(r.message));
    QCOMPARE(r.samples(), plan.samples());
    QVERIFY(s.drives.syncs() > 240);
    // The ideal drive holds exactly the target it was sent for this SYNC: sample k must be
    // plan sample k in the drive's integer units, and tau the offset sent with it.
    for (int k = 0; k < r.samples(); ++k) {
        for (int j = 0; j < 2; ++j) {
            const double q = scaling.toRad(scaling.toIncrements(plan.desired.q(j, k)));
            const double tau = scaling.toNewtonMetre(scaling.toPermille(plan.feedforward(j, k)));
            QCOMPARE(r.q(j, k), q);
            QCOMPARE(r.tau(j, k), tau);
        }
    }
    // Configuration reached the drives.
    QCOMPARE(s.drives.node(2).od.value(0x2100, 1), 5000.0);
    QCOMPARE(s.drives.node(1).od.value(0x2300, 0), 8.0);
    QCOMPARE(s.drives.node(1).od.value(0x1017, 0), 100.0);
    QCOMPARE(s.drives.node(1).od.value(0x1A00, 0), 3.0);
    QTRY_COMPARE(s.drives.node(2).nmt, NmtState::PreOperational); // after the trial
    QVERIFY(s.drives.controlwords.contains(0x0006));              // shutdown at the end
    QCOMPARE(s.worker->lastStatistics().lateSetpoints, 0);
    QCOMPARE(r.lateSetpoints, 0);
}

void TestCanRobotWorker::lateSetpoints_countedInTheRecord()
{
    WorkerSetup s;
    s.drives.lateSetpoint = [](int node, qint64 n) {
        return node == 1 && n % 23 == 0;
    };
    s.drives.startSync();
    const TrialPlan plan = test::testPlan(300);
    const TrialRecord r = s.run(plan);
    QVERIFY2(r.completed(), qPrintable(r.message));
    QCOMPARE(r.samples(), plan.samples());
    // The ideal drive follows every set-point but the late ones, where it holds the one before:
    // joint 1 is off the plan's sample there, joint 2 never.
    int held = 0;
    for (int k = 0; k < r.samples(); ++k) {
        held += r.q(0, k) != scaling.toRad(scaling.toIncrements(plan.desired.q(0, k)));
        QCOMPARE(r.q(1, k), scaling.toRad(scaling.toIncrements(plan.desired.q(1, k))));
    }
    QVERIFY2(held >= 10, qPrintable(QString::number(held))); // about 300 / 23 SYNCs
    QCOMPARE(r.lateSetpoints, held);
    QCOMPARE(s.worker->lastStatistics().lateSetpoints, held);
}

void TestCanRobotWorker::configurationAbort_namesObjectAndCode_nothingMoves()
{
    WorkerSetup s;
    s.drives.node(2).server->setRefusal([](quint16 index, quint8 sub, bool write) {
        return write && index == 0x2100 && sub == 3 ? sdoabort::invalidValue : 0u;
    });
    s.drives.startSync();
    const TrialRecord r = s.run(test::testPlan(50));
    QCOMPARE(r.status, TrialStatus::Faulted);
    QCOMPARE(r.samples(), 0);
    QVERIFY2(r.message.contains(QLatin1String("0x2100:03")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("node 2")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("0x06090030")), qPrintable(r.message));
    QVERIFY(s.drives.controlwords.isEmpty()); // no RPDO: nothing moved
    QCOMPARE(s.drives.node(1).nmt, NmtState::PreOperational);
}

void TestCanRobotWorker::missingTpdo_abortsWithQuickStop()
{
    WorkerSetup s;
    qint64 dropAt = -1;
    s.drives.dropTpdo = [&](int node, qint64 n) {
        return node == 2 && n == dropAt;
    };
    s.drives.onSync = [&](qint64 n) {
        if (dropAt < 0 && s.drives.node(1).drive.state() == cia402::State::OperationEnabled)
            dropAt = n + 300; // during the return move
    };
    s.drives.startSync();
    const TrialRecord r = s.run(test::testPlan(100));
    QCOMPARE(r.status, TrialStatus::Aborted);
    QVERIFY2(r.message.contains(QLatin1String("node 2")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("TPDO")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("SYNC")), qPrintable(r.message));
    QVERIFY(s.drives.controlwords.contains(0x0002));
}

void TestCanRobotWorker::emcy_abortsFaultedWithQuickStop()
{
    WorkerSetup s;
    int enabledSyncs = 0;
    s.drives.onSync = [&](qint64) {
        if (s.drives.node(1).drive.state() == cia402::State::OperationEnabled &&
            ++enabledSyncs == 500)
            s.drives.sendEmcy(1, 0x8611);
    };
    s.drives.startSync();
    const TrialPlan plan = test::testPlan(200);
    const TrialRecord r = s.run(plan);
    QCOMPARE(r.status, TrialStatus::Faulted);
    QVERIFY2(r.message.contains(QLatin1String("0x8611")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("SYNC")), qPrintable(r.message));
    QVERIFY2(r.samples() > 0 && r.samples() < plan.samples(), // the partial record is kept
             qPrintable(QString::number(r.samples())));
    QVERIFY(s.drives.controlwords.contains(0x0002));
    QTRY_COMPARE(s.drives.node(2).nmt, NmtState::PreOperational);
}

void TestCanRobotWorker::heartbeatLoss_aborts()
{
    WorkerSetup s;
    bool silenced = false;
    s.drives.onSync = [&](qint64) {
        if (!silenced && s.drives.node(1).drive.state() == cia402::State::OperationEnabled) {
            silenced = true;
            s.drives.node(2).heartbeat->setSilent(true);
        }
    };
    s.drives.startSync();
    QElapsedTimer clock;
    clock.start();
    const TrialRecord r = s.run(test::testPlan(1000));
    QCOMPARE(r.status, TrialStatus::Faulted);
    QVERIFY2(r.message.contains(QLatin1String("heartbeat of node 2")), qPrintable(r.message));
    QVERIFY(clock.elapsed() < 2000);
}

void TestCanRobotWorker::cancel_stopsAtNextSync()
{
    WorkerSetup s;
    std::atomic_bool cancel{false};
    TrialMonitor monitor;
    monitor.cancel = &cancel;
    int progressCalls = 0;
    monitor.progress = [&](int done, int) {
        if (++progressCalls == 2)
            cancel = true;
        Q_UNUSED(done)
    };
    s.drives.startSync();
    const TrialRecord r = s.run(test::testPlan(1000), monitor);
    QCOMPARE(r.status, TrialStatus::Cancelled);
    QVERIFY(r.samples() >= 200 && r.samples() < 1000);
    QVERIFY(s.drives.controlwords.contains(0x0002));
}

void TestCanRobotWorker::deviceLost_endsTheTrialNamingTheDevice()
{
    WorkerSetup s;
    int enabledSyncs = 0;
    s.drives.onSync = [&](qint64) {
        if (s.drives.node(1).drive.state() == cia402::State::OperationEnabled &&
            ++enabledSyncs == 100 && s.master)
            s.master->injectError(QStringLiteral("cable unplugged"), QCanBusDevice::ConnectionError,
                                  true);
    };
    s.drives.startSync();
    const TrialRecord r = s.run(test::testPlan(200));
    QCOMPARE(r.status, TrialStatus::Faulted);
    QVERIFY2(r.message.contains(QLatin1String("memory/master")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("cable unplugged")), qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("SYNC")), qPrintable(r.message));
    // The next call connects again.
    s.drives.onSync = nullptr;
    QCOMPARE(s.apply(Eigen::Vector3d(20, 5, 8)), QString());
}

void TestCanRobotWorker::errorFrame_fatalStopsNamingTheError_otherIsOnlyLogged_data()
{
    // Error classes (the identifier) and byte 1 of a controller error, as in linux/can/error.h.
    QTest::addColumn<int>("classes");
    QTest::addColumn<int>("controller");
    QTest::addColumn<QString>("expected"); // in the trial's message; empty: the trial completes
    QTest::newRow("bus-off") << 0x40 << 0x00 << QStringLiteral("reported bus off");
    QTest::newRow("error-passive")
        << 0x04 << 0x20 << QStringLiteral("reported controller error passive (tx)");
    QTest::newRow("rx-overflow") << 0x04 << 0x01 << QStringLiteral("buffer overflow");
    QTest::newRow("no-ack") << 0x20 << 0x00 << QStringLiteral("no acknowledgement");
    QTest::newRow("warning") << 0x04 << 0x08 << QString();
    QTest::newRow("lost-arbitration") << 0x02 << 0x00 << QString();
}

void TestCanRobotWorker::errorFrame_fatalStopsNamingTheError_otherIsOnlyLogged()
{
    QFETCH(int, classes);
    QFETCH(int, controller);
    QFETCH(QString, expected);
    WorkerSetup s;
    int enabledSyncs = 0;
    QElapsedTimer sinceError;
    s.drives.onSync = [&](qint64) {
        if (s.drives.node(1).drive.state() != cia402::State::OperationEnabled ||
            ++enabledSyncs != 300 || !s.master)
            return;
        QCanBusFrame error(QCanBusFrame::ErrorFrame);
        error.setError(QCanBusFrame::FrameErrors(classes));
        QByteArray payload(8, '\0');
        payload[1] = char(controller);
        error.setPayload(payload);
        s.master->injectErrorFrame(error);
        sinceError.start();
    };
    s.drives.startSync();
    const TrialPlan plan = test::testPlan(400);
    const TrialRecord r = s.run(plan);
    QVERIFY(sinceError.isValid()); // injected during the trial
    if (expected.isEmpty()) {
        QVERIFY2(r.completed(), qPrintable(r.message));
        QCOMPARE(r.samples(), plan.samples());
        return;
    }
    const qint64 ms = sinceError.elapsed();
    QCOMPARE(r.status, TrialStatus::Faulted);
    QVERIFY2(r.message.contains(QLatin1String("memory/master")), qPrintable(r.message));
    QVERIFY2(r.message.contains(expected), qPrintable(r.message));
    QVERIFY2(r.message.contains(QStringLiteral("error frame 0x%1").arg(classes, 0, 16)),
             qPrintable(r.message));
    QVERIFY2(r.message.contains(QLatin1String("SYNC")), qPrintable(r.message));
    QVERIFY(s.drives.controlwords.contains(0x0002)); // quick stop: the device still writes
    QVERIFY2(ms < 1000, qPrintable(QString::number(ms)));
}

void TestCanRobotWorker::apply_writesReadsBackAndStores()
{
    WorkerSetup s;
    QCOMPARE(s.apply(Eigen::Vector3d(20.5, 5.25, 8.125)), QString());
    for (const int node : {1, 2}) {
        QCOMPARE(s.drives.node(node).od.value(0x2200, 0), 3.0);
        QCOMPARE(s.drives.node(node).od.value(0x2200, 2), 5.25);
        QCOMPARE(s.drives.node(node).stores, 1);
    }
}

void TestCanRobotWorker::apply_readBackMismatch_storesNothing()
{
    WorkerSetup s;
    // Node 2 rounds what it receives (a drive that keeps a different precision).
    connect(&s.drives.node(2).od, &ObjectDictionary::valueWritten, [&](quint16 index, quint8 sub) {
        if (index == 0x2200 && sub == 3)
            s.drives.node(2).od.setValue(0x2200, 3, 8.0);
    });
    const QString error = s.apply(Eigen::Vector3d(20, 5, 8.125));
    QVERIFY2(error.contains(QLatin1String("node 2, object 0x2200:03")), qPrintable(error));
    QVERIFY2(error.contains(QLatin1String("nothing was stored")), qPrintable(error));
    QCOMPARE(s.drives.node(1).stores, 0);
    QCOMPARE(s.drives.node(2).stores, 0);
}

void TestCanRobotWorker::apply_abort_storesNothing()
{
    WorkerSetup s;
    s.drives.node(1).server->setRefusal([](quint16 index, quint8 sub, bool write) {
        return write && index == 0x2200 && sub == 1 ? sdoabort::cannotStore : 0u;
    });
    const QString error = s.apply(Eigen::Vector3d(20, 5, 8));
    QVERIFY2(error.contains(QLatin1String("0x2200:01")), qPrintable(error));
    QVERIFY2(error.contains(QLatin1String("0x08000020")), qPrintable(error));
    QVERIFY2(error.contains(QLatin1String("0x1010 not written")), qPrintable(error));
    QCOMPARE(s.drives.node(1).stores, 0);
    QCOMPARE(s.drives.node(2).stores, 0);
}

// The units of a lost connection are gone when its reconnect fails: a trial and an apply must
// end with the reconnect's error (under ASan: no use of the units freed with the connection).
void TestCanRobotWorker::lostConnection_failedReconnect_trialAndApplyEndWithTheError()
{
    WorkerSetup s;
    const Eigen::Vector3d phi(20.5, 5.25, 8.125);
    QCOMPARE(s.apply(phi), QString()); // connects and builds the units
    QVERIFY(s.master);
    s.master->injectError(QStringLiteral("cable unplugged"), QCanBusDevice::ConnectionError, true);
    s.refuseDevice = QStringLiteral("adapter not found");

    s.drives.startSync();
    const TrialRecord r = s.run(test::testPlan(50));
    QCOMPARE(r.status, TrialStatus::Refused);
    QVERIFY2(r.message.contains(QLatin1String("adapter not found")), qPrintable(r.message));
    QCOMPARE(r.samples(), 0);

    const QString error = s.apply(phi);
    QVERIFY2(error.contains(QLatin1String("adapter not found")), qPrintable(error));
    QVERIFY2(error.contains(QLatin1String("stored parameters are unchanged")), qPrintable(error));
    QCOMPARE(s.drives.node(1).stores, 1); // only the first apply stored

    // Once the adapter is back, the next call connects and builds new units.
    s.refuseDevice.clear();
    QCOMPARE(s.apply(phi), QString());
    QCOMPARE(s.drives.node(1).stores, 2);
}

void TestCanRobotWorker::apply_silentNode_saysSoInOneSentence()
{
    WorkerSetup s;
    s.drives.node(2).server.reset(); // node 2 answers no SDO
    const QString error = s.apply(Eigen::Vector3d(20, 5, 8));
    QVERIFY2(error.contains(QStringLiteral("node 2 did not answer within %1 ms; nothing was stored")
                                .arg(s.options.sdoTimeoutMs)),
             qPrintable(error));
    QVERIFY2(!error.contains(QLatin1String(".;")), qPrintable(error));
    QCOMPARE(s.drives.node(1).stores, 0);
}

// The load is checked at the plan's sample period, before any frame is sent: 2 joints at 2 ms on
// a 125 kbit/s bus need 242 %; the offered 7 ms passes the check and reaches the drives.
void TestCanRobotWorker::busLoadAtThePlansPeriod_refusedBeforeAnyFrame_offeredPeriodPasses()
{
    CanRobotOptions slowBus;
    slowBus.bitrate = 125'000.0;
    slowBus.syncPeriod = 0.007; // what the options say is overridden by the plan's period
    WorkerSetup s(slowBus);
    s.drives.startSync();
    const TrialRecord refused = s.run(test::testPlan(50));
    QCOMPARE(refused.status, TrialStatus::Refused);
    QCOMPARE(refused.samples(), 0);
    for (const char *part : {"2 nodes at 500 Hz", "242.0 % of 125 kbit/s",
                             "shortest SYNC period that fits is 7 ms", "controller.samplePeriod"})
        QVERIFY2(refused.message.contains(QLatin1String(part)), qPrintable(refused.message));
    QVERIFY(!s.master); // not even connected: nothing sent
    QCOMPARE(s.drives.node(1).od.value(0x1017, 0), 0.0);

    TrialPlan at7ms = test::testPlan(50);
    at7ms.desired.samplePeriod = 0.007;
    const TrialRecord offered = s.run(at7ms);
    QVERIFY2(!offered.message.contains(QLatin1String("kbit/s")), qPrintable(offered.message));
    QVERIFY(s.master);
    QCOMPARE(s.drives.node(1).od.value(0x1017, 0), 100.0); // configuration reached the drives
}

QTEST_GUILESS_MAIN(TestCanRobotWorker)
#include "tst_canrobotworker.moc"
