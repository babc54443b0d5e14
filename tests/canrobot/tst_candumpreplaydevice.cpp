// CandumpReplayDevice: the robot side of a log played in lock step with the master's writes.
#include "can/CanLink.h"
#include "canrobot/CandumpReplayDevice.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

namespace {

CandumpEntry entry(quint32 id, const char *hex)
{
    return {QStringLiteral("can0"), QCanBusFrame(id, QByteArray::fromHex(hex))};
}

} // namespace

class TestCandumpReplayDevice : public QObject
{
    Q_OBJECT

private slots:
    void masterFrames_areRecognisedByCobId();
    void robotFrames_comeUpToTheMastersNextFrame();
    void busRecording_masterAheadOfRobotFrames_matchesAndPlaysThemAfter();
    void differentMasterFrame_endsTheReplayNamingBoth();
};

void TestCandumpReplayDevice::masterFrames_areRecognisedByCobId()
{
    for (const quint32 id : {0x000u, 0x201u, 0x27Fu, 0x301u, 0x401u, 0x501u, 0x601u, 0x67Fu})
        QVERIFY2(isMasterFrame(QCanBusFrame(id, QByteArray(1, 0))),
                 qPrintable(QString::number(id, 16)));
    for (const quint32 id : {0x080u, 0x081u, 0x181u, 0x281u, 0x581u, 0x701u})
        QVERIFY2(!isMasterFrame(QCanBusFrame(id, QByteArray(1, 0))),
                 qPrintable(QString::number(id, 16)));
}

void TestCandumpReplayDevice::robotFrames_comeUpToTheMastersNextFrame()
{
    CandumpReplayDevice device({entry(0x701, "05"), entry(0x080, "01"), entry(0x201, "0100"),
                                entry(0x181, "02"), entry(0x080, "02"), entry(0x201, "0200")});
    CanLink link(&device);
    QList<quint32> received;
    connect(&link, &CanLink::frameReceived,
            [&](const QCanBusFrame &f) { received << f.frameId(); });
    QVERIFY(device.connectDevice());
    QTRY_COMPARE(received, (QList<quint32>{0x701, 0x080}));
    QTest::qWait(20);
    QCOMPARE(received.size(), 2); // waits for the master
    QVERIFY(link.send(QCanBusFrame(0x201, QByteArray::fromHex("0100"))));
    QTRY_COMPARE(received, (QList<quint32>{0x701, 0x080, 0x181, 0x080}));
    QVERIFY(link.send(QCanBusFrame(0x201, QByteArray::fromHex("0200"))));
    QVERIFY(device.atEnd());
}

// candump of a bus: both nodes answer the SYNC, and the master's second set-point went out
// after node 2's TPDO, which the master had not handled yet when it wrote both set-points.
void TestCandumpReplayDevice::busRecording_masterAheadOfRobotFrames_matchesAndPlaysThemAfter()
{
    CandumpReplayDevice device({entry(0x080, "01"), entry(0x181, "11"), entry(0x201, "0100"),
                                entry(0x182, "12"), entry(0x202, "0200"), entry(0x080, "02")});
    CanLink link(&device);
    QList<quint32> received;
    connect(&link, &CanLink::frameReceived,
            [&](const QCanBusFrame &f) { received << f.frameId(); });
    QVERIFY(device.connectDevice());
    QTRY_COMPARE(received, (QList<quint32>{0x080, 0x181}));
    QVERIFY(link.send(QCanBusFrame(0x201, QByteArray::fromHex("0100"))));
    QVERIFY(link.send(QCanBusFrame(0x202, QByteArray::fromHex("0200")))); // before 0x182 played
    QCOMPARE(device.state(), QCanBusDevice::ConnectedState);
    QCOMPARE(device.position(), 4); // 0x080, 0x181 played, 0x201 and 0x202 matched
    QTRY_COMPARE(received, (QList<quint32>{0x080, 0x181, 0x182, 0x080}));
    QVERIFY(device.atEnd());
    QCOMPARE(device.position(), 6);
    // A master frame that is not the log's next one still ends the replay.
    CandumpReplayDevice other({entry(0x080, "01"), entry(0x181, "11"), entry(0x201, "0100")});
    QVERIFY(other.connectDevice());
    QVERIFY(!other.writeFrame(QCanBusFrame(0x202, QByteArray::fromHex("0100"))));
    QVERIFY2(other.errorString().contains(QLatin1String("log frame 3")),
             qPrintable(other.errorString()));
}

void TestCandumpReplayDevice::differentMasterFrame_endsTheReplayNamingBoth()
{
    CandumpReplayDevice device({entry(0x080, "01"), entry(0x201, "0100")});
    QSignalSpy received(&device, &QCanBusDevice::framesReceived);
    QVERIFY(device.connectDevice());
    QTRY_COMPARE(received.size(), 1);
    QVERIFY(!device.writeFrame(QCanBusFrame(0x201, QByteArray::fromHex("0101"))));
    QCOMPARE(device.state(), QCanBusDevice::UnconnectedState);
    QVERIFY2(device.errorString().contains(QLatin1String("log frame 2")),
             qPrintable(device.errorString()));
    QVERIFY2(device.errorString().contains(QLatin1String("01 01")),
             qPrintable(device.errorString()));
}

QTEST_GUILESS_MAIN(TestCandumpReplayDevice)
#include "tst_candumpreplaydevice.moc"
