#include "CanTestBus.h"
#include "can/CanOpen.h"
#include "can/ObjectDictionary.h"
#include "can/SdoAbortCode.h"
#include "can/SdoServer.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;
using canopen::DataType;
using Access = ObjectDictionary::Access;

namespace {

constexpr quint8 node = 3;

struct ServerSetup
{
    test::CanTestBus net;
    ObjectDictionary od;
    SdoServer server{&net.slaveLink, node, &od};

    ServerSetup()
    {
        od.add(0x6041, 0, DataType::Unsigned16, Access::ReadOnly, 0x0237);
        od.add(0x6060, 0, DataType::Integer8, Access::ReadWrite, 0);
        od.add(0x607A, 0, DataType::Integer32, Access::ReadWrite, 0);
        od.add(0x6064, 0, DataType::Integer32, Access::ReadOnly, -2);
        od.addBytes(0x1008, 0, DataType::VisibleString, Access::ReadOnly, "simulated joint");
        od.addBytes(0x2400, 0, DataType::Domain, Access::ReadWrite, {}, 64);
    }

    /// Sends one request (hex) to the server and returns its answer (hex, upper case), or
    /// an empty string when none comes within waitMs.
    QByteArray exchange(const char *requestHex, int waitMs = 1000)
    {
        QSignalSpy received(&net.masterLink, &CanLink::frameReceived);
        net.masterLink.send(
            QCanBusFrame(canopen::sdoRxCobId(node), QByteArray::fromHex(requestHex)));
        if (!received.wait(waitMs))
            return {};
        const QCanBusFrame f = received.at(0).at(0).value<QCanBusFrame>();
        if (f.frameId() != canopen::sdoTxCobId(node) || f.payload().size() != 8)
            return "wrong frame";
        return f.payload().toHex().toUpper();
    }
};

QByteArray abortHex(const char *object, quint32 code)
{
    QByteArray p = QByteArray::fromHex(QByteArray("80") + object + "00000000");
    canopen::writeU32(p, 4, code);
    return p.toHex().toUpper();
}

} // namespace

class TestSdoServer : public QObject
{
    Q_OBJECT

private slots:
    void expeditedUpload_answersWithSizeIndicated_data();
    void expeditedUpload_answersWithSizeIndicated();
    void expeditedDownload_withSize_writesAndConfirms();
    void expeditedDownload_withoutSize_takesTheObjectsSize();
    void accessErrors_abortWithTheirCode_data();
    void accessErrors_abortWithTheirCode();
    void segmentedUpload_sendsSegmentsWithAlternatingToggle();
    void segmentedUpload_wrongToggle_abortsWithToggleCode();
    void segmentedDownload_storesAfterTheLastSegment();
    void segmentedDownload_wrongToggle_abortsWithToggleCode();
    void segmentedDownload_lessDataThanAnnounced_abortsWithLengthMismatch();
    void segmentedDownload_moreDataThanAnnounced_abortsWithLengthTooHigh();
    void segmentWithoutInitiate_abortsWithCommandSpecifierCode();
    void blockTransfers_abortWithCommandSpecifierCode();
    void stalledClient_abortsWithTimeoutCode();
    void clientAbort_endsTheTransferSilently();
    void refusal_abortsWithTheInjectedCode();
    void silentServer_answersNothing();
    void requestsForOtherNodes_areIgnored();
};

void TestSdoServer::expeditedUpload_answersWithSizeIndicated_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("answer");
    QTest::newRow("1 byte") << QByteArray("4060600000000000") << QByteArray("4F60600000000000");
    QTest::newRow("2 bytes") << QByteArray("4041600000000000") << QByteArray("4B41600037020000");
    QTest::newRow("4 bytes") << QByteArray("4064600000000000") << QByteArray("43646000FEFFFFFF");
}

void TestSdoServer::expeditedUpload_answersWithSizeIndicated()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, answer);
    ServerSetup s;
    QCOMPARE(s.exchange(request.constData()), answer);
}

