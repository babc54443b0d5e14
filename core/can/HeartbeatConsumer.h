#pragma once

#include "can/Nmt.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <map>
#include <memory>
#include <optional>

namespace learnid {

class CanLink;

/// Watches the heartbeats (0x700 + node) of the monitored nodes (CiA 301 §7.2.8.3.2): a node
/// whose heartbeat does not come within its timeout is reported lost, once, until it comes
/// back. A boot-up message (state 0x00) the master did not order with expectBootUp() means the
/// node restarted on its own (power loss, watchdog) and is reported as unexpected.
class HeartbeatConsumer : public QObject
{
    Q_OBJECT

public:
    explicit HeartbeatConsumer(CanLink *link, QObject *parent = nullptr);
    ~HeartbeatConsumer() override;

    /// Starts (or restarts) watching node: a heartbeat is due within timeoutMs from now on.
    void monitor(quint8 node, int timeoutMs);
    void stopMonitoring(quint8 node);
    void stopAll();
    bool isMonitoring(quint8 node) const;
    /// Monitored, and its last heartbeat within the timeout.
    bool isAlive(quint8 node) const;
    /// The state the node's last heartbeat reported.
    std::optional<NmtState> lastState(quint8 node) const;
    /// The next boot-up of node is the answer to a reset the master ordered.
    void expectBootUp(quint8 node);

signals:
    void heartbeatReceived(quint8 node, learnid::NmtState state);
    /// The reported state differs from the previous heartbeat's (or it is the first).
    void stateChanged(quint8 node, learnid::NmtState state);
    /// No heartbeat for longer than the node's timeout; msSinceLast counts from the last
    /// heartbeat, or from monitor() when none came.
    void heartbeatLost(quint8 node, qint64 msSinceLast);
    void heartbeatResumed(quint8 node);
    void unexpectedBootUp(quint8 node);
    void bootUp(quint8 node);

private:
    struct Watch
    {
        QTimer timer;
        int timeout = 0; ///< [ms]
        QElapsedTimer sinceLast;
        std::optional<NmtState> state;
        bool lost = false;
        bool bootUpExpected = false;
    };
    void handleHeartbeat(quint8 node, quint8 byte);

    std::map<quint8, std::unique_ptr<Watch>> m_watches;
};

} // namespace learnid
