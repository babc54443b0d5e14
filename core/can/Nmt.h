#pragma once

#include <QCanBusFrame>
#include <QMetaType>
#include <QObject>
#include <optional>

namespace learnid {

class CanLink;

/// NMT node control commands (CiA 301 §7.2.8.3.1); the byte sent in the frame.
enum class NmtCommand : quint8 {
    Start = 0x01,
    Stop = 0x02,
    EnterPreOperational = 0x80,
    ResetNode = 0x81,
    ResetCommunication = 0x82,
};

/// NMT states as a heartbeat reports them (CiA 301 §7.2.8.3.2.1).
enum class NmtState : quint8 {
    BootUp = 0x00,
    Stopped = 0x04,
    Operational = 0x05,
    PreOperational = 0x7F,
};

/// The state, named for the technician (translated).
QString nmtStateName(NmtState state);
/// The state a heartbeat byte reports (the toggle bit 7 is ignored), nullopt for others.
std::optional<NmtState> nmtStateFromByte(quint8 byte);
/// The NMT frame for node (0: all nodes).
QCanBusFrame nmtCommandFrame(NmtCommand command, quint8 node);
/// Slave side: the command in frame when it is an NMT frame addressed to node or to all.
std::optional<NmtCommand> nmtCommandFor(const QCanBusFrame &frame, quint8 node);
/// Slave side: the state a node is in after the command (reset commands end in BootUp; the
/// node then sends its boot-up message and is pre-operational).
NmtState nmtStateAfter(NmtCommand command, NmtState current);

/// The NMT master: sends node control commands. Node 0 addresses all nodes.
class Nmt : public QObject
{
    Q_OBJECT

public:
    explicit Nmt(CanLink *link, QObject *parent = nullptr);

    /// Returns false when the frame could not be written (see CanLink::lastError()).
    bool send(NmtCommand command, quint8 node);
    bool startNode(quint8 node) { return send(NmtCommand::Start, node); }
    bool stopNode(quint8 node) { return send(NmtCommand::Stop, node); }
    bool enterPreOperational(quint8 node) { return send(NmtCommand::EnterPreOperational, node); }
    bool resetNode(quint8 node) { return send(NmtCommand::ResetNode, node); }
    bool resetCommunication(quint8 node) { return send(NmtCommand::ResetCommunication, node); }

private:
    CanLink *m_link;
};

} // namespace learnid

Q_DECLARE_METATYPE(learnid::NmtState)
