#include "canrobot/CanConnection.h"

#include "can/CanBusErrors.h"
#include "can/CanLink.h"
#include "can/CanLogging.h"
#include "can/SocketCanInterface.h"

#include <QAbstractSocket>
#ifdef Q_OS_LINUX
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#endif
#include <QCoreApplication>
#include <QVariant>
#include <utility>

namespace learnid {

CanConnection::CanConnection(CanDeviceFactory factory, QString name, int timeoutMs, QObject *parent)
    : QObject(parent)
    , m_factory(std::move(factory))
    , m_name(std::move(name))
    , m_timeoutMs(timeoutMs)
    , m_timer(new QTimer(this))
    , m_interfaceTimer(new QTimer(this))
{
    m_interfaceTimer->setInterval(25);
    connect(m_interfaceTimer, &QTimer::timeout, this, &CanConnection::checkInterface);
    m_clock.start();
    m_timer->setSingleShot(true);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, [this] {
        const QString error = tr("the CAN device %1 did not connect within %2 ms (is the bus or "
                                 "the robot side running?)")
                                  .arg(m_name)
                                  .arg(m_timeoutMs);
        close();
        complete(error);
    });
}

CanConnection::~CanConnection()
{
    close();
}

void CanConnection::open(Done done)
{
    if (m_pending) { // a second caller waits for the same attempt
        Done first = std::move(m_pending);
        m_pending = [first = std::move(first), done = std::move(done)](const QString &e) {
            first(e);
            done(e);
        };
        return;
    }
    m_pending = std::move(done);
    if (isConnected()) {
        QMetaObject::invokeMethod(
            this, [this] { complete({}); }, Qt::QueuedConnection);
        return;
    }
    close();
    QString error;
    QCanBusDevice *device = m_factory ? m_factory(&error) : nullptr;
    if (!device) {
        if (error.isEmpty())
            error = tr("no CAN device for %1").arg(m_name);
        QMetaObject::invokeMethod(
            this, [this, error] { complete(error); }, Qt::QueuedConnection);
        return;
    }
    m_device = device;
    device->setParent(this);
    // Connected before the link, so that the arrival time is taken before any unit reads.
    connect(device, &QCanBusDevice::framesReceived, this, [this] {
        m_lastArrival = m_clock.nsecsElapsed();
        acknowledgeQuickly();
    });
    m_link = std::make_unique<CanLink>(device);
    connect(m_link.get(), &CanLink::errorFrameReceived, this, &CanConnection::onErrorFrame);
    connect(device, &QCanBusDevice::stateChanged, this, &CanConnection::onStateChanged);
    connect(device, &QCanBusDevice::errorOccurred, this, &CanConnection::onError);
    m_timer->start(m_timeoutMs);
    if (!device->connectDevice()) {
        const QString reason =
            tr("cannot connect the CAN device %1: %2").arg(m_name, device->errorString());
        close();
        QMetaObject::invokeMethod(
            this, [this, reason] { complete(reason); }, Qt::QueuedConnection);
        return;
    }
    if (device->state() == QCanBusDevice::ConnectedState)
        onStateChanged(QCanBusDevice::ConnectedState);
}

void CanConnection::close()
{
    m_timer->stop();
    m_interfaceTimer->stop();
    m_connected = false;
    m_link.reset();
    if (m_device) {
        QCanBusDevice *device = m_device;
        m_device = nullptr;
        device->disconnect(this);
        closeCanDevice(device);
        device->deleteLater(); // close() may run inside one of the device's signals
    }
}

void CanConnection::watchSocketCanInterface(const QString &interface)
{
    m_watchedInterface = interface;
}

bool CanConnection::isConnected() const
{
    return m_connected && m_device && m_device->state() == QCanBusDevice::ConnectedState;
}

void CanConnection::onStateChanged(QCanBusDevice::CanBusDeviceState state)
{
    if (state == QCanBusDevice::ConnectedState && !m_connected) {
        m_timer->stop();
        // virtualcan carries frames over TCP without TCP_NODELAY: Nagle's algorithm would hold
        // a second frame written within one round trip (the RPDO of joint 2) until an ACK.
        m_sockets.clear();
        for (QAbstractSocket *socket : m_device->findChildren<QAbstractSocket *>()) {
            socket->setSocketOption(QAbstractSocket::LowDelayOption, QVariant(1));
            m_sockets.append(socket);
        }
        m_connected = true;
        qCInfo(lcCan).noquote() << "connected" << m_name;
        if (!m_watchedInterface.isEmpty()) {
            const SocketCanInterfaceInfo info = readSocketCanInterface(m_watchedInterface);
            m_watchState = info.state != CanControllerState::Unknown;
            qCInfo(lcCan).noquote() << describeSocketCanInterface(m_watchedInterface, info);
            m_interfaceTimer->start();
        }
        QMetaObject::invokeMethod(
            this, [this] { complete({}); }, Qt::QueuedConnection);
    } else if (state == QCanBusDevice::UnconnectedState && m_connected) {
        const QString detail = m_device && !m_device->errorString().isEmpty()
                                   ? m_device->errorString()
                                   : tr("no error reported (the other side may have exited)");
        fail(tr("the CAN device %1 went unconnected: %2").arg(m_name, detail));
    }
}

