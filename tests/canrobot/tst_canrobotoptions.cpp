// The CAN robot's options: the bus load of n joints at a SYNC period against the limit, the
// offer of the shortest SYNC period that fits (from the same estimateBusLoad), and the node list
// (docs/can-protocol.md §8.5).
#include "canrobot/CanRobotOptions.h"

#include <QRegularExpression>
#include <QTest>

using namespace learnid;

namespace {

CanRobotOptions optionsFor(int joints, double syncPeriod)
{
    CanRobotOptions o;
    o.nodes = defaultNodeList(joints);
    o.syncPeriod = syncPeriod;
    return o;
}

// The offered period in the refusal's text ("the shortest SYNC period that fits is 3 ms"), 0
// when the text has none.
int offeredMs(const QString &error)
{
    static const QRegularExpression offer(QStringLiteral("fits is (\\d+) ms"));
    const QRegularExpressionMatch m = offer.match(error);
    return m.hasMatch() ? m.captured(1).toInt() : 0;
}

} // namespace

class TestCanRobotOptions : public QObject
{
    Q_OBJECT

private slots:
    void loadTable_matchesTheFrameFormula_data();
    void loadTable_matchesTheFrameFormula();
    void sevenJointsAt2ms_refusedWithFiguresAndTheOffer();
    void offeredPeriod_isTheShortestThatFits_andPassesWhenUsed_data();
    void offeredPeriod_isTheShortestThatFits_andPassesWhenUsed();
    void noPeriodFits_saysSo();
    void nodeCheck_ignoresTheLoad_fullCheckDoesNot();
    void nodeIds_anyListUpTo127();
    void setSyncPeriod_keepsTheSyncTimeoutInMilliseconds();
};

void TestCanRobotOptions::loadTable_matchesTheFrameFormula_data()
{
    QTest::addColumn<int>("joints");
    QTest::addColumn<int>("periodMs");
    QTest::addColumn<QString>("percent"); // as the tool prints it
    QTest::addColumn<bool>("accepted");
    // per SYNC: SYNC 65 bits + 2 n PDOs of 135 bits (docs/can-protocol.md §8.5)
    const char *table[][3] = {{"60.5", "30.3", "15.1"},  {"87.5", "43.8", "21.9"},
                              {"114.5", "57.3", "28.6"}, {"141.5", "70.8", "35.4"},
                              {"168.5", "84.3", "42.1"}, {"195.5", "97.8", "48.9"}};
    const int periods[] = {1, 2, 4};
    for (int n = 2; n <= 7; ++n) {
        for (int p = 0; p < 3; ++p) {
            const double percent = (65.0 + 270.0 * n) / (10.0 * periods[p]);
            QTest::addRow("%d joints, %d ms", n, periods[p])
                << n << periods[p] << QString::fromLatin1(table[n - 2][p]) << (percent <= 70.0);
        }
    }
}

void TestCanRobotOptions::loadTable_matchesTheFrameFormula()
{
    QFETCH(int, joints);
    QFETCH(int, periodMs);
    QFETCH(QString, percent);
    QFETCH(bool, accepted);
    const CanRobotOptions o = optionsFor(joints, periodMs / 1000.0);
    const BusLoad load = configuredBusLoad(o);
    QCOMPARE(load.bitsPerSecond, (65.0 + 270.0 * joints) * 1000.0 / periodMs);
    QCOMPARE(qRound(load.framesPerSecond), qRound((1.0 + 2.0 * joints) * 1000.0 / periodMs));
    QVERIFY2(load.text(o.bitrate).startsWith(percent + QStringLiteral(" % ")),
             qPrintable(load.text(o.bitrate)));
    QCOMPARE(busLoadError(o).isEmpty(), accepted);
    QCOMPARE(canRobotOptionsError(o).isEmpty(), accepted);
}

void TestCanRobotOptions::sevenJointsAt2ms_refusedWithFiguresAndTheOffer()
{
    const CanRobotOptions o = optionsFor(7, 0.002);
    const QString error = canRobotOptionsError(o);
    for (const char *part :
         {"7 nodes at 500 Hz", "SYNC every 2 ms", "97.8 % of 1000 kbit/s (7500 frames/s)",
          "the 70 % the tool allows", "shortest SYNC period that fits is 3 ms",
          "65.2 % of 1000 kbit/s (5000 frames/s)", "controller.samplePeriod to 0.003 s"})
        QVERIFY2(error.contains(QLatin1String(part)), qPrintable(part + (": " + error)));
    QCOMPARE(shortestFittingSyncPeriodMs(o), 3);
}

void TestCanRobotOptions::offeredPeriod_isTheShortestThatFits_andPassesWhenUsed_data()
{
    QTest::addColumn<int>("joints");
    QTest::addColumn<double>("syncPeriod");
    QTest::addColumn<double>("bitrate");
    QTest::addColumn<int>("expectedMs");
    QTest::newRow("5 joints, 2 ms") << 5 << 0.002 << 1e6 << 3;
    QTest::newRow("6 joints, 2 ms") << 6 << 0.002 << 1e6 << 3;
    QTest::newRow("7 joints, 2 ms") << 7 << 0.002 << 1e6 << 3;
    QTest::newRow("3 joints, 1 ms") << 3 << 0.001 << 1e6 << 2;
    QTest::newRow("7 joints, 1 ms") << 7 << 0.001 << 1e6 << 3;
    QTest::newRow("7 joints, 2 ms, 500 kbit/s") << 7 << 0.002 << 5e5 << 6;
    QTest::newRow("7 joints, 2.5 ms") << 7 << 0.0025 << 1e6 << 3;
    QTest::newRow("127 joints, 2 ms") << 127 << 0.002 << 1e6 << 50;
}

