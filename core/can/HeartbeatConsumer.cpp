#include "can/HeartbeatConsumer.h"

#include "can/CanLink.h"
#include "can/CanLogging.h"
#include "can/CanOpen.h"

#include <utility>

namespace learnid {

HeartbeatConsumer::HeartbeatConsumer(CanLink *link, QObject *parent)
    : QObject(parent)
{
    Q_ASSERT(link);
    connect(link, &CanLink::frameReceived, this, [this](const QCanBusFrame &frame) {
        const quint32 id = frame.frameId();
        if (frame.frameType() == QCanBusFrame::DataFrame && !frame.hasExtendedFrameFormat() &&
            id > canopen::heartbeatCobId(0) && id <= canopen::heartbeatCobId(127) &&
            frame.payload().size() >= 1)
            handleHeartbeat(canopen::nodeOfCobId(id), quint8(frame.payload().at(0)));
    });
}

HeartbeatConsumer::~HeartbeatConsumer() = default;

void HeartbeatConsumer::monitor(quint8 node, int timeoutMs)
{
    auto &slot = m_watches[node];
    if (!slot) {
        slot = std::make_unique<Watch>();
        slot->timer.setSingleShot(true);
        slot->timer.setTimerType(Qt::PreciseTimer);
        Watch *w = slot.get();
        connect(&w->timer, &QTimer::timeout, this, [this, node, w] {
            const qint64 ms = w->sinceLast.elapsed();
            if (ms < w->timeout) { // timers may fire a little early
                w->timer.start(int(w->timeout - ms));
                return;
            }
            w->lost = true;
            qCWarning(lcCan) << "heartbeat of node" << node << "lost after" << ms << "ms";
            emit heartbeatLost(node, ms);
        });
    }
    slot->lost = false;
    slot->state.reset();
    slot->sinceLast.start();
    slot->timeout = timeoutMs;
    slot->timer.start(timeoutMs);
}

void HeartbeatConsumer::stopMonitoring(quint8 node)
{
    m_watches.erase(node);
}

void HeartbeatConsumer::stopAll()
{
    m_watches.clear();
}

bool HeartbeatConsumer::isMonitoring(quint8 node) const
{
    return m_watches.count(node) > 0;
}

bool HeartbeatConsumer::isAlive(quint8 node) const
{
    const auto it = m_watches.find(node);
    return it != m_watches.end() && !it->second->lost && it->second->state.has_value();
}

std::optional<NmtState> HeartbeatConsumer::lastState(quint8 node) const
{
    const auto it = m_watches.find(node);
    return it == m_watches.end() ? std::nullopt : it->second->state;
}

void HeartbeatConsumer::expectBootUp(quint8 node)
{
    const auto it = m_watches.find(node);
    if (it != m_watches.end())
        it->second->bootUpExpected = true;
}

void HeartbeatConsumer::handleHeartbeat(quint8 node, quint8 byte)
{
    const auto it = m_watches.find(node);
    const std::optional<NmtState> state = nmtStateFromByte(byte);
    if (it == m_watches.end() || !state)
        return;
    Watch &w = *it->second;
    w.sinceLast.start();
    w.timer.start(w.timeout);
    const bool resumed = w.lost;
    w.lost = false;
    const bool changed = w.state != state;
    w.state = state;
    if (resumed)
        emit heartbeatResumed(node);
    emit heartbeatReceived(node, *state);
    if (changed)
        emit stateChanged(node, *state);
    if (*state == NmtState::BootUp) {
        if (std::exchange(w.bootUpExpected, false)) {
            emit bootUp(node);
        } else {
            qCWarning(lcCan) << "unexpected boot-up of node" << node;
            emit unexpectedBootUp(node);
        }
    }
}

} // namespace learnid
