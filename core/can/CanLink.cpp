#include "can/CanLink.h"

#include "can/CanLogging.h"

namespace learnid {

CanLink::CanLink(QCanBusDevice *device, QObject *parent)
    : QObject(parent)
    , m_device(device)
{
    Q_ASSERT(device);
    connect(device, &QCanBusDevice::framesReceived, this, &CanLink::readFrames);
}

bool CanLink::isConnected() const
{
    return m_device && m_device->state() == QCanBusDevice::ConnectedState;
}

bool CanLink::send(const QCanBusFrame &frame)
{
    QString reason;
    if (!m_device)
        reason = tr("The CAN device no longer exists.");
    else if (m_device->state() != QCanBusDevice::ConnectedState)
        reason = tr("The CAN device %1 is not connected.").arg(m_device->deviceInfo().name());
    else if (!m_device->writeFrame(frame))
        reason = tr("The CAN device refused the frame: %1").arg(m_device->errorString());
    if (!reason.isEmpty()) {
        m_lastError = reason;
        qCWarning(lcCan) << "send failed:" << frame.toString() << reason;
        emit sendFailed(frame, reason);
        return false;
    }
    emit frameSent(frame);
    return true;
}

void CanLink::readFrames()
{
    if (!m_device)
        return;
    // A unit may react by sending; that never re-enters here synchronously because devices
    // deliver received frames through the event loop.
    const QList<QCanBusFrame> frames = m_device->readAllFrames();
    for (const QCanBusFrame &frame : frames) {
        if (frame.frameType() == QCanBusFrame::ErrorFrame)
            emit errorFrameReceived(frame);
        else if (frame.isValid())
            emit frameReceived(frame);
    }
}

} // namespace learnid
