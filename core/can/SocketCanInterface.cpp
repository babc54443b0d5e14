#include "can/SocketCanInterface.h"

#include <QCanBusDevice>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QSocketNotifier>

#ifdef Q_OS_LINUX
#include <cstring>
#include <linux/can/netlink.h>
#include <linux/if_link.h>
#include <linux/netlink.h>
#include <linux/rtnetlink.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>
#endif

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CanBus)
};

constexpr int arphrdCan = 280;
constexpr quint32 iffUp = 0x1;

QString readSysfs(const QString &dir, const char *file)
{
    QFile f(QDir(dir).filePath(QLatin1String(file)));
    return f.open(QIODevice::ReadOnly) ? QString::fromLatin1(f.readAll()).trimmed() : QString();
}

#ifdef Q_OS_LINUX
// IFLA_LINKINFO of the interface by rtnetlink: the link kind and, for a CAN controller, its
// bitrate and state (linux/can/netlink.h).
void readLinkInfo(const QString &name, SocketCanInterfaceInfo *info)
{
    const unsigned index = if_nametoindex(name.toLocal8Bit().constData());
    if (index == 0)
        return;
    const int fd = ::socket(AF_NETLINK, SOCK_RAW | SOCK_CLOEXEC, NETLINK_ROUTE);
    if (fd < 0)
        return;
    struct
    {
        nlmsghdr header;
        ifinfomsg body;
    } request{};
    request.header.nlmsg_len = NLMSG_LENGTH(sizeof(ifinfomsg));
    request.header.nlmsg_type = RTM_GETLINK;
    request.header.nlmsg_flags = NLM_F_REQUEST;
    request.body.ifi_family = AF_UNSPEC;
    request.body.ifi_index = int(index);
    timeval timeout{0, 200000};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof(timeout));
    alignas(nlmsghdr) char buffer[16384];
    ssize_t n = -1;
    if (::send(fd, &request, request.header.nlmsg_len, 0) >= 0)
        n = ::recv(fd, buffer, sizeof(buffer), 0);
    ::close(fd);
    if (n <= 0)
        return;
    for (auto *h = reinterpret_cast<nlmsghdr *>(buffer); NLMSG_OK(h, unsigned(n));
         h = NLMSG_NEXT(h, n)) {
        if (h->nlmsg_type != RTM_NEWLINK)
            continue;
        auto *link = static_cast<ifinfomsg *>(NLMSG_DATA(h));
        int len = int(IFLA_PAYLOAD(h));
        for (rtattr *a = IFLA_RTA(link); RTA_OK(a, len); a = RTA_NEXT(a, len)) {
            if (a->rta_type != IFLA_LINKINFO)
                continue;
            int infoLen = int(RTA_PAYLOAD(a));
            for (rtattr *i = static_cast<rtattr *>(RTA_DATA(a)); RTA_OK(i, infoLen);
                 i = RTA_NEXT(i, infoLen)) {
                if (i->rta_type == IFLA_INFO_KIND)
                    info->kind = QString::fromLatin1(static_cast<const char *>(RTA_DATA(i)));
                if (i->rta_type != IFLA_INFO_DATA)
                    continue;
                int dataLen = int(RTA_PAYLOAD(i));
                for (rtattr *d = static_cast<rtattr *>(RTA_DATA(i)); RTA_OK(d, dataLen);
                     d = RTA_NEXT(d, dataLen)) {
                    if (d->rta_type == IFLA_CAN_BITTIMING && RTA_PAYLOAD(d) >= sizeof(quint32)) {
                        std::memcpy(&info->bitrate, RTA_DATA(d), sizeof(quint32));
                    } else if (d->rta_type == IFLA_CAN_STATE && RTA_PAYLOAD(d) >= sizeof(quint32)) {
                        quint32 s = 0;
                        std::memcpy(&s, RTA_DATA(d), sizeof(s));
                        switch (s) {
                        case CAN_STATE_ERROR_ACTIVE:
                            info->state = CanControllerState::ErrorActive;
                            break;
                        case CAN_STATE_ERROR_WARNING:
                            info->state = CanControllerState::ErrorWarning;
                            break;
                        case CAN_STATE_ERROR_PASSIVE:
                            info->state = CanControllerState::ErrorPassive;
                            break;
                        case CAN_STATE_BUS_OFF:
                            info->state = CanControllerState::BusOff;
                            break;
                        case CAN_STATE_STOPPED:
                            info->state = CanControllerState::Stopped;
                            break;
                        default:
                            break;
                        }
                    }
                }
            }
        }
    }
}
#endif

} // namespace