void CanConnection::fail(const QString &reason)
{
    if (!m_connected)
        return;
    m_connected = false;
    m_interfaceTimer->stop();
    emit lost(reason);
}

void CanConnection::onErrorFrame(const QCanBusFrame &frame)
{
    const CanBusErrorReport report = classifyErrorFrame(frame);
    if (!report.fatal) {
        qCWarning(lcCan).noquote()
            << tr("the CAN device %1 reported an error frame: %2").arg(m_name, report.what);
        return;
    }
    fail(tr("the CAN device %1 reported %2 (error frame 0x%3 %4)")
             .arg(m_name, report.what)
             .arg(quint32(frame.error().toInt()), 0, 16) // frameId() is 0 for error frames
             .arg(QString::fromLatin1(frame.payload().toHex(' '))));
}

QString CanConnection::interfaceFault() const
{
    if (m_watchedInterface.isEmpty())
        return {};
    const SocketCanInterfaceInfo info = readSocketCanInterface(m_watchedInterface);
    if (!info.exists)
        return tr("the CAN interface %1 of %2 disappeared").arg(m_watchedInterface, m_name);
    if (!info.up)
        return tr("the CAN interface %1 of %2 went down (ip link set %1 up brings it back)")
            .arg(m_watchedInterface, m_name);
    if (m_watchState && isFatalControllerState(info.state))
        return tr("the CAN controller of %1 (%2) is %3")
            .arg(m_watchedInterface, m_name, canControllerStateName(info.state));
    return {};
}

void CanConnection::checkInterface()
{
    if (!m_connected || m_watchedInterface.isEmpty())
        return;
    const QString fault = interfaceFault();
    if (!fault.isEmpty())
        return fail(fault);
    // What the plugin says itself (Qt's socketcan plugin with libsocketcan: a real controller).
    if (m_device && m_device->hasBusStatus()) {
        const QCanBusDevice::CanBusStatus status = m_device->busStatus();
        if (status == QCanBusDevice::CanBusStatus::BusOff)
            return fail(tr("the CAN device %1 reports bus off").arg(m_name));
        if (status == QCanBusDevice::CanBusStatus::Error)
            return fail(tr("the CAN device %1 reports error passive").arg(m_name));
    }
}

void CanConnection::onError(QCanBusDevice::CanBusError error)
{
    if (!m_device)
        return;
    if (m_connected && (error == QCanBusDevice::ReadError || error == QCanBusDevice::WriteError)) {
        // On SocketCAN: ENETDOWN (the interface went down), ENOBUFS (the controller cannot send:
        // bus off, no other node acknowledges); a trial cannot go on with either. The state of
        // the interface says more than the errno, when it is the cause.
        const QString fault = interfaceFault();
        if (!fault.isEmpty())
            return fail(fault);
        return fail(tr("the CAN device %1 reported a %2 error: %3")
                        .arg(m_name, error == QCanBusDevice::ReadError ? tr("read") : tr("write"),
                             m_device->errorString()));
    }
    if (error != QCanBusDevice::ConnectionError)
        return;
    const QString reason = tr("the CAN device %1 reported a connection error: %2")
                               .arg(m_name, m_device->errorString());
    if (m_connected) {
        fail(reason);
    } else if (m_pending) {
        close();
        QMetaObject::invokeMethod(
            this, [this, reason] { complete(reason); }, Qt::QueuedConnection);
    }
}

void CanConnection::acknowledgeQuickly()
{
#ifdef Q_OS_LINUX
    // The virtualcan server writes without TCP_NODELAY: while our delayed ACK of its last frame
    // is pending, Nagle's algorithm holds its next frame (the next SYNC) for up to 40 ms.
    // Quick ACKs (Linux) let every frame through at once.
    for (const QPointer<QAbstractSocket> &socket : std::as_const(m_sockets)) {
        if (!socket || socket->socketDescriptor() < 0)
            continue;
        const int one = 1;
        ::setsockopt(int(socket->socketDescriptor()), IPPROTO_TCP, TCP_QUICKACK, &one, sizeof(one));
    }
#endif
}

void CanConnection::complete(const QString &error)
{
    if (Done done = std::exchange(m_pending, nullptr))
        done(error);
}

} // namespace learnid
