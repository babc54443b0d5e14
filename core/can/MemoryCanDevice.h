#pragma once

#include <QCanBusDevice>
#include <QPointer>

namespace learnid {

class MemoryCanBus;

/// A QCanBusDevice on a MemoryCanBus (see there). Classic CAN only (at most 8 data bytes).
/// Honours RawFilterKey (receive filters) and ReceiveOwnKey; other keys are stored only.
class MemoryCanDevice : public QCanBusDevice
{
    Q_OBJECT

public:
    /// Attached to bus (may be null: the device then cannot connect).
    explicit MemoryCanDevice(const QString &name, MemoryCanBus *bus, QObject *parent = nullptr);
    ~MemoryCanDevice() override;

    QString name() const { return m_name; }
    MemoryCanBus *bus() const { return m_bus; }

    /// Fault injection: connectDevice() fails with ConnectionError while set.
    void setRefuseConnect(bool refuse) { m_refuseConnect = refuse; }
    /// Fault injection: writeFrame() fails with WriteError while set (e.g. a full TX queue).
    void setRefuseWrite(bool refuse) { m_refuseWrite = refuse; }
    /// Fault injection: the driver reports an error (e.g. bus off) and, when disconnect is set,
    /// drops the connection as a real adapter does.
    void injectError(const QString &text, QCanBusDevice::CanBusError error, bool disconnect);
    /// Fault injection: the controller reports an error frame (as SocketCAN's drivers do, to
    /// this device only; it is not on the wire). Ignored when not connected.
    void injectErrorFrame(const QCanBusFrame &frame);

    bool writeFrame(const QCanBusFrame &frame) override;
    QString interpretErrorFrame(const QCanBusFrame &errorFrame) override;
    QCanBusDeviceInfo deviceInfo() const override;

protected:
    bool open() override;
    void close() override;

private:
    friend class MemoryCanBus;
    /// From the bus: the frame on the wire; ignored when not connected or filtered out.
    void receive(const QCanBusFrame &frame);
    void confirmWritten() { emit framesWritten(1); }
    bool acceptedByFilters(const QCanBusFrame &frame) const;

    QString m_name;
    QPointer<MemoryCanBus> m_bus;
    bool m_refuseConnect = false;
    bool m_refuseWrite = false;
};

} // namespace learnid