SocketCanInterfaceInfo readSocketCanInterface(const QString &name, const QString &sysfsNet)
{
    SocketCanInterfaceInfo info;
    const QString dir = QDir(sysfsNet).filePath(name);
    if (name.isEmpty() || name.contains(QLatin1Char('/')) || !QFileInfo(dir).isDir())
        return info;
    info.exists = true;
    info.isCan = readSysfs(dir, "type").toInt() == arphrdCan;
    bool ok = false;
    info.up = readSysfs(dir, "flags").toUInt(&ok, 16) & iffUp;
    info.mtu = readSysfs(dir, "mtu").toInt();
#ifdef Q_OS_LINUX
    if (sysfsNet == QLatin1String("/sys/class/net"))
        readLinkInfo(name, &info);
#endif
    return info;
}

QString socketCanInterfaceError(const QString &name, const SocketCanInterfaceInfo &info)
{
    if (!info.exists)
        return Text::tr("the CAN interface %1 does not exist (ip link show: is the adapter "
                        "plugged in, its driver loaded?)")
            .arg(name);
    if (!info.isCan)
        return Text::tr("%1 is not a CAN interface").arg(name);
    if (!info.up)
        return Text::tr("the CAN interface %1 is down (as root: ip link set %1 type can bitrate "
                        "1000000 && ip link set %1 up)")
            .arg(name);
    if (isFatalControllerState(info.state))
        return Text::tr("the CAN controller of %1 is %2 (as root: ip link set %1 down && ip link "
                        "set %1 up; check wiring and termination)")
            .arg(name, canControllerStateName(info.state));
    return {};
}

QString describeSocketCanInterface(const QString &name, const SocketCanInterfaceInfo &info)
{
    const QString frames = info.canFd() ? Text::tr("CAN FD (mtu %1)").arg(info.mtu)
                                        : Text::tr("CAN (mtu %1)").arg(info.mtu);
    const QString bitrate = info.bitrate > 0
                                ? Text::tr("bitrate %1 kbit/s").arg(info.bitrate / 1000.0)
                                : Text::tr("bitrate not readable");
    QString text = Text::tr("%1: %2, %3, %4")
                       .arg(name, info.up ? Text::tr("up") : Text::tr("down"), frames, bitrate);
    if (!info.kind.isEmpty())
        text += Text::tr(", driver %1").arg(info.kind);
    if (info.state != CanControllerState::Unknown)
        text += Text::tr(", controller %1").arg(canControllerStateName(info.state));
    return text;
}

void prepareCanDevice(QCanBusDevice *device, const QString &plugin)
{
    if (!device || plugin != QLatin1String("socketcan"))
        return;
    device->setConfigurationParameter(QCanBusDevice::BitRateKey, QVariant());
    // Every error frame the controller reports (CAN_RAW_ERR_FILTER), whatever the plugin's
    // default: they are how SocketCAN tells of bus off, error passive and lost frames.
    device->setConfigurationParameter(
        QCanBusDevice::ErrorFilterKey,
        QVariant::fromValue(QCanBusFrame::FrameErrors(QCanBusFrame::AnyError)));
}

void closeCanDevice(QCanBusDevice *device)
{
    if (!device)
        return;
    for (QSocketNotifier *notifier : device->findChildren<QSocketNotifier *>())
        notifier->setEnabled(false);
    if (device->state() != QCanBusDevice::UnconnectedState)
        device->disconnectDevice();
}

} // namespace learnid
