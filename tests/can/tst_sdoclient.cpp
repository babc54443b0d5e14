#include "CanTestBus.h"
#include "can/CanOpen.h"
#include "can/ObjectDictionary.h"
#include "can/SdoAbortCode.h"
#include "can/SdoClient.h"
#include "can/SdoServer.h"

#include <QSignalSpy>
#include <QTest>
#include <functional>
#include <optional>

using namespace learnid;
using canopen::DataType;
using Access = ObjectDictionary::Access;

namespace {

constexpr quint8 node = 5;

/// A client against a well-behaved server on node 5 with a few objects.
struct SdoSetup
{
    test::CanTestBus net;
    ObjectDictionary od;
    SdoServer server{&net.slaveLink, node, &od};
    SdoClient client{&net.masterLink};

    SdoSetup()
    {
        od.add(0x6041, 0, DataType::Unsigned16, Access::ReadOnly, 0x0237);
        od.add(0x607A, 0, DataType::Integer32, Access::ReadWrite, -5);
        od.add(0x2200, 0, DataType::Unsigned8, Access::ReadWrite, 3);
        od.add(0x2200, 1, DataType::Real32, Access::ReadWrite, 20.0);
        od.add(0x2300, 0, DataType::Real32, Access::ReadWrite, 8.0,
               ObjectDictionary::rangeValidator(DataType::Real32, 0.0, 100.0));
        od.add(0x1010, 1, DataType::Unsigned32, Access::WriteOnly, 0);
        od.addBytes(0x1008, 0, DataType::VisibleString, Access::ReadOnly, "learnid drive");
        od.addBytes(0x2400, 0, DataType::Domain, Access::ReadWrite, {}, 200);
        client.setTimeout(200);
    }
};

/// Runs one transfer started by start() to its end and returns its result.
SdoResult run(SdoClient &client, const std::function<quint64()> &start)
{
    QSignalSpy finished(&client, &SdoClient::finished);
    const quint64 id = start();
    if (!finished.wait(2000))
        return SdoResult{};
    const SdoResult r = finished.at(0).at(0).value<SdoResult>();
    if (r.id != id)
        qWarning("result of another transfer");
    return r;
}

/// A peer on node 5 that answers each request with the next scripted payload (8 bytes hex).
void script(test::CanTestBus &net, QStringList answers)
{
    QObject::connect(&net.slaveLink, &CanLink::frameReceived, &net.slaveLink,
                     [&net, answers](const QCanBusFrame &f) mutable {
                         if (f.frameId() != canopen::sdoRxCobId(node) || answers.isEmpty())
                             return;
                         const QByteArray p = QByteArray::fromHex(answers.takeFirst().toLatin1());
                         net.slaveLink.send(QCanBusFrame(canopen::sdoTxCobId(node), p));
                     });
}

/// The abort the client put on the bus last, if any.
std::optional<quint32> clientAbortCode(const test::CanTestBus &net)
{
    const QList<QCanBusFrame> requests = net.framesWithId(canopen::sdoRxCobId(node));
    if (requests.isEmpty() || quint8(requests.last().payload().at(0)) != 0x80)
        return std::nullopt;
    return canopen::readU32(requests.last().payload(), 4);
}

} // namespace

class TestSdoClient : public QObject
{
    Q_OBJECT

private slots:
    void expeditedUpload_readsTheValue();
    void expeditedDownload_writesTheValue();
    void segmentedUpload_readsEveryByte_data();
    void segmentedUpload_readsEveryByte();
    void segmentedDownload_writesEveryByte_data();
    void segmentedDownload_writesEveryByte();
    void serverAbort_isReportedWithCodeAndMessage_data();
    void serverAbort_isReportedWithCodeAndMessage();
    void validatorAbortAfterLastSegment_isReported();
    void silentServer_timesOut_andClientAbortsOnTheBus();
    void segmentedUpload_toggleBitError_aborts();
    void segmentedDownload_toggleBitError_aborts();
    void wrongCommandSpecifier_aborts();
    void answerForAnotherObject_aborts();
    void segmentedUpload_moreDataThanAnnounced_aborts();
    void transfersToOneNode_runOneAtATimeInCallOrder();
    void transfersToTwoNodes_runConcurrently();
    void invalidNodeOrEmptyData_failsAfterReturning();
    void unconnectedDevice_failsWithReason();
    void callback_receivesTheResult();
    void cancelAll_endsActiveAndQueuedTransfers();
    void lateAnswerAfterTimeout_isIgnored();
};

