#include "canrobot/CanRobotOptions.h"

#include "can/CanOpen.h"
#include "can/CanTimeouts.h"
#include "can/SocketCanInterface.h"
#include "model/Error.h"

#include <QCanBus>
#include <QCoreApplication>
#include <QSet>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CanRobot)
};

} // namespace

CanDeviceFactory qcanbusDeviceFactory(const QString &plugin, const QString &interface)
{
    return [plugin, interface](QString *error) -> QCanBusDevice * {
        if (plugin == QLatin1String("socketcan")) {
            // What the plugin would only find out by failing, or not at all (a down interface
            // opens, and carries nothing).
            const QString unusable =
                socketCanInterfaceError(interface, readSocketCanInterface(interface));
            if (!unusable.isEmpty()) {
                if (error)
                    *error = unusable;
                return nullptr;
            }
        }
        QString reason;
        QCanBusDevice *device = QCanBus::instance()->createDevice(plugin, interface, &reason);
        prepareCanDevice(device, plugin);
        if (!device && error) {
            *error = Text::tr("cannot create the CAN device %1/%2: %3")
                         .arg(plugin, interface,
                              reason.isEmpty() ? Text::tr("unknown plugin or interface") : reason);
        }
        return device;
    };
}

BusLoadConfig busLoadConfig(const CanRobotOptions &options)
{
    BusLoadConfig config;
    config.joints = int(options.nodes.size());
    config.sampleRate = options.syncPeriod > 0 ? 1.0 / options.syncPeriod : 1.0;
    config.bitrate = options.bitrate > 0 ? options.bitrate : 1.0;
    return config;
}

BusLoad configuredBusLoad(const CanRobotOptions &options)
{
    return estimateBusLoad(busLoadConfig(options));
}

int shortestFittingSyncPeriodMs(const CanRobotOptions &options)
{
    // 0x60C2:01 carries whole milliseconds (UNSIGNED8, exponent -3): 1 to 255 ms.
    BusLoadConfig config = busLoadConfig(options);
    for (int ms = 1; ms <= 255; ++ms) {
        config.sampleRate = 1000.0 / ms;
        if (estimateBusLoad(config).percent <= options.maxBusLoadPercent)
            return ms;
    }
    return 0;
}

QString busLoadError(const CanRobotOptions &options)
{
    const BusLoad load = configuredBusLoad(options);
    if (load.percent <= options.maxBusLoadPercent)
        return {};
    const QString figures =
        Text::tr("the configuration of %1 nodes at %2 Hz (SYNC every %3 ms) needs %4 of the bus, "
                 "more than the %5 % the tool allows")
            .arg(options.nodes.size())
            .arg(1.0 / options.syncPeriod, 0, 'f', 0)
            .arg(options.syncPeriod * 1000.0, 0, 'g', 4)
            .arg(load.text(options.bitrate))
            .arg(options.maxBusLoadPercent, 0, 'f', 0);
    const int ms = shortestFittingSyncPeriodMs(options);
    if (ms == 0)
        return Text::tr("%1; no SYNC period up to 255 ms fits: use a faster bus").arg(figures);
    CanRobotOptions offered = options;
    offered.syncPeriod = ms / 1000.0;
    // One trial drives every joint at every SYNC (docs/can-protocol.md §8.5): a longer SYNC
    // period is the only offer; the gains must suit it (the pre-trial check says so).
    return Text::tr("%1; the shortest SYNC period that fits is %2 ms (%3): set the scenario's "
                    "controller.samplePeriod to %4 s and the robot side's SYNC period to match")
        .arg(figures)
        .arg(ms)
        .arg(configuredBusLoad(offered).text(options.bitrate))
        .arg(ms / 1000.0, 0, 'g', 3);
}

QString canNodeOptionsError(const CanRobotOptions &options)
{
    if (options.nodes.isEmpty())
        return Text::tr("no CAN node given: one node per joint is needed");
    QSet<int> seen;
    for (const int node : options.nodes) {
        if (!canopen::isValidNodeId(node))
            return Text::tr("%1 is not a valid CANopen node id (1 to 127)").arg(node);
        if (seen.contains(node))
            return Text::tr("node %1 is listed twice").arg(node);
        seen.insert(node);
    }
    if (options.connectTimeoutMs <= 0 || options.sdoTimeoutMs <= 0 ||
        options.heartbeatPeriodMs < 0 || options.heartbeatPeriodMs > 65535 ||
        options.enableTimeoutMs <= 0 || options.syncTimeoutMs < 0 || !(options.syncPeriod > 0) ||
        !(options.bitrate > 0) || options.extraWaitMs < 0)
        return Text::tr("CAN timing options must be positive (heartbeat period at most 65535 ms)");
    return {};
}

QString canRobotOptionsError(const CanRobotOptions &options)
{
    const QString invalid = canNodeOptionsError(options);
    return invalid.isEmpty() ? busLoadError(options) : invalid;
}

QList<int> defaultNodeList(int joints)
{
    QList<int> nodes;
    for (int j = 1; j <= joints; ++j)
        nodes << j;
    return nodes;
}

void setSyncTimeoutMs(CanRobotOptions &options, int ms)
{
    options.syncTimeoutMs = std::max(0, ms);
}

void setSyncPeriod(CanRobotOptions &options, double seconds)
{
    if (seconds > 0)
        options.syncPeriod = seconds;
}

int effectiveSyncTimeoutMs(const CanRobotOptions &options)
{
    if (options.syncTimeoutMs <= 0)
        return cantimeouts::syncTimeoutMs(options.syncPeriod);
    return std::max(options.syncTimeoutMs,
                    cantimeouts::periodsWithFloorMs(options.syncPeriod, 2, 0));
}

CanRobotOptions replayOptions(CanRobotOptions options)
{
    options.plugin = QStringLiteral("candump");
    options.interface = QStringLiteral("replay");
    options.checkJointIdentity = false;
    options.extraWaitMs = cantimeouts::replayExtraWaitMs;
    return options;
}

int effectiveHeartbeatPeriodMs(const CanRobotOptions &options)
{
    return options.heartbeatPeriodMs > 0 ? options.heartbeatPeriodMs
                                         : cantimeouts::heartbeatPeriodMs(options.syncPeriod);
}

QList<int> parseNodeList(const QString &text, QString *error)
{
    QList<int> nodes;
    const QStringList parts = text.split(QLatin1Char(','));
    for (const QString &part : parts) {
        bool ok = false;
        const int node = part.trimmed().toInt(&ok);
        if (!ok || !canopen::isValidNodeId(node)) {
            if (error)
                *error = Text::tr("'%1' is not a CANopen node id (1 to 127)").arg(part.trimmed());
            return {};
        }
        if (nodes.contains(node)) {
            if (error)
                *error = Text::tr("node %1 is listed twice").arg(node);
            return {};
        }
        nodes.append(node);
    }
    return nodes;
}

} // namespace learnid
