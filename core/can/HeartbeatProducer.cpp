#include "can/HeartbeatProducer.h"

#include "can/CanLink.h"
#include "can/CanOpen.h"

namespace learnid {

HeartbeatProducer::HeartbeatProducer(CanLink *link, quint8 node, QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_node(node)
{
    Q_ASSERT(link && canopen::isValidNodeId(node));
    connect(&m_timer, &QTimer::timeout, this, [this] { send(quint8(m_state)); });
}

void HeartbeatProducer::setPeriod(int ms)
{
    m_period = qMax(0, ms);
    if (m_period > 0)
        m_timer.start(m_period);
    else
        m_timer.stop();
}

void HeartbeatProducer::sendBootUp()
{
    send(quint8(NmtState::BootUp));
    m_state = NmtState::PreOperational;
    if (m_period > 0)
        m_timer.start(m_period);
}

void HeartbeatProducer::send(quint8 byte)
{
    if (!m_silent)
        m_link->send(QCanBusFrame(canopen::heartbeatCobId(m_node), QByteArray(1, char(byte))));
}

} // namespace learnid
