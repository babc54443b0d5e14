#include "canrobot/TrialWatchdog.h"

#include "can/CanOpen.h"
#include "can/EmcyConsumer.h"
#include "can/HeartbeatConsumer.h"

namespace learnid {

TrialWatchdog::TrialWatchdog(HeartbeatConsumer *heartbeat, EmcyConsumer *emcy, QObject *parent)
    : QObject(parent)
    , m_heartbeat(heartbeat)
    , m_emcy(emcy)
{
    m_syncGap.setSingleShot(true);
    m_syncGap.setTimerType(Qt::PreciseTimer);
    connect(&m_syncGap, &QTimer::timeout, this, [this] {
        // After a stall of this thread the timer can fire before the frames that came in the
        // meantime are handled: look again once the pending events have run.
        QMetaObject::invokeMethod(
            this,
            [this] {
                if (m_nodes.isEmpty() || m_syncGap.isActive())
                    return; // stopped, or a SYNC came meanwhile
                emit fault(TrialStatus::Aborted,
                           tr("no SYNC for %1 ms: the robot side stopped sending")
                               .arg(m_sinceSync.elapsed()));
            },
            Qt::QueuedConnection);
    });
}

void TrialWatchdog::start(const QList<int> &nodes, int heartbeatTimeoutMs, int syncGapMs)
{
    stop();
    m_nodes = nodes;
    m_heartbeatTimeout = heartbeatTimeoutMs;
    m_connections << connect(m_emcy, &EmcyConsumer::emergency, this, [this](const EmcyMessage &m) {
        if (m_nodes.contains(int(m.node)) && !m.isErrorReset())
            emit fault(TrialStatus::Faulted, m.text());
    });
    m_connections << connect(
        m_heartbeat, &HeartbeatConsumer::heartbeatLost, this, [this](quint8 node, qint64 ms) {
            emit fault(TrialStatus::Faulted, tr("heartbeat of %1 lost: none for %2 ms (timeout "
                                                "%3 ms)")
                                                 .arg(nodeName(node))
                                                 .arg(ms)
                                                 .arg(m_heartbeatTimeout));
        });
    m_connections << connect(
        m_heartbeat, &HeartbeatConsumer::unexpectedBootUp, this, [this](quint8 node) {
            emit fault(TrialStatus::Faulted, tr("%1 restarted on its own (boot-up message 0x%2)")
                                                 .arg(nodeName(node))
                                                 .arg(canopen::heartbeatCobId(node), 0, 16));
        });
    for (const int node : nodes)
        m_heartbeat->monitor(quint8(node), heartbeatTimeoutMs);
    m_syncGap.setInterval(std::max(1, syncGapMs));
    syncReceived();
}

void TrialWatchdog::restartClocks()
{
    if (m_nodes.isEmpty())
        return;
    for (const int node : std::as_const(m_nodes))
        m_heartbeat->monitor(quint8(node), m_heartbeatTimeout);
    syncReceived();
}

void TrialWatchdog::stop()
{
    m_syncGap.stop();
    for (const auto &c : std::as_const(m_connections))
        disconnect(c);
    m_connections.clear();
    for (const int node : std::as_const(m_nodes))
        m_heartbeat->stopMonitoring(quint8(node));
    m_nodes.clear();
}

QString TrialWatchdog::nodeName(quint8 node) const
{
    return tr("node %1 (joint %2)").arg(node).arg(m_nodes.indexOf(int(node)) + 1);
}

} // namespace learnid
