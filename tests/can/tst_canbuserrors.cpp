// classifyErrorFrame: each error class of SocketCAN's error frames (linux/can/error.h, the
// kernel's own constants as the reference) gives its words and whether a trial must stop.
#include "can/CanBusErrors.h"

#include <QTest>
#include <linux/can/error.h>

using namespace learnid;

namespace {

/// An error frame as Qt's socketcan plugin builds it from the kernel's: the error classes of
/// can_id (without CAN_ERR_FLAG) and the 8 data bytes.
QCanBusFrame errorFrame(quint32 classes, const QByteArray &data = QByteArray(8, '\0'))
{
    QCanBusFrame frame(QCanBusFrame::ErrorFrame);
    frame.setError(QCanBusFrame::FrameErrors(int(classes)));
    frame.setPayload(data);
    return frame;
}

QByteArray data(int byte, quint8 value)
{
    QByteArray d(8, '\0');
    d[byte] = char(value);
    return d;
}

} // namespace

class TestCanBusErrors : public QObject
{
    Q_OBJECT

private slots:
    void qtErrorClasses_areTheKernels();
    void errorFrame_classified_data();
    void errorFrame_classified();
    void severalClasses_fatalFirstAllNamed();
    void dataFrame_givesNoReport();
    void controllerStates_fatalFromErrorPassiveOn();
};

// The classifier reads Qt's FrameErrors; the plugin passes the kernel's bits through.
void TestCanBusErrors::qtErrorClasses_areTheKernels()
{
    QCOMPARE(int(QCanBusFrame::TransmissionTimeoutError), CAN_ERR_TX_TIMEOUT);
    QCOMPARE(int(QCanBusFrame::LostArbitrationError), CAN_ERR_LOSTARB);
    QCOMPARE(int(QCanBusFrame::ControllerError), CAN_ERR_CRTL);
    QCOMPARE(int(QCanBusFrame::ProtocolViolationError), CAN_ERR_PROT);
    QCOMPARE(int(QCanBusFrame::TransceiverError), CAN_ERR_TRX);
    QCOMPARE(int(QCanBusFrame::MissingAcknowledgmentError), CAN_ERR_ACK);
    QCOMPARE(int(QCanBusFrame::BusOffError), CAN_ERR_BUSOFF);
    QCOMPARE(int(QCanBusFrame::BusError), CAN_ERR_BUSERROR);
    QCOMPARE(int(QCanBusFrame::ControllerRestartError), CAN_ERR_RESTARTED);
}

