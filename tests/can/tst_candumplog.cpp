#include "can/CandumpLog.h"
#include "model/Error.h"

#include <QBuffer>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

QCanBusFrame frameAt(quint32 id, const QByteArray &data, qint64 s, qint64 us)
{
    QCanBusFrame f(id, data);
    f.setTimeStamp(QCanBusFrame::TimeStamp(s, us));
    return f;
}

CandumpEntry parse(const QString &line)
{
    CandumpEntry e;
    QString reason;
    if (!candump::parseLine(line, &e, &reason))
        qWarning("%s", qPrintable(reason));
    return e;
}

} // namespace

class TestCandumpLog : public QObject
{
    Q_OBJECT

private slots:
    void formatLine_writesCanUtilsLogFormat_data();
    void formatLine_writesCanUtilsLogFormat();
    void parseLine_readsEveryFrameKind();
    void parseLine_acceptsDirectionFlagDotsAndShortFractions();
    void log_roundTripsThroughWriteAndRead();
    void file_roundTripsThroughWriteFileAndReadFile();
    void malformedLine_isReportedWithFileLineAndReason_data();
    void malformedLine_isReportedWithFileLineAndReason();
    void missingFile_isReported();
};

void TestCandumpLog::formatLine_writesCanUtilsLogFormat_data()
{
    QTest::addColumn<QCanBusFrame>("frame");
    QTest::addColumn<QString>("line");
    QTest::newRow("standard") << frameAt(0x123, QByteArray::fromHex("DEADBEEF"), 1700000000, 123456)
                              << "(1700000000.123456) can0 123#DEADBEEF";
    QTest::newRow("short id, padded")
        << frameAt(0x80, QByteArray(), 1700000000, 5) << "(1700000000.000005) can0 080#";
    QCanBusFrame ext = frameAt(0x1ABCDEF, QByteArray::fromHex("01"), 12, 0);
    ext.setExtendedFrameFormat(true);
    QTest::newRow("extended") << ext << "(0000000012.000000) can0 01ABCDEF#01";
    QCanBusFrame rtr = frameAt(0x701, QByteArray(), 1, 1);
    rtr.setFrameType(QCanBusFrame::RemoteRequestFrame);
    QTest::newRow("remote") << rtr << "(0000000001.000001) can0 701#R";
    QCanBusFrame rtr1 = frameAt(0x701, QByteArray(1, '\0'), 1, 1);
    rtr1.setFrameType(QCanBusFrame::RemoteRequestFrame);
    QTest::newRow("remote with length") << rtr1 << "(0000000001.000001) can0 701#R1";
}

void TestCandumpLog::formatLine_writesCanUtilsLogFormat()
{
    QFETCH(QCanBusFrame, frame);
    QFETCH(QString, line);
    QCOMPARE(candump::formatLine(frame, "can0"), line);
}

void TestCandumpLog::parseLine_readsEveryFrameKind()
{
    CandumpEntry e = parse("(1700000000.123456) can0 123#DEADBEEF");
    QCOMPARE(e.interface, QString("can0"));
    QCOMPARE(e.frame.frameId(), 0x123u);
    QVERIFY(!e.frame.hasExtendedFrameFormat());
    QCOMPARE(e.frame.payload(), QByteArray::fromHex("DEADBEEF"));
    QCOMPARE(e.frame.timeStamp().seconds(), 1700000000);
    QCOMPARE(e.frame.timeStamp().microSeconds(), 123456);

    e = parse("(1.000000) vcan1 12345678#");
    QVERIFY(e.frame.hasExtendedFrameFormat());
    QCOMPARE(e.frame.frameId(), 0x12345678u);
    QVERIFY(e.frame.payload().isEmpty());
    QCOMPARE(e.frame.frameType(), QCanBusFrame::DataFrame);

    e = parse("(1.000000) can0 701#R");
    QCOMPARE(e.frame.frameType(), QCanBusFrame::RemoteRequestFrame);
    e = parse("(1.000000) can0 701#R8");
    QCOMPARE(e.frame.payload().size(), 8);

    e = parse("(1.000000) can0 20000004#0004000000000000");
    QCOMPARE(e.frame.frameType(), QCanBusFrame::ErrorFrame);
    QCOMPARE(e.frame.error(), QCanBusFrame::ControllerError);
}

void TestCandumpLog::parseLine_acceptsDirectionFlagDotsAndShortFractions()
{
    CandumpEntry e = parse("(1700000000.5) can0 181#11.22.33 R");
    QCOMPARE(e.frame.payload(), QByteArray::fromHex("112233"));
    QCOMPARE(e.frame.timeStamp().microSeconds(), 500000);
    e = parse("  (1700000000.123456789)   can0   181#abcd  ");
    QCOMPARE(e.frame.timeStamp().microSeconds(), 123456);
    QCOMPARE(e.frame.payload(), QByteArray::fromHex("ABCD"));
}

