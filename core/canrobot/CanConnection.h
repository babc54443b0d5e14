#pragma once

#include "canrobot/CanRobotOptions.h"

#include <QAbstractSocket>
#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <functional>
#include <memory>

namespace learnid {

class CanLink;

/// The CAN device of the master and the link every protocol unit shares. Connecting has a
/// timeout of its own (virtualcan stays "connecting" forever on an unreachable host), and a
/// device that drops to unconnected later is reported as lost (virtualcan does so without an
/// error signal when the other side exits). Lives in the thread that opens the device.
class CanConnection : public QObject
{
    Q_OBJECT

public:
    using Done = std::function<void(const QString &error)>;

    CanConnection(CanDeviceFactory factory, QString name, int timeoutMs, QObject *parent = nullptr);
    ~CanConnection() override;

    /// Creates and connects the device; done(error) once, empty on success, never from inside
    /// open(). An open connection answers at once.
    void open(Done done);
    void close();
    /// While connected, watch the SocketCAN interface: when it goes down or its controller
    /// turns error passive or bus off, lost() names the interface (checked every 25 ms).
    void watchSocketCanInterface(const QString &interface);
    bool isConnected() const;
    QString name() const { return m_name; }

    CanLink *link() const { return m_link.get(); }
    QCanBusDevice *device() const { return m_device; }
    /// When the frames being handled arrived [ns of a steady clock] (for latency figures).
    qint64 lastArrivalNs() const { return m_lastArrival; }
    qint64 nowNs() const { return m_clock.nsecsElapsed(); }

signals:
    /// The device went unconnected (or reported a fatal error) after it had connected.
    void lost(const QString &reason);

private:
    void onStateChanged(QCanBusDevice::CanBusDeviceState state);
    void onError(QCanBusDevice::CanBusError error);
    void onErrorFrame(const QCanBusFrame &frame);
    void checkInterface();
    /// What is wrong with the watched SocketCAN interface (gone, down, error passive, bus off),
    /// or empty.
    QString interfaceFault() const;
    void fail(const QString &reason);
    void complete(const QString &error);
    void acknowledgeQuickly();

    CanDeviceFactory m_factory;
    QString m_name;
    int m_timeoutMs;
    QPointer<QCanBusDevice> m_device;
    QList<QPointer<QAbstractSocket>> m_sockets; ///< of a TCP-carried bus (virtualcan)
    std::unique_ptr<CanLink> m_link;
    QTimer *m_timer;          ///< a child: it moves to the CAN thread with this object
    QTimer *m_interfaceTimer; ///< the SocketCAN interface watch, a child as well
    QString m_watchedInterface;
    bool m_watchState = false; ///< the driver reports a controller state (a real CAN controller)
    Done m_pending;
    bool m_connected = false;
    QElapsedTimer m_clock;
    qint64 m_lastArrival = 0;
};

} // namespace learnid
