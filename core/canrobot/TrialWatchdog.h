#pragma once

#include "types/Trial.h"

#include <QElapsedTimer>
#include <QList>
#include <QObject>
#include <QTimer>

namespace learnid {

class EmcyConsumer;
class HeartbeatConsumer;

/// The watches of a running trial that do not depend on its samples: an EMCY of a trial node,
/// a lost heartbeat, a boot-up nobody ordered, no SYNC for too long. Reports each as fault()
/// with the node and code in words (the streamer adds where in the trial it happened).
class TrialWatchdog : public QObject
{
    Q_OBJECT

public:
    TrialWatchdog(HeartbeatConsumer *heartbeat, EmcyConsumer *emcy, QObject *parent = nullptr);

    /// Starts watching nodes (joint order): heartbeats within heartbeatTimeoutMs, a SYNC
    /// within syncGapMs of the previous one (call syncReceived() for each).
    void start(const QList<int> &nodes, int heartbeatTimeoutMs, int syncGapMs);
    void syncReceived()
    {
        m_sinceSync.start(); // first: the gap reported is never below the timer's interval
        m_syncGap.start();
    }
    /// Counts the SYNC gap and each heartbeat's timeout from now on: after the master's own
    /// pause (planning the return move), whose frames still wait in the socket, so that the
    /// master's pause is not taken for the robot side's (docs/can-protocol.md §8.2).
    void restartClocks();
    void stop();

signals:
    void fault(learnid::TrialStatus status, const QString &reason);

private:
    QString nodeName(quint8 node) const;

    HeartbeatConsumer *m_heartbeat;
    EmcyConsumer *m_emcy;
    QList<int> m_nodes;
    int m_heartbeatTimeout = 0;
    QList<QMetaObject::Connection> m_connections;
    QTimer m_syncGap;
    QElapsedTimer m_sinceSync;
};

} // namespace learnid