void TestCandumpLog::log_roundTripsThroughWriteAndRead()
{
    QList<CandumpEntry> entries;
    entries.append({"can0", frameAt(0x080, {}, 1700000000, 0)});
    entries.append(
        {"can0", frameAt(0x201, QByteArray::fromHex("0000008000800F00"), 1700000000, 2000)});
    QCanBusFrame ext = frameAt(0x18FF50E5, QByteArray::fromHex("0102"), 1700000000, 999999);
    ext.setExtendedFrameFormat(true);
    entries.append({"can1", ext});
    QCanBusFrame rtr = frameAt(0x701, {}, 1700000001, 0);
    rtr.setFrameType(QCanBusFrame::RemoteRequestFrame);
    entries.append({"can0", rtr});

    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    candump::write(buffer, entries);
    buffer.close();
    buffer.open(QIODevice::ReadOnly);
    const QList<CandumpEntry> back = candump::read(buffer, "trial.log");
    QCOMPARE(back.size(), entries.size());
    for (int i = 0; i < entries.size(); ++i) {
        QCOMPARE(back[i].interface, entries[i].interface);
        QCOMPARE(back[i].frame.frameId(), entries[i].frame.frameId());
        QCOMPARE(back[i].frame.frameType(), entries[i].frame.frameType());
        QCOMPARE(back[i].frame.hasExtendedFrameFormat(), entries[i].frame.hasExtendedFrameFormat());
        QCOMPARE(back[i].frame.payload(), entries[i].frame.payload());
        QCOMPARE(back[i].frame.timeStamp().seconds(), entries[i].frame.timeStamp().seconds());
        QCOMPARE(back[i].frame.timeStamp().microSeconds(),
                 entries[i].frame.timeStamp().microSeconds());
    }
}

void TestCandumpLog::file_roundTripsThroughWriteFileAndReadFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath("trial-1.log");
    candump::writeFile(path,
                       {{"can0", frameAt(0x585, QByteArray::fromHex("4B41600037020000"), 5, 6)}});
    const QList<CandumpEntry> back = candump::readFile(path);
    QCOMPARE(back.size(), 1);
    QCOMPARE(back[0].frame.payload(), QByteArray::fromHex("4B41600037020000"));
}

void TestCandumpLog::malformedLine_isReportedWithFileLineAndReason_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<QString>("reason");
    QTest::newRow("no timestamp") << "can0 123#00"
                                  << "found 2 fields";
    QTest::newRow("timestamp without parentheses") << "1700000000.000000 can0 123#00"
                                                   << "timestamp in parentheses";
    QTest::newRow("timestamp without fraction") << "(1700000000) can0 123#00"
                                                << "not a timestamp";
    QTest::newRow("timestamp not a number") << "(17000x0000.000000) can0 123#00"
                                            << "not a timestamp";
    QTest::newRow("negative timestamp") << "(-1.000000) can0 123#00"
                                        << "not a timestamp";
    QTest::newRow("no interface") << "(1.000000) 123#00"
                                  << "found 2 fields";
    QTest::newRow("no hash") << "(1.000000) can0 12300"
                             << "no '#'";
    QTest::newRow("id of 4 digits") << "(1.000000) can0 1234#00"
                                    << "3 (standard) or 8 (extended)";
    QTest::newRow("id not hex") << "(1.000000) can0 12G#00"
                                << "3 (standard) or 8 (extended)";
    QTest::newRow("standard id too big") << "(1.000000) can0 800#00"
                                         << "exceeds 7FF";
    QTest::newRow("extended id too big") << "(1.000000) can0 40000000#00"
                                         << "exceeds 1FFFFFFF";
    QTest::newRow("odd data digits") << "(1.000000) can0 123#ABC"
                                     << "whole bytes";
    QTest::newRow("data not hex") << "(1.000000) can0 123#ZZ"
                                  << "whole bytes";
    QTest::newRow("9 data bytes") << "(1.000000) can0 123#000102030405060708"
                                  << "at most 8";
    QTest::newRow("bad remote length") << "(1.000000) can0 123#R9"
                                       << "remote request";
    QTest::newRow("CAN FD") << "(1.000000) can0 123##1DEADBEEF"
                            << "CAN FD";
    QTest::newRow("trailing text") << "(1.000000) can0 123#00 extra"
                                   << "unexpected text";
}

void TestCandumpLog::malformedLine_isReportedWithFileLineAndReason()
{
    QFETCH(QString, line);
    QFETCH(QString, reason);
    QByteArray log = "(1700000000.000000) can0 080#\n\n(1700000000.002000) can0 080#\n";
    log += line.toUtf8() + "\n(1700000000.004000) can0 080#\n";
    QBuffer buffer(&log);
    buffer.open(QIODevice::ReadOnly);
    try {
        candump::read(buffer, "run.log");
        QFAIL("no exception");
    } catch (const Error &e) {
        QVERIFY2(e.message().startsWith("run.log:4: "), qPrintable(e.message()));
        QVERIFY2(e.message().contains(reason), qPrintable(e.message()));
    }
}

void TestCandumpLog::missingFile_isReported()
{
    QVERIFY_THROWS_EXCEPTION(Error, candump::readFile("/nonexistent/dir/x.log"));
}

QTEST_GUILESS_MAIN(TestCandumpLog)
#include "tst_candumplog.moc"
