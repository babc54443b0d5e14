#include "can/Nmt.h"

#include "can/CanLink.h"
#include "can/CanOpen.h"

#include <QCoreApplication>

namespace learnid {

QString nmtStateName(NmtState state)
{
    switch (state) {
    case NmtState::BootUp:
        return QCoreApplication::translate("Nmt", "boot-up");
    case NmtState::Stopped:
        return QCoreApplication::translate("Nmt", "stopped");
    case NmtState::Operational:
        return QCoreApplication::translate("Nmt", "operational");
    case NmtState::PreOperational:
        return QCoreApplication::translate("Nmt", "pre-operational");
    }
    return {};
}

std::optional<NmtState> nmtStateFromByte(quint8 byte)
{
    switch (byte & 0x7F) {
    case 0x00:
        return NmtState::BootUp;
    case 0x04:
        return NmtState::Stopped;
    case 0x05:
        return NmtState::Operational;
    case 0x7F:
        return NmtState::PreOperational;
    default:
        return std::nullopt;
    }
}

QCanBusFrame nmtCommandFrame(NmtCommand command, quint8 node)
{
    QByteArray payload(2, '\0');
    payload[0] = char(command);
    payload[1] = char(node);
    return QCanBusFrame(canopen::nmtCobId, payload);
}

std::optional<NmtCommand> nmtCommandFor(const QCanBusFrame &frame, quint8 node)
{
    const QByteArray p = frame.payload();
    if (frame.frameType() != QCanBusFrame::DataFrame || frame.hasExtendedFrameFormat() ||
        frame.frameId() != canopen::nmtCobId || p.size() < 2)
        return std::nullopt;
    const quint8 target = quint8(p.at(1));
    if (target != 0 && target != node)
        return std::nullopt;
    switch (quint8(p.at(0))) {
    case 0x01:
        return NmtCommand::Start;
    case 0x02:
        return NmtCommand::Stop;
    case 0x80:
        return NmtCommand::EnterPreOperational;
    case 0x81:
        return NmtCommand::ResetNode;
    case 0x82:
        return NmtCommand::ResetCommunication;
    default:
        return std::nullopt;
    }
}

NmtState nmtStateAfter(NmtCommand command, NmtState current)
{
    switch (command) {
    case NmtCommand::Start:
        return NmtState::Operational;
    case NmtCommand::Stop:
        return NmtState::Stopped;
    case NmtCommand::EnterPreOperational:
        return NmtState::PreOperational;
    case NmtCommand::ResetNode:
    case NmtCommand::ResetCommunication:
        return NmtState::BootUp;
    }
    return current;
}

Nmt::Nmt(CanLink *link, QObject *parent)
    : QObject(parent)
    , m_link(link)
{
    Q_ASSERT(link);
}

bool Nmt::send(NmtCommand command, quint8 node)
{
    return m_link->send(nmtCommandFrame(command, node));
}

} // namespace learnid