void TestCanRobotOptions::offeredPeriod_isTheShortestThatFits_andPassesWhenUsed()
{
    QFETCH(int, joints);
    QFETCH(double, syncPeriod);
    QFETCH(double, bitrate);
    QFETCH(int, expectedMs);
    CanRobotOptions o = optionsFor(joints, syncPeriod);
    o.bitrate = bitrate;
    const QString error = canRobotOptionsError(o);
    QVERIFY(!error.isEmpty());
    // The round trip: the period the text offers, used, passes; one ms less does not.
    const int ms = offeredMs(error);
    QCOMPARE(ms, expectedMs);
    QCOMPARE(shortestFittingSyncPeriodMs(o), ms);
    CanRobotOptions offered = o;
    offered.syncPeriod = ms / 1000.0;
    QVERIFY2(canRobotOptionsError(offered).isEmpty(), qPrintable(canRobotOptionsError(offered)));
    QVERIFY(configuredBusLoad(offered).percent <= o.maxBusLoadPercent);
    offered.syncPeriod = (ms - 1) / 1000.0;
    if (ms > 1)
        QVERIFY(configuredBusLoad(offered).percent > o.maxBusLoadPercent);
}

void TestCanRobotOptions::noPeriodFits_saysSo()
{
    CanRobotOptions o = optionsFor(7, 0.002);
    o.bitrate = 10'000.0; // 1955 bits per SYNC: 70 % of 10 kbit/s needs 280 ms
    QCOMPARE(shortestFittingSyncPeriodMs(o), 0);
    const QString error = canRobotOptionsError(o);
    QVERIFY2(error.contains(QLatin1String("no SYNC period up to 255 ms fits")), qPrintable(error));
    QCOMPARE(offeredMs(error), 0);
}

void TestCanRobotOptions::nodeCheck_ignoresTheLoad_fullCheckDoesNot()
{
    const CanRobotOptions heavy = optionsFor(7, 0.002);
    QVERIFY(canNodeOptionsError(heavy).isEmpty());
    QVERIFY(!canRobotOptionsError(heavy).isEmpty());
    CanRobotOptions twice = optionsFor(7, 0.004);
    twice.nodes[6] = 3;
    QCOMPARE(canNodeOptionsError(twice), QStringLiteral("node 3 is listed twice"));
    QCOMPARE(canRobotOptionsError(twice), canNodeOptionsError(twice));
}

void TestCanRobotOptions::nodeIds_anyListUpTo127()
{
    QString error;
    QCOMPARE(parseNodeList(QStringLiteral("127,5,9,1,64,2,100"), &error),
             (QList<int>{127, 5, 9, 1, 64, 2, 100}));
    QVERIFY(parseNodeList(QStringLiteral("1,128"), &error).isEmpty());
    QVERIFY2(error.contains(QLatin1String("'128'")), qPrintable(error));
    QVERIFY(parseNodeList(QStringLiteral("0"), &error).isEmpty());
    QCOMPARE(defaultNodeList(7), (QList<int>{1, 2, 3, 4, 5, 6, 7}));
    CanRobotOptions all = optionsFor(127, 0.05); // every node id, at a period that fits
    QVERIFY2(canRobotOptionsError(all).isEmpty(), qPrintable(canRobotOptionsError(all)));
    all.nodes << 128;
    QVERIFY(canNodeOptionsError(all).contains(QLatin1String("128")));
}

void TestCanRobotOptions::setSyncPeriod_keepsTheSyncTimeoutInMilliseconds()
{
    CanRobotOptions o; // default: 10 periods, at least 50 ms
    QCOMPARE(effectiveSyncTimeoutMs(o), 50);
    QCOMPARE(effectiveHeartbeatPeriodMs(o), 100);
    setSyncPeriod(o, 0.01);
    QCOMPARE(o.syncPeriod, 0.01);
    QCOMPARE(effectiveSyncTimeoutMs(o), 100); // the default follows the period
    QCOMPARE(effectiveHeartbeatPeriodMs(o), 100);
    setSyncTimeoutMs(o, 200);
    QCOMPARE(effectiveSyncTimeoutMs(o), 200);
    setSyncPeriod(o, 0.003);
    QCOMPARE(effectiveSyncTimeoutMs(o), 200); // given in ms: kept
    setSyncPeriod(o, 0.15);
    QCOMPARE(effectiveSyncTimeoutMs(o), 300); // at least 2 periods
    QCOMPARE(effectiveHeartbeatPeriodMs(o), 1500);
    setSyncPeriod(o, 0.0); // ignored
    QCOMPARE(o.syncPeriod, 0.15);
    o.heartbeatPeriodMs = 250;
    QCOMPARE(effectiveHeartbeatPeriodMs(o), 250);
    setSyncTimeoutMs(o, 0);
    QCOMPARE(effectiveSyncTimeoutMs(o), 1500);
}

QTEST_GUILESS_MAIN(TestCanRobotOptions)
#include "tst_canrobotoptions.moc"
