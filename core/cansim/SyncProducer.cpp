#include "cansim/SyncProducer.h"

#include "can/CanOpen.h"
#include "cansim/DriveSettings.h"

#include <cmath>

namespace learnid {

SyncProducer::SyncProducer(QObject *parent)
    : QObject(parent)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &SyncProducer::due);
}

void SyncProducer::start(quint32 periodUs)
{
    m_timer.start(std::max(1, int(std::lround(periodUs / 1000.0))));
}

void SyncProducer::stop()
{
    m_timer.stop();
}

quint8 SyncProducer::advance()
{
    m_counter = m_counter >= cansim::syncCounterMax ? 1 : quint8(m_counter + 1);
    return m_counter;
}

QCanBusFrame SyncProducer::frame(quint8 counter)
{
    return QCanBusFrame(canopen::syncCobId, QByteArray(1, char(counter)));
}

} // namespace learnid