void TestCanBusErrors::errorFrame_classified_data()
{
    QTest::addColumn<QCanBusFrame>("frame");
    QTest::addColumn<bool>("fatal");
    QTest::addColumn<QString>("what");
    QTest::newRow("tx-timeout") << errorFrame(CAN_ERR_TX_TIMEOUT) << true
                                << QStringLiteral("transmit timeout");
    QTest::newRow("lost-arbitration")
        << errorFrame(CAN_ERR_LOSTARB, data(0, 5)) << false << QStringLiteral("lost arbitration");
    QTest::newRow("rx-passive") << errorFrame(CAN_ERR_CRTL, data(1, CAN_ERR_CRTL_RX_PASSIVE))
                                << true << QStringLiteral("controller error passive (rx)");
    QTest::newRow("tx-passive") << errorFrame(CAN_ERR_CRTL, data(1, CAN_ERR_CRTL_TX_PASSIVE))
                                << true << QStringLiteral("controller error passive (tx)");
    QTest::newRow("rx-tx-passive")
        << errorFrame(CAN_ERR_CRTL, data(1, CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE))
        << true << QStringLiteral("controller error passive (rx, tx)");
    QTest::newRow("rx-overflow") << errorFrame(CAN_ERR_CRTL, data(1, CAN_ERR_CRTL_RX_OVERFLOW))
                                 << true
                                 << QStringLiteral("controller buffer overflow: frames were lost");
    QTest::newRow("tx-overflow") << errorFrame(CAN_ERR_CRTL, data(1, CAN_ERR_CRTL_TX_OVERFLOW))
                                 << true
                                 << QStringLiteral("controller buffer overflow: frames were lost");
    QTest::newRow("rx-warning") << errorFrame(CAN_ERR_CRTL, data(1, CAN_ERR_CRTL_RX_WARNING))
                                << false << QStringLiteral("controller error warning level");
    QTest::newRow("tx-warning") << errorFrame(CAN_ERR_CRTL, data(1, CAN_ERR_CRTL_TX_WARNING))
                                << false << QStringLiteral("controller error warning level");
    QTest::newRow("back-to-active") << errorFrame(CAN_ERR_CRTL, data(1, CAN_ERR_CRTL_ACTIVE))
                                    << false << QStringLiteral("controller back to error active");
    QTest::newRow("controller-unspecified")
        << errorFrame(CAN_ERR_CRTL) << false << QStringLiteral("controller problem (unspecified)");
    QByteArray prot(8, '\0');
    prot[2] = char(CAN_ERR_PROT_STUFF);
    prot[3] = char(CAN_ERR_PROT_LOC_CRC_SEQ);
    QTest::newRow("protocol") << errorFrame(CAN_ERR_PROT, prot) << true
                              << QStringLiteral("protocol violation (type 0x04, location 0x08)");
    QTest::newRow("transceiver") << errorFrame(CAN_ERR_TRX, data(4, CAN_ERR_TRX_CANH_NO_WIRE))
                                 << true << QStringLiteral("transceiver error (0x04)");
    QTest::newRow("no-ack") << errorFrame(CAN_ERR_ACK) << true
                            << QStringLiteral("no acknowledgement (no other node on the bus?)");
    QTest::newRow("bus-off") << errorFrame(CAN_ERR_BUSOFF) << true << QStringLiteral("bus off");
    QTest::newRow("bus-error") << errorFrame(CAN_ERR_BUSERROR) << true
                               << QStringLiteral("bus error");
    QTest::newRow("restarted") << errorFrame(CAN_ERR_RESTARTED) << false
                               << QStringLiteral("controller restarted");
    QTest::newRow("unknown-class")
        << errorFrame(0x200) << false << QStringLiteral("error class 0x200");
}

void TestCanBusErrors::errorFrame_classified()
{
    QFETCH(QCanBusFrame, frame);
    QFETCH(bool, fatal);
    QFETCH(QString, what);
    const CanBusErrorReport report = classifyErrorFrame(frame);
    QCOMPARE(report.fatal, fatal);
    QCOMPARE(report.what, what);
}

// What SocketCAN sends when a controller goes bus off after passive: every class is named, the
// fatal ones first; one fatal class makes the frame fatal.
void TestCanBusErrors::severalClasses_fatalFirstAllNamed()
{
    QByteArray d(8, '\0');
    d[1] = char(CAN_ERR_CRTL_TX_WARNING | CAN_ERR_CRTL_TX_PASSIVE);
    const CanBusErrorReport report =
        classifyErrorFrame(errorFrame(CAN_ERR_CRTL | CAN_ERR_BUSOFF | CAN_ERR_RESTARTED, d));
    QVERIFY(report.fatal);
    QCOMPARE(report.what, QStringLiteral("bus off, controller error passive (tx), controller "
                                         "error warning level, controller restarted"));
}

void TestCanBusErrors::dataFrame_givesNoReport()
{
    const CanBusErrorReport report = classifyErrorFrame(QCanBusFrame(0x040, QByteArray(8, '\0')));
    QVERIFY(!report.fatal);
    QVERIFY(report.what.isEmpty());
}

void TestCanBusErrors::controllerStates_fatalFromErrorPassiveOn()
{
    QVERIFY(!isFatalControllerState(CanControllerState::Unknown));
    QVERIFY(!isFatalControllerState(CanControllerState::ErrorActive));
    QVERIFY(!isFatalControllerState(CanControllerState::ErrorWarning));
    QVERIFY(isFatalControllerState(CanControllerState::ErrorPassive));
    QVERIFY(isFatalControllerState(CanControllerState::BusOff));
    QVERIFY(isFatalControllerState(CanControllerState::Stopped));
    QCOMPARE(canControllerStateName(CanControllerState::BusOff), QStringLiteral("bus off"));
}

QTEST_GUILESS_MAIN(TestCanBusErrors)
#include "tst_canbuserrors.moc"