void TestSdoClient::expeditedUpload_readsTheValue()
{
    SdoSetup s;
    const SdoResult r = run(s.client, [&] { return s.client.upload(node, 0x6041, 0); });
    QVERIFY2(r.ok(), qPrintable(r.errorMessage));
    QCOMPARE(r.node, node);
    QCOMPARE(r.index, quint16(0x6041));
    QVERIFY(r.upload);
    QCOMPARE(r.data, QByteArray::fromHex("3702"));
    // one request, one answer: 0x40 initiate upload, 0x4B expedited 2 bytes
    QCOMPARE(s.net.wire.size(), 2);
    QCOMPARE(s.net.wire[0].payload(), QByteArray::fromHex("4041600000000000"));
    QCOMPARE(s.net.wire[1].payload(), QByteArray::fromHex("4B41600037020000"));
}

void TestSdoClient::expeditedDownload_writesTheValue()
{
    SdoSetup s;
    const SdoResult r = run(s.client, [&] {
        return s.client.download(node, 0x607A, 0, canopen::encodeValue(DataType::Integer32, 1000));
    });
    QVERIFY2(r.ok(), qPrintable(r.errorMessage));
    QCOMPARE(s.od.value(0x607A, 0), 1000.0);
    QCOMPARE(s.net.wire[0].payload(), QByteArray::fromHex("237A6000E8030000"));
    QCOMPARE(s.net.wire[1].payload(), QByteArray::fromHex("607A600000000000"));
}

void TestSdoClient::segmentedUpload_readsEveryByte_data()
{
    QTest::addColumn<int>("size");
    QTest::newRow("5 bytes: one short segment") << 5;
    QTest::newRow("7 bytes: one full segment") << 7;
    QTest::newRow("8 bytes") << 8;
    QTest::newRow("14 bytes: two full segments") << 14;
    QTest::newRow("100 bytes") << 100;
    QTest::newRow("0 bytes") << 0;
}

void TestSdoClient::segmentedUpload_readsEveryByte()
{
    QFETCH(int, size);
    SdoSetup s;
    QByteArray data;
    for (int i = 0; i < size; ++i)
        data.append(char('a' + i % 26));
    s.od.setBytes(0x2400, 0, data);
    const SdoResult r = run(s.client, [&] { return s.client.upload(node, 0x2400, 0); });
    QVERIFY2(r.ok(), qPrintable(r.errorMessage));
    QCOMPARE(r.data, data);
    const int segments = qMax(1, (size + 6) / 7);
    QCOMPARE(s.net.wire.size(), 2 + 2 * segments);
}

void TestSdoClient::segmentedDownload_writesEveryByte_data()
{
    QTest::addColumn<int>("size");
    QTest::newRow("5 bytes") << 5;
    QTest::newRow("7 bytes") << 7;
    QTest::newRow("14 bytes") << 14;
    QTest::newRow("15 bytes") << 15;
    QTest::newRow("200 bytes") << 200;
}

void TestSdoClient::segmentedDownload_writesEveryByte()
{
    QFETCH(int, size);
    SdoSetup s;
    QByteArray data;
    for (int i = 0; i < size; ++i)
        data.append(char(i));
    QSignalSpy written(&s.od, &ObjectDictionary::valueWritten);
    const SdoResult r = run(s.client, [&] { return s.client.download(node, 0x2400, 0, data); });
    QVERIFY2(r.ok(), qPrintable(r.errorMessage));
    QCOMPARE(s.od.bytes(0x2400, 0), data);
    QCOMPARE(written.count(), 1);
    // initiate with size indicated, then alternating toggle bits
    QCOMPARE(quint8(s.net.wire[0].payload().at(0)), quint8(0x21));
    QCOMPARE(canopen::readU32(s.net.wire[0].payload(), 4), quint32(size));
    const QList<QCanBusFrame> requests = s.net.framesWithId(canopen::sdoRxCobId(node));
    for (int i = 1; i < requests.size(); ++i)
        QCOMPARE(bool(requests[i].payload().at(0) & 0x10), (i - 1) % 2 == 1);
}

