#pragma once

#include <QCanBusDevice>
#include <QCanBusFrame>
#include <QObject>
#include <QPointer>

namespace learnid {

/// One CAN device shared by several protocol units (SDO, NMT, heartbeat, EMCY, PDO).
/// QCanBusDevice::readFrame() takes a frame out of the device's queue, so only one reader may
/// exist: the link reads every received frame and hands it to all units through frameReceived()
/// (error frames through errorFrameReceived()).
/// It also writes for them and reports both directions (for the candump log).
/// The link does not own the device; the device must outlive it or be destroyed with it.
class CanLink : public QObject
{
    Q_OBJECT

public:
    explicit CanLink(QCanBusDevice *device, QObject *parent = nullptr);

    QCanBusDevice *device() const { return m_device; }
    bool isConnected() const;

    /// Writes a frame. Returns false, and emits sendFailed(), when the device refuses it
    /// (not connected, invalid frame, driver error).
    bool send(const QCanBusFrame &frame);
    /// The reason of the last refused send(), translated.
    QString lastError() const { return m_lastError; }

signals:
    /// A data or remote frame from the bus.
    void frameReceived(const QCanBusFrame &frame);
    /// An error frame of the controller (SocketCAN's CAN_ERR_FLAG frames): kept apart, because
    /// its identifier is a set of error classes, not a COB-ID (CAN_ERR_BUSERROR is 0x080, the
    /// SYNC's).
    void errorFrameReceived(const QCanBusFrame &frame);
    /// A frame the device accepted for writing (not yet a confirmation of transmission).
    void frameSent(const QCanBusFrame &frame);
    void sendFailed(const QCanBusFrame &frame, const QString &reason);

private:
    void readFrames();

    QPointer<QCanBusDevice> m_device;
    QString m_lastError;
};

} // namespace learnid
