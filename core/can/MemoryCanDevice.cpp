#include "can/MemoryCanDevice.h"

#include "can/MemoryCanBus.h"

#include <QVariant>

namespace learnid {

MemoryCanDevice::MemoryCanDevice(const QString &name, MemoryCanBus *bus, QObject *parent)
    : QCanBusDevice(parent)
    , m_name(name)
    , m_bus(bus)
{
    if (m_bus)
        m_bus->attach(this);
}

MemoryCanDevice::~MemoryCanDevice()
{
    if (m_bus)
        m_bus->detach(this);
}

bool MemoryCanDevice::open()
{
    if (!m_bus) {
        setError(tr("The memory CAN device %1 is not attached to a bus.").arg(m_name),
                 ConnectionError);
        return false;
    }
    if (m_refuseConnect) {
        setError(tr("The memory CAN device %1 refused to connect.").arg(m_name), ConnectionError);
        return false;
    }
    clearError();
    setState(ConnectedState);
    return true;
}

void MemoryCanDevice::close()
{
    setState(UnconnectedState);
}

bool MemoryCanDevice::writeFrame(const QCanBusFrame &frame)
{
    if (state() != ConnectedState) {
        setError(tr("Cannot write a frame: the device %1 is not connected.").arg(m_name),
                 WriteError);
        return false;
    }
    if (!frame.isValid() || frame.hasFlexibleDataRateFormat() || frame.payload().size() > 8) {
        setError(tr("Cannot write an invalid or CAN FD frame: %1.").arg(frame.toString()),
                 WriteError);
        return false;
    }
    if (frame.frameType() != QCanBusFrame::DataFrame &&
        frame.frameType() != QCanBusFrame::RemoteRequestFrame) {
        setError(tr("Only data and remote request frames can be written."), WriteError);
        return false;
    }
    if (m_refuseWrite || !m_bus) {
        setError(tr("The memory CAN device %1 failed to write the frame.").arg(m_name), WriteError);
        return false;
    }
    m_bus->transmit(this, frame);
    return true;
}

void MemoryCanDevice::injectError(const QString &text, CanBusError error, bool disconnect)
{
    setError(text, error);
    if (disconnect && state() != UnconnectedState)
        setState(UnconnectedState);
}

void MemoryCanDevice::injectErrorFrame(const QCanBusFrame &frame)
{
    if (state() == ConnectedState && frame.frameType() == QCanBusFrame::ErrorFrame)
        enqueueReceivedFrames({frame});
}

QString MemoryCanDevice::interpretErrorFrame(const QCanBusFrame &errorFrame)
{
    if (errorFrame.frameType() != QCanBusFrame::ErrorFrame)
        return {};
    return tr("CAN error frame, error classes 0x%1.")
        .arg(quint32(errorFrame.error().toInt()), 0, 16);
}

QCanBusDeviceInfo MemoryCanDevice::deviceInfo() const
{
    return createDeviceInfo(QStringLiteral("memory"), m_name, true, false);
}

void MemoryCanDevice::receive(const QCanBusFrame &frame)
{
    if (state() != ConnectedState || !acceptedByFilters(frame))
        return;
    enqueueReceivedFrames({frame});
}

bool MemoryCanDevice::acceptedByFilters(const QCanBusFrame &frame) const
{
    const QVariant value = configurationParameter(RawFilterKey);
    if (!value.isValid())
        return true;
    const auto filters = value.value<QList<QCanBusDevice::Filter>>();
    if (filters.isEmpty())
        return true;
    for (const Filter &f : filters) {
        const bool format = frame.hasExtendedFrameFormat()
                                ? (f.format & Filter::MatchExtendedFormat)
                                : (f.format & Filter::MatchBaseFormat);
        const bool type = f.type == QCanBusFrame::InvalidFrame || f.type == frame.frameType();
        if (format && type && (frame.frameId() & f.frameIdMask) == (f.frameId & f.frameIdMask))
            return true;
    }
    return false;
}

} // namespace learnid