void TestSdoServer::expeditedDownload_withSize_writesAndConfirms()
{
    ServerSetup s;
    QSignalSpy written(&s.od, &ObjectDictionary::valueWritten);
    QCOMPARE(s.exchange("237A6000E8030000"), QByteArray("607A600000000000"));
    QCOMPARE(s.od.value(0x607A, 0), 1000.0);
    QCOMPARE(written.count(), 1);
    QCOMPARE(s.exchange("2F60600008000000"), QByteArray("6060600000000000"));
    QCOMPARE(s.od.value(0x6060, 0), 8.0);
}

void TestSdoServer::expeditedDownload_withoutSize_takesTheObjectsSize()
{
    ServerSetup s;
    QCOMPARE(s.exchange("22606000FF000000"), QByteArray("6060600000000000"));
    QCOMPARE(s.od.value(0x6060, 0), -1.0);
}

void TestSdoServer::accessErrors_abortWithTheirCode_data()
{
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("answer");
    QTest::newRow("read missing object")
        << QByteArray("4000300000000000") << abortHex("003000", sdoabort::objectDoesNotExist);
    QTest::newRow("read missing sub-index")
        << QByteArray("4041600100000000") << abortHex("416001", sdoabort::subIndexDoesNotExist);
    QTest::newRow("write read-only")
        << QByteArray("2B41600000000000") << abortHex("416000", sdoabort::readOnly);
    QTest::newRow("write constant string, segmented")
        << QByteArray("2108100000000000") << abortHex("081000", sdoabort::readOnly);
    QTest::newRow("write 2 bytes to INTEGER32")
        << QByteArray("2B7A600001000000") << abortHex("7A6000", sdoabort::lengthTooLow);
    QTest::newRow("segmented write of 5 bytes to INTEGER32")
        << QByteArray("217A600005000000") << abortHex("7A6000", sdoabort::lengthTooHigh);
    QTest::newRow("segmented write beyond the domain's size")
        << QByteArray("2100240041000000") << abortHex("002400", sdoabort::lengthTooHigh);
    QTest::newRow("unknown command specifier")
        << QByteArray("E000240000000000") << abortHex("002400", sdoabort::invalidCommandSpecifier);
}

void TestSdoServer::accessErrors_abortWithTheirCode()
{
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, answer);
    ServerSetup s;
    QSignalSpy aborted(&s.server, &SdoServer::transferAborted);
    QCOMPARE(s.exchange(request.constData()), answer);
    QCOMPARE(aborted.count(), 1);
    QCOMPARE(aborted.at(0).at(3).toBool(), false);
}

void TestSdoServer::segmentedUpload_sendsSegmentsWithAlternatingToggle()
{
    ServerSetup s; // "simulated joint": 15 bytes
    QCOMPARE(s.exchange("4008100000000000"), QByteArray("410810000F000000"));
    QCOMPARE(s.exchange("6000000000000000"), QByteArray("0073696D756C6174"));
    QCOMPARE(s.exchange("7000000000000000"), QByteArray("106564206A6F696E"));
    QCOMPARE(s.exchange("6000000000000000"), QByteArray("0D74000000000000"));
    // done: a further segment request is out of place
    QCOMPARE(s.exchange("7000000000000000"), abortHex("081000", sdoabort::invalidCommandSpecifier));
}

void TestSdoServer::segmentedUpload_wrongToggle_abortsWithToggleCode()
{
    ServerSetup s;
    s.exchange("4008100000000000");
    QCOMPARE(s.exchange("7000000000000000"), abortHex("081000", sdoabort::toggleBitNotAlternated));
}

void TestSdoServer::segmentedDownload_storesAfterTheLastSegment()
{
    ServerSetup s;
    QSignalSpy written(&s.od, &ObjectDictionary::valueWritten);
    QCOMPARE(s.exchange("210024000A000000"), QByteArray("6000240000000000"));
    QCOMPARE(s.exchange("0001020304050607"), QByteArray("2000000000000000"));
    QCOMPARE(written.count(), 0);
    QCOMPARE(s.exchange("1908090A00000000"), QByteArray("3000000000000000")); // 3 bytes, last
    QCOMPARE(written.count(), 1);
    QCOMPARE(s.od.bytes(0x2400, 0), QByteArray::fromHex("0102030405060708090A"));
}

