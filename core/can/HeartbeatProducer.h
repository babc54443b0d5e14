#pragma once

#include "can/Nmt.h"

#include <QObject>
#include <QTimer>

namespace learnid {

class CanLink;

/// The heartbeat of one slave node (0x700 + node, one byte: the NMT state), every period()
/// ms as object 0x1017 sets it, and its boot-up message.
class HeartbeatProducer : public QObject
{
    Q_OBJECT

public:
    HeartbeatProducer(CanLink *link, quint8 node, QObject *parent = nullptr);

    /// Producer heartbeat time [ms]; 0 stops the heartbeat.
    void setPeriod(int ms);
    int period() const { return m_period; }
    void setState(NmtState state) { m_state = state; }
    NmtState state() const { return m_state; }
    /// Sends the boot-up message; the node is pre-operational afterwards.
    void sendBootUp();
    /// Fault injection: a silent producer sends nothing (a node that died).
    void setSilent(bool silent) { m_silent = silent; }

private:
    void send(quint8 byte);

    CanLink *m_link;
    quint8 m_node;
    int m_period = 0;
    NmtState m_state = NmtState::PreOperational;
    bool m_silent = false;
    QTimer m_timer;
};

} // namespace learnid
