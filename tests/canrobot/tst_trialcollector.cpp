// TrialCollector: TPDOs into the record by SYNC, the counter's wrap at 240, missing TPDOs and
// lost SYNCs.
#include "can/CanOpen.h"
#include "canrobot/TrialCollector.h"

#include <QTest>

using namespace learnid;

namespace {

QByteArray tpdo(qint32 position, qint16 torque, quint16 statusword = 0x1237)
{
    QByteArray p(8, '\0');
    canopen::writeU32(p, 0, quint32(position));
    canopen::writeU16(p, 4, quint16(torque));
    canopen::writeU16(p, 6, statusword);
    return p;
}

const QStringList names{QStringLiteral("node 5 (joint 1)"), QStringLiteral("node 6 (joint 2)")};

} // namespace

class TestTrialCollector : public QObject
{
    Q_OBJECT

private slots:
    void samplesFollowTheSyncTheyWereAppliedAt_acrossTheCounterWrap();
    void missingTpdo_isReportedAtTheNextSync();
    void skippedCounter_isALostSync();
    void shortPayload_isRefused();
};

void TestTrialCollector::samplesFollowTheSyncTheyWereAppliedAt_acrossTheCounterWrap()
{
    const DriveScaling s{1u << 16, 1, 500}; // 0.5 mN m per per mille
    TrialCollector c({s, s}, 20, 0.002);
    quint8 counter = 230;
    // 5 SYNCs of return move, then plan samples 0..19 (crossing 240 -> 1), one per SYNC.
    for (int n = 0; n < 25; ++n) {
        const int sample = n >= 5 ? n - 5 : -1;
        QCOMPARE(c.beginCycle(counter, sample, true, names), QString());
        QVERIFY(c.addTpdo(1, tpdo(-n, qint16(-2 * n))).isEmpty());
        QVERIFY(!c.cycleComplete());
        QVERIFY(c.addTpdo(0, tpdo(1000 + n, qint16(n))).isEmpty());
        QVERIFY(c.cycleComplete());
        counter = quint8(counter % 240 + 1);
    }
    QCOMPARE(c.recordedSamples(), 20);
    const TrialRecord r = c.record(TrialStatus::Completed, {});
    QCOMPARE(r.samples(), 20);
    for (int k = 0; k < 20; ++k) {
        QCOMPARE(r.q(0, k), s.toRad(1000 + k + 5));
        QCOMPARE(r.q(1, k), s.toRad(-(k + 5)));
        QCOMPARE(r.tau(0, k), (k + 5) * 0.0005);
        QCOMPARE(r.tau(1, k), -2 * (k + 5) * 0.0005);
    }
    QCOMPARE(c.counter(), quint8(14)); // 230 + 24 wrapped
}

void TestTrialCollector::missingTpdo_isReportedAtTheNextSync()
{
    TrialCollector c({DriveScaling{}, DriveScaling{}}, 10, 0.002);
    QVERIFY(c.beginCycle(7, 0, true, names).isEmpty());
    c.addTpdo(0, tpdo(1, 1));
    const QString error = c.beginCycle(8, 1, true, names);
    QVERIFY2(error.contains(QLatin1String("node 6 (joint 2)")), qPrintable(error));
    QVERIFY2(error.contains(QLatin1String("SYNC 1 (counter 7)")), qPrintable(error));
    QCOMPARE(c.recordedSamples(), 0);
    // Not required (enable phase): no error.
    TrialCollector d({DriveScaling{}, DriveScaling{}}, 10, 0.002);
    d.beginCycle(7, -1, false, names);
    QVERIFY(d.beginCycle(8, -1, false, names).isEmpty());
}

void TestTrialCollector::skippedCounter_isALostSync()
{
    TrialCollector c({DriveScaling{}}, 10, 0.002);
    QVERIFY(c.beginCycle(240, -1, false, names).isEmpty());
    QVERIFY(c.beginCycle(1, -1, false, names).isEmpty()); // the wrap is no gap
    const QString error = c.beginCycle(3, -1, false, names);
    QVERIFY2(error.contains(QLatin1String("from 1 to 3")), qPrintable(error));
    QVERIFY2(error.contains(QLatin1String("1 SYNC(s) lost")), qPrintable(error));
}

void TestTrialCollector::shortPayload_isRefused()
{
    TrialCollector c({DriveScaling{}}, 10, 0.002);
    c.beginCycle(1, 0, true, names);
    QVERIFY(!c.addTpdo(0, QByteArray(6, '\0')).isEmpty());
    QVERIFY(!c.cycleComplete());
}

QTEST_GUILESS_MAIN(TestTrialCollector)
#include "tst_trialcollector.moc"