void TestSdoServer::segmentedDownload_wrongToggle_abortsWithToggleCode()
{
    ServerSetup s;
    s.exchange("210024000A000000");
    QCOMPARE(s.exchange("1001020304050607"), abortHex("002400", sdoabort::toggleBitNotAlternated));
    QVERIFY(s.od.bytes(0x2400, 0).isEmpty());
}

void TestSdoServer::segmentedDownload_lessDataThanAnnounced_abortsWithLengthMismatch()
{
    ServerSetup s;
    s.exchange("210024000A000000");
    QCOMPARE(s.exchange("0101020304050607"), abortHex("002400", sdoabort::lengthMismatch));
}

void TestSdoServer::segmentedDownload_moreDataThanAnnounced_abortsWithLengthTooHigh()
{
    ServerSetup s;
    s.exchange("2100240005000000");
    QCOMPARE(s.exchange("0001020304050607"), abortHex("002400", sdoabort::lengthTooHigh));
}

void TestSdoServer::segmentWithoutInitiate_abortsWithCommandSpecifierCode()
{
    ServerSetup s;
    const QByteArray answer = s.exchange("0001020304050607");
    QVERIFY(answer.startsWith("80"));
    QCOMPARE(answer.right(8), QByteArray("01000405"));
}

void TestSdoServer::blockTransfers_abortWithCommandSpecifierCode()
{
    ServerSetup s;
    QCOMPARE(s.exchange("C600240000000000"), abortHex("002400", sdoabort::invalidCommandSpecifier));
    QCOMPARE(s.exchange("A400240000000000"), abortHex("002400", sdoabort::invalidCommandSpecifier));
}

void TestSdoServer::stalledClient_abortsWithTimeoutCode()
{
    ServerSetup s;
    s.server.setSegmentTimeout(30);
    QSignalSpy received(&s.net.masterLink, &CanLink::frameReceived);
    s.exchange("210024000A000000");
    QVERIFY(received.wait(1000)); // the abort, unprompted
    QCOMPARE(received.last().at(0).value<QCanBusFrame>().payload().toHex().toUpper(),
             abortHex("002400", sdoabort::protocolTimeout));
}

void TestSdoServer::clientAbort_endsTheTransferSilently()
{
    ServerSetup s;
    QSignalSpy aborted(&s.server, &SdoServer::transferAborted);
    s.exchange("210024000A000000");
    QCOMPARE(s.exchange("8000240000000008", 100), QByteArray()); // no answer to an abort
    QCOMPARE(aborted.count(), 1);
    QCOMPARE(aborted.at(0).at(2).value<quint32>(), sdoabort::generalError);
    QCOMPARE(aborted.at(0).at(3).toBool(), true);
    QCOMPARE(s.exchange("0001020304050607"), abortHex("002400", sdoabort::invalidCommandSpecifier));
}

void TestSdoServer::refusal_abortsWithTheInjectedCode()
{
    ServerSetup s;
    s.server.setRefusal([](quint16 index, quint8, bool write) {
        return write && index == 0x607A ? sdoabort::cannotStoreDeviceState : 0u;
    });
    QCOMPARE(s.exchange("237A6000E8030000"), abortHex("7A6000", sdoabort::cannotStoreDeviceState));
    QCOMPARE(s.exchange("407A600000000000"), QByteArray("437A600000000000"));
    QCOMPARE(s.od.value(0x607A, 0), 0.0);
}

void TestSdoServer::silentServer_answersNothing()
{
    ServerSetup s;
    s.server.setSilent(true);
    QVERIFY(s.server.isSilent());
    QCOMPARE(s.exchange("4041600000000000", 50), QByteArray());
}

void TestSdoServer::requestsForOtherNodes_areIgnored()
{
    ServerSetup s;
    QSignalSpy received(&s.net.masterLink, &CanLink::frameReceived);
    s.net.masterLink.send(
        QCanBusFrame(canopen::sdoRxCobId(4), QByteArray::fromHex("4041600000000000")));
    QVERIFY(!received.wait(50));
}

QTEST_GUILESS_MAIN(TestSdoServer)
#include "tst_sdoserver.moc"
