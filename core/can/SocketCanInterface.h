#pragma once

#include "can/CanBusErrors.h"

#include <QString>

class QCanBusDevice;

namespace learnid {

/// What learnid finds out about a SocketCAN interface before and while it uses it
/// (docs/user-guide.md, "A robot on a CAN bus"): from /sys/class/net/NAME (type, flags, mtu)
/// and, where the driver gives them, from rtnetlink (bitrate and controller state of a real CAN
/// controller; a vcan has neither).
struct SocketCanInterfaceInfo
{
    bool exists = false;
    bool isCan = false;  ///< link type ARPHRD_CAN (280)
    bool up = false;     ///< IFF_UP
    int mtu = 0;         ///< 16: CAN 2.0, 72: CAN FD
    QString kind;        ///< rtnetlink's link kind: "can", "vcan", ... (empty when unknown)
    quint32 bitrate = 0; ///< [bit/s]; 0 when not readable
    CanControllerState state = CanControllerState::Unknown;

    bool canFd() const { return mtu == 72; }
};

/// Reads the interface's facts; sysfsNet is the folder of the network interfaces (tests give
/// a folder of their own; rtnetlink is then not asked).
SocketCanInterfaceInfo
readSocketCanInterface(const QString &name,
                       const QString &sysfsNet = QStringLiteral("/sys/class/net"));

/// Why the interface cannot carry a trial (missing, not CAN, down, error passive, bus off), with
/// what to do, or empty.
QString socketCanInterfaceError(const QString &name, const SocketCanInterfaceInfo &info);

/// "vcan0: up, CAN FD (mtu 72), virtual (vcan), bitrate not readable" for the log.
QString describeSocketCanInterface(const QString &name, const SocketCanInterfaceInfo &info);

/// Before connecting: on socketcan, removes the bitrate that Qt's plugin would otherwise try to
/// set at every connect (it cannot: SocketCAN takes the bitrate from `ip link`, and Qt warns
/// "Cannot apply parameter: 4 with value: 500000"), and asks for every error frame. Other
/// plugins are left as they are.
void prepareCanDevice(QCanBusDevice *device, const QString &plugin);

/// Disconnects the device so that nothing polls its socket afterwards: its socket notifiers are
/// disabled before the plugin closes the file descriptor (Qt's socketcan plugin closes it but
/// leaves the notifier on: "QSocketNotifier: Invalid socket ... disabling...").
void closeCanDevice(QCanBusDevice *device);

} // namespace learnid