void TestSdoClient::serverAbort_isReportedWithCodeAndMessage_data()
{
    QTest::addColumn<bool>("upload");
    QTest::addColumn<quint16>("index");
    QTest::addColumn<quint8>("sub");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<quint32>("code");
    QTest::addColumn<QString>("words");
    QTest::newRow("read missing object") << true << quint16(0x3000) << quint8(0) << QByteArray()
                                         << sdoabort::objectDoesNotExist << "does not exist";
    QTest::newRow("read missing sub-index") << true << quint16(0x2200) << quint8(9) << QByteArray()
                                            << sdoabort::subIndexDoesNotExist << "Sub-index";
    QTest::newRow("read write-only") << true << quint16(0x1010) << quint8(1) << QByteArray()
                                     << sdoabort::writeOnly << "write-only";
    QTest::newRow("write read-only") << false << quint16(0x6041) << quint8(0) << QByteArray(2, '\0')
                                     << sdoabort::readOnly << "read-only";
    QTest::newRow("write too short") << false << quint16(0x607A) << quint8(0) << QByteArray(2, '\0')
                                     << sdoabort::lengthTooLow << "too low";
    QTest::newRow("write too long, segmented")
        << false << quint16(0x607A) << quint8(0) << QByteArray(6, '\0') << sdoabort::lengthTooHigh
        << "too high";
    QTest::newRow("write out of range")
        << false << quint16(0x2300) << quint8(0) << canopen::encodeValue(DataType::Real32, 150.0)
        << sdoabort::valueTooHigh << "too high";
    QTest::newRow("write read-only string")
        << false << quint16(0x1008) << quint8(0) << QByteArray("new name") << sdoabort::readOnly
        << "read-only";
}

void TestSdoClient::serverAbort_isReportedWithCodeAndMessage()
{
    QFETCH(bool, upload);
    QFETCH(quint16, index);
    QFETCH(quint8, sub);
    QFETCH(QByteArray, data);
    QFETCH(quint32, code);
    QFETCH(QString, words);
    SdoSetup s;
    const SdoResult r = run(s.client, [&] {
        return upload ? s.client.upload(node, index, sub)
                      : s.client.download(node, index, sub, data);
    });
    QVERIFY(!r.ok());
    QCOMPARE(r.abortCode, code);
    QVERIFY(r.abortedByServer);
    QVERIFY2(r.errorMessage.contains(words), qPrintable(r.errorMessage));
    QVERIFY2(r.errorMessage.contains(sdoabort::codeText(code)), qPrintable(r.errorMessage));
    QVERIFY2(r.errorMessage.contains(canopen::objectAddress(index, sub)),
             qPrintable(r.errorMessage));
    QVERIFY(!clientAbortCode(s.net)); // the client does not abort an abort
}

void TestSdoClient::validatorAbortAfterLastSegment_isReported()
{
    SdoSetup s;
    s.od.addBytes(0x2500, 0, DataType::Domain, Access::ReadWrite, {}, 0,
                  [](const QByteArray &) { return sdoabort::cannotStoreDeviceState; });
    const SdoResult r =
        run(s.client, [&] { return s.client.download(node, 0x2500, 0, QByteArray(20, 'x')); });
    QCOMPARE(r.abortCode, sdoabort::cannotStoreDeviceState);
    QVERIFY(r.abortedByServer);
    QVERIFY(s.od.bytes(0x2500, 0).isEmpty());
}

void TestSdoClient::silentServer_timesOut_andClientAbortsOnTheBus()
{
    SdoSetup s;
    s.server.setSilent(true);
    s.client.setTimeout(30);
    const SdoResult r = run(s.client, [&] { return s.client.upload(node, 0x6041, 0); });
    QVERIFY(!r.ok());
    QCOMPARE(r.abortCode, sdoabort::protocolTimeout);
    QVERIFY(!r.abortedByServer);
    QVERIFY2(r.errorMessage.contains("did not answer within 30 ms"), qPrintable(r.errorMessage));
    QTRY_COMPARE_WITH_TIMEOUT(clientAbortCode(s.net), std::optional<quint32>(0x05040000), 1000);
}

