#pragma once

#include <QCanBusFrame>
#include <QList>
#include <QObject>
#include <QPointer>
#include <functional>

namespace learnid {

class MemoryCanDevice;

/// An in-process CAN bus for tests and demos: every frame one attached device writes reaches all
/// other connected devices (and the writer itself when its ReceiveOwnKey is true), in write
/// order, through the event loop like real hardware: never inside the writeFrame() call.
/// Devices and bus live in one thread.
///
/// Fault injection: a drop predicate loses chosen frames on the wire; the writer still sees
/// them written (framesWritten), as with a receiver that misses a frame.
class MemoryCanBus : public QObject
{
    Q_OBJECT

public:
    /// Returns true for a frame to lose.
    using DropPredicate = std::function<bool(const QCanBusFrame &frame)>;

    explicit MemoryCanBus(QObject *parent = nullptr);
    ~MemoryCanBus() override;

    /// A new device on this bus, named e.g. "can0"; owned by parent, or by the bus when null.
    /// The device still has to be connected with connectDevice().
    MemoryCanDevice *createDevice(const QString &name, QObject *parent = nullptr);
    QList<MemoryCanDevice *> devices() const;

    void setDropPredicate(DropPredicate predicate) { m_drop = std::move(predicate); }
    void clearDropPredicate() { m_drop = nullptr; }

    qint64 deliveredFrames() const { return m_delivered; }
    qint64 droppedFrames() const { return m_dropped; }

signals:
    /// A frame was on the wire (after the drop predicate spared it), with its bus timestamp.
    void frameTransmitted(const QCanBusFrame &frame);
    void frameDropped(const QCanBusFrame &frame);

private:
    friend class MemoryCanDevice;
    void attach(MemoryCanDevice *device);
    void detach(MemoryCanDevice *device);
    void transmit(MemoryCanDevice *sender, const QCanBusFrame &frame);
    void deliverPending();

    struct Pending
    {
        QPointer<MemoryCanDevice> sender;
        QCanBusFrame frame;
    };
    QList<QPointer<MemoryCanDevice>> m_devices;
    QList<Pending> m_pending;
    bool m_deliveryScheduled = false;
    DropPredicate m_drop;
    qint64 m_delivered = 0;
    qint64 m_dropped = 0;
};

} // namespace learnid
