#include "can/MemoryCanBus.h"

#include "can/MemoryCanDevice.h"

#include <QDateTime>
#include <utility>

namespace learnid {

MemoryCanBus::MemoryCanBus(QObject *parent)
    : QObject(parent)
{}

MemoryCanBus::~MemoryCanBus()
{
    for (const QPointer<MemoryCanDevice> &device : std::as_const(m_devices)) {
        if (device)
            device->m_bus = nullptr;
    }
}

MemoryCanDevice *MemoryCanBus::createDevice(const QString &name, QObject *parent)
{
    return new MemoryCanDevice(name, this, parent ? parent : this);
}

QList<MemoryCanDevice *> MemoryCanBus::devices() const
{
    QList<MemoryCanDevice *> result;
    for (const QPointer<MemoryCanDevice> &device : m_devices) {
        if (device)
            result.append(device.data());
    }
    return result;
}

void MemoryCanBus::attach(MemoryCanDevice *device)
{
    if (!m_devices.contains(device))
        m_devices.append(device);
}

void MemoryCanBus::detach(MemoryCanDevice *device)
{
    m_devices.removeAll(device);
}

void MemoryCanBus::transmit(MemoryCanDevice *sender, const QCanBusFrame &frame)
{
    QCanBusFrame onWire = frame;
    const qint64 us = QDateTime::currentMSecsSinceEpoch() * 1000;
    onWire.setTimeStamp(QCanBusFrame::TimeStamp::fromMicroSeconds(us));
    m_pending.append({sender, onWire});
    if (!m_deliveryScheduled) {
        m_deliveryScheduled = true;
        QMetaObject::invokeMethod(this, &MemoryCanBus::deliverPending, Qt::QueuedConnection);
    }
}

void MemoryCanBus::deliverPending()
{
    m_deliveryScheduled = false;
    // Frames written while delivering (answers) are queued behind and delivered next round.
    const QList<Pending> pending = std::exchange(m_pending, {});
    for (const Pending &p : pending) {
        if (m_drop && m_drop(p.frame)) {
            ++m_dropped;
            emit frameDropped(p.frame);
        } else {
            ++m_delivered;
            emit frameTransmitted(p.frame);
            const QList<QPointer<MemoryCanDevice>> receivers = m_devices;
            for (const QPointer<MemoryCanDevice> &device : receivers) {
                if (!device)
                    continue;
                const bool own = device == p.sender;
                if (!own || device->configurationParameter(QCanBusDevice::ReceiveOwnKey).toBool())
                    device->receive(p.frame);
            }
        }
        if (p.sender)
            p.sender->confirmWritten();
    }
}

} // namespace learnid
