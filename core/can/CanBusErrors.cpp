#include "can/CanBusErrors.h"

#include <QCoreApplication>
#include <QStringList>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CanBus)
};

// Byte 1 of a controller error frame (linux/can/error.h, CAN_ERR_CRTL_*).
constexpr quint8 rxOverflow = 0x01, txOverflow = 0x02, rxWarning = 0x04, txWarning = 0x08,
                 rxPassive = 0x10, txPassive = 0x20, backToActive = 0x40;

} // namespace

CanBusErrorReport classifyErrorFrame(const QCanBusFrame &frame)
{
    CanBusErrorReport r;
    if (frame.frameType() != QCanBusFrame::ErrorFrame)
        return r;
    const QCanBusFrame::FrameErrors e = frame.error();
    const QByteArray p = frame.payload();
    QStringList fatal, other;
    if (e & QCanBusFrame::BusOffError)
        fatal << Text::tr("bus off");
    if (e & QCanBusFrame::ControllerError) {
        const quint8 c = p.size() > 1 ? quint8(p.at(1)) : 0;
        if (c & (rxPassive | txPassive))
            fatal << Text::tr("controller error passive (%1)")
                         .arg((c & rxPassive) && (c & txPassive) ? QStringLiteral("rx, tx")
                              : (c & rxPassive)                  ? QStringLiteral("rx")
                                                                 : QStringLiteral("tx"));
        if (c & (rxOverflow | txOverflow))
            fatal << Text::tr("controller buffer overflow: frames were lost");
        if (c & (rxWarning | txWarning))
            other << Text::tr("controller error warning level");
        if (c & backToActive)
            other << Text::tr("controller back to error active");
        if (c == 0)
            other << Text::tr("controller problem (unspecified)");
    }
    if (e & QCanBusFrame::TransmissionTimeoutError)
        fatal << Text::tr("transmit timeout");
    if (e & QCanBusFrame::ProtocolViolationError)
        fatal << Text::tr("protocol violation (type 0x%1, location 0x%2)")
                     .arg(p.size() > 2 ? quint8(p.at(2)) : 0, 2, 16, QLatin1Char('0'))
                     .arg(p.size() > 3 ? quint8(p.at(3)) : 0, 2, 16, QLatin1Char('0'));
    if (e & QCanBusFrame::TransceiverError)
        fatal << Text::tr("transceiver error (0x%1)")
                     .arg(p.size() > 4 ? quint8(p.at(4)) : 0, 2, 16, QLatin1Char('0'));
    if (e & QCanBusFrame::MissingAcknowledgmentError)
        fatal << Text::tr("no acknowledgement (no other node on the bus?)");
    if (e & QCanBusFrame::BusError)
        fatal << Text::tr("bus error");
    if (e & QCanBusFrame::LostArbitrationError)
        other << Text::tr("lost arbitration");
    if (e & QCanBusFrame::ControllerRestartError)
        other << Text::tr("controller restarted");
    if (fatal.isEmpty() && other.isEmpty())
        other << Text::tr("error class 0x%1").arg(quint32(e), 0, 16);
    r.fatal = !fatal.isEmpty();
    r.what = (fatal + other).join(QStringLiteral(", "));
    return r;
}

QString canControllerStateName(CanControllerState state)
{
    switch (state) {
    case CanControllerState::ErrorActive:
        return Text::tr("error active");
    case CanControllerState::ErrorWarning:
        return Text::tr("error warning");
    case CanControllerState::ErrorPassive:
        return Text::tr("error passive");
    case CanControllerState::BusOff:
        return Text::tr("bus off");
    case CanControllerState::Stopped:
        return Text::tr("stopped");
    case CanControllerState::Unknown:
        break;
    }
    return Text::tr("unknown");
}

bool isFatalControllerState(CanControllerState state)
{
    return state == CanControllerState::ErrorPassive || state == CanControllerState::BusOff ||
           state == CanControllerState::Stopped;
}

} // namespace learnid