void TestSdoClient::segmentedUpload_toggleBitError_aborts()
{
    test::CanTestBus net;
    SdoClient client(&net.masterLink);
    // initiate: segmented, 14 bytes; first segment answered with toggle 1 instead of 0
    script(net, {"410024000E000000", "1061626364656667"});
    const SdoResult r = run(client, [&] { return client.upload(node, 0x2400, 0); });
    QCOMPARE(r.abortCode, sdoabort::toggleBitNotAlternated);
    QVERIFY(!r.abortedByServer);
    QVERIFY(r.data.isEmpty());
    QTRY_COMPARE_WITH_TIMEOUT(clientAbortCode(net), std::optional<quint32>(0x05030000), 1000);
}

void TestSdoClient::segmentedDownload_toggleBitError_aborts()
{
    test::CanTestBus net;
    SdoClient client(&net.masterLink);
    // initiate accepted, first segment acknowledged correctly (t = 0), second with t = 0 again
    script(net, {"6000240000000000", "2000000000000000", "2000000000000000"});
    const SdoResult r =
        run(client, [&] { return client.download(node, 0x2400, 0, QByteArray(20, 'x')); });
    QCOMPARE(r.abortCode, sdoabort::toggleBitNotAlternated);
    QTRY_COMPARE_WITH_TIMEOUT(clientAbortCode(net), std::optional<quint32>(0x05030000), 1000);
}

void TestSdoClient::wrongCommandSpecifier_aborts()
{
    test::CanTestBus net;
    SdoClient client(&net.masterLink);
    client.setTimeout(200);
    script(net, {"6041600000000000"}); // a download answer to an upload
    const SdoResult r = run(client, [&] { return client.upload(node, 0x6041, 0); });
    QCOMPARE(r.abortCode, sdoabort::invalidCommandSpecifier);
    QTRY_COMPARE_WITH_TIMEOUT(clientAbortCode(net), std::optional<quint32>(0x05040001), 1000);
}

void TestSdoClient::answerForAnotherObject_aborts()
{
    test::CanTestBus net;
    SdoClient client(&net.masterLink);
    client.setTimeout(200);
    script(net, {"4B42600037020000"}); // 0x6042 instead of 0x6041
    const SdoResult r = run(client, [&] { return client.upload(node, 0x6041, 0); });
    QCOMPARE(r.abortCode, sdoabort::generalError);
    QVERIFY(r.errorMessage.contains("another object"));
}

void TestSdoClient::segmentedUpload_moreDataThanAnnounced_aborts()
{
    test::CanTestBus net;
    SdoClient client(&net.masterLink);
    // announces 10 bytes, then sends 7 and 7 (the last flagged)
    script(net, {"410024000A000000", "0061626364656667", "1161626364656667"});
    const SdoResult r = run(client, [&] { return client.upload(node, 0x2400, 0); });
    QCOMPARE(r.abortCode, sdoabort::lengthMismatch);
    QVERIFY2(r.errorMessage.contains("announced 10 bytes"), qPrintable(r.errorMessage));
}

void TestSdoClient::transfersToOneNode_runOneAtATimeInCallOrder()
{
    SdoSetup s;
    QSignalSpy finished(&s.client, &SdoClient::finished);
    const quint64 a = s.client.upload(node, 0x2400, 0);
    const quint64 b = s.client.download(node, 0x2200, 1, canopen::encodeValue(DataType::Real32, 7));
    const quint64 c = s.client.upload(node, 0x2200, 1);
    QCOMPARE(s.client.pendingTransfers(node), 3);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 3, 2000);
    QCOMPARE(finished.at(0).at(0).value<SdoResult>().id, a);
    QCOMPARE(finished.at(1).at(0).value<SdoResult>().id, b);
    const SdoResult last = finished.at(2).at(0).value<SdoResult>();
    QCOMPARE(last.id, c);
    QCOMPARE(canopen::decodeValue(DataType::Real32, last.data), 7.0);
    // requests and answers of the node alternate: never two requests outstanding
    int outstanding = 0;
    for (const QCanBusFrame &f : s.net.wire) {
        outstanding += f.frameId() == canopen::sdoRxCobId(node) ? 1 : -1;
        QVERIFY(outstanding == 0 || outstanding == 1);
    }
    QCOMPARE(s.client.pendingTransfers(node), 0);
}

