#include "can/BusLoad.h"
#include "model/Error.h"

#include <QTest>

using namespace learnid;

class TestBusLoad : public QObject
{
    Q_OBJECT

private slots:
    void worstCaseFrameBits_matchesTheStuffingFormula_data();
    void worstCaseFrameBits_matchesTheStuffingFormula();
    void twoJointsAt500HzOn1Mbit_isAbout30Percent();
    void withoutSync_andOtherRates_scale();
    void measuredLoad_ofRecordedFrames_matchesTheEstimate();
    void invalidConfiguration_throws();
    void text_reportsPercentBitrateAndFrames();
};

void TestBusLoad::worstCaseFrameBits_matchesTheStuffingFormula_data()
{
    QTest::addColumn<int>("dlc");
    QTest::addColumn<bool>("extended");
    QTest::addColumn<int>("bits");
    // by hand: 47 + 8n + floor((34 + 8n - 1) / 4), extended 67 + 8n + floor((54 + 8n - 1) / 4)
    QTest::newRow("SYNC, dlc 0") << 0 << false << 47 + 0 + 8;     // 33/4 = 8
    QTest::newRow("dlc 1") << 1 << false << 47 + 8 + 10;          // 41/4 = 10
    QTest::newRow("dlc 2") << 2 << false << 47 + 16 + 12;         // 49/4 = 12
    QTest::newRow("dlc 8") << 8 << false << 47 + 64 + 24;         // 97/4 = 24
    QTest::newRow("extended dlc 0") << 0 << true << 67 + 0 + 13;  // 53/4 = 13
    QTest::newRow("extended dlc 8") << 8 << true << 67 + 64 + 29; // 117/4 = 29
}

void TestBusLoad::worstCaseFrameBits_matchesTheStuffingFormula()
{
    QFETCH(int, dlc);
    QFETCH(bool, extended);
    QFETCH(int, bits);
    QCOMPARE(worstCaseFrameBits(dlc, extended), bits);
}

void TestBusLoad::twoJointsAt500HzOn1Mbit_isAbout30Percent()
{
    // per 2 ms: SYNC with its 1-byte counter 65 bits (47 + 8 + floor(41/4)) + 4 PDOs of 8 bytes
    // at 135 bits (47 + 64 + floor(97/4)) = 605 bits
    const BusLoad load = estimateBusLoad(BusLoadConfig{});
    QCOMPARE(load.framesPerSecond, 2500.0);
    QCOMPARE(load.bitsPerSecond, 302500.0);
    QCOMPARE(load.percent, 30.25);
}

void TestBusLoad::withoutSync_andOtherRates_scale()
{
    BusLoadConfig c;
    c.sync = false;
    c.joints = 6;
    c.sampleRate = 1000.0;
    c.bitrate = 500000.0;
    const BusLoad load = estimateBusLoad(c);
    QCOMPARE(load.framesPerSecond, 12000.0);
    QCOMPARE(load.bitsPerSecond, 12000.0 * 135);
    QCOMPARE(load.percent, 100.0 * 1620000.0 / 500000.0); // overloaded: 324 %
}

void TestBusLoad::measuredLoad_ofRecordedFrames_matchesTheEstimate()
{
    QList<QCanBusFrame> frames;
    for (int sample = 0; sample < 500; ++sample) { // one second at 500 Hz
        frames.append(QCanBusFrame(0x080, QByteArray(1, char(sample % 240 + 1)))); // counter
        for (quint32 node : {1u, 2u}) {
            frames.append(QCanBusFrame(0x200 + node, QByteArray(8, '\0')));
            frames.append(QCanBusFrame(0x180 + node, QByteArray(8, '\0')));
        }
    }
    const BusLoad measured = measureBusLoad(frames, 1.0, 1e6);
    const BusLoad estimated = estimateBusLoad(BusLoadConfig{});
    QCOMPARE(measured.framesPerSecond, estimated.framesPerSecond);
    QCOMPARE(measured.bitsPerSecond, estimated.bitsPerSecond);
    QCOMPARE(measured.percent, estimated.percent);
}

void TestBusLoad::invalidConfiguration_throws()
{
    BusLoadConfig c;
    c.payloadBytes = 9;
    QVERIFY_THROWS_EXCEPTION(Error, estimateBusLoad(c));
    c = BusLoadConfig{};
    c.sampleRate = 0;
    QVERIFY_THROWS_EXCEPTION(Error, estimateBusLoad(c));
    QVERIFY_THROWS_EXCEPTION(Error, measureBusLoad({}, 0.0, 1e6));
}

void TestBusLoad::text_reportsPercentBitrateAndFrames()
{
    QCOMPARE(estimateBusLoad(BusLoadConfig{}).text(1e6),
             QString("30.3 % of 1000 kbit/s (2500 frames/s)"));
}

QTEST_GUILESS_MAIN(TestBusLoad)
#include "tst_busload.moc"