void TestSdoClient::transfersToTwoNodes_runConcurrently()
{
    SdoSetup s;
    ObjectDictionary od6;
    od6.add(0x6041, 0, DataType::Unsigned16, Access::ReadOnly, 0x0250);
    SdoServer server6(&s.net.slaveLink, 6, &od6);
    QSignalSpy finished(&s.client, &SdoClient::finished);
    s.client.upload(node, 0x6041, 0);
    s.client.upload(6, 0x6041, 0);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 2000);
    QCOMPARE(s.net.wire[0].frameId(), 0x605u); // both requests before any answer
    QCOMPARE(s.net.wire[1].frameId(), 0x606u);
    QCOMPARE(finished.at(1).at(0).value<SdoResult>().data, QByteArray::fromHex("5002"));
}

void TestSdoClient::invalidNodeOrEmptyData_failsAfterReturning()
{
    SdoSetup s;
    QSignalSpy finished(&s.client, &SdoClient::finished);
    s.client.upload(0, 0x6041, 0);
    s.client.download(node, 0x2400, 0, QByteArray());
    QCOMPARE(finished.count(), 0);
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 1000);
    QVERIFY(finished.at(0).at(0).value<SdoResult>().errorMessage.contains("node id"));
    QVERIFY(finished.at(1).at(0).value<SdoResult>().errorMessage.contains("no data"));
    QVERIFY(s.net.wire.isEmpty());
}

void TestSdoClient::unconnectedDevice_failsWithReason()
{
    SdoSetup s;
    s.net.master->disconnectDevice();
    const SdoResult r = run(s.client, [&] { return s.client.upload(node, 0x6041, 0); });
    QVERIFY(!r.ok());
    QCOMPARE(r.abortCode, 0u);
    QVERIFY2(r.errorMessage.contains("not connected"), qPrintable(r.errorMessage));
}

void TestSdoClient::callback_receivesTheResult()
{
    SdoSetup s;
    std::optional<SdoResult> got;
    s.client.upload(node, 0x1008, 0, [&](const SdoResult &r) { got = r; });
    QTRY_VERIFY_WITH_TIMEOUT(got.has_value(), 1000);
    QCOMPARE(got->data, QByteArray("learnid drive"));
}

void TestSdoClient::cancelAll_endsActiveAndQueuedTransfers()
{
    SdoSetup s;
    s.server.setSilent(true);
    QSignalSpy finished(&s.client, &SdoClient::finished);
    s.client.upload(node, 0x6041, 0);
    s.client.upload(node, 0x607A, 0);
    QTRY_COMPARE_WITH_TIMEOUT(s.net.wire.size(), 1, 1000); // the first request is out
    s.client.cancelAll("Stopped by the technician.");
    QCOMPARE(finished.count(), 2);
    for (const QList<QVariant> &args : finished)
        QCOMPARE(args.at(0).value<SdoResult>().errorMessage, QString("Stopped by the technician."));
    QCOMPARE(s.client.pendingTransfers(node), 0);
    QTRY_COMPARE_WITH_TIMEOUT(clientAbortCode(s.net), std::optional<quint32>(0x08000000), 1000);
}

void TestSdoClient::lateAnswerAfterTimeout_isIgnored()
{
    test::CanTestBus net;
    SdoClient client(&net.masterLink);
    client.setTimeout(20);
    const SdoResult r = run(client, [&] { return client.upload(node, 0x6041, 0); });
    QCOMPARE(r.abortCode, sdoabort::protocolTimeout);
    QSignalSpy finished(&client, &SdoClient::finished);
    net.slaveLink.send(QCanBusFrame(0x585, QByteArray::fromHex("4B41600037020000")));
    QTRY_COMPARE_WITH_TIMEOUT(net.wire.size(), 3, 1000); // request, abort, late answer
    QCOMPARE(finished.count(), 0);
}

QTEST_GUILESS_MAIN(TestSdoClient)
#include "tst_sdoclient.moc"
