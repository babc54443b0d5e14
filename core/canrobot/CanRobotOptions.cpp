#include "canrobot/CanRobotOptions.h"

#include "can/CanOpen.h"
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
        QString reason;
        QCanBusDevice *device = QCanBus::instance()->createDevice(plugin, interface, &reason);
        if (!device && error) {
            *error = Text::tr("cannot create the CAN device %1/%2: %3")
                         .arg(plugin, interface,
                              reason.isEmpty() ? Text::tr("unknown plugin or interface") : reason);
        }
        return device;
    };
}

BusLoad configuredBusLoad(const CanRobotOptions &options)
{
    BusLoadConfig config;
    config.joints = int(options.nodes.size());
    config.sampleRate = options.syncPeriod > 0 ? 1.0 / options.syncPeriod : 1.0;
    config.bitrate = options.bitrate > 0 ? options.bitrate : 1.0;
    return estimateBusLoad(config);
}

QString canRobotOptionsError(const CanRobotOptions &options)
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
        options.heartbeatPeriodMs <= 0 || options.heartbeatPeriodMs > 65535 ||
        options.heartbeatTimeoutFactor < 1 || options.enableTimeoutMs <= 0 ||
        options.syncGapPeriods < 2 || !(options.syncPeriod > 0) || !(options.bitrate > 0))
        return Text::tr("CAN timing options must be positive (heartbeat period at most 65535 ms)");
    const BusLoad load = configuredBusLoad(options);
    if (load.percent > options.maxBusLoadPercent) {
        return Text::tr("the configuration of %1 nodes at %2 Hz needs %3 of the bus, more than the "
                        "%4 % the tool allows: use fewer nodes per bus or a longer SYNC period")
            .arg(options.nodes.size())
            .arg(1.0 / options.syncPeriod, 0, 'f', 0)
            .arg(load.text(options.bitrate))
            .arg(options.maxBusLoadPercent, 0, 'f', 0);
    }
    return {};
}

void setSyncTimeoutMs(CanRobotOptions &options, int ms)
{
    options.syncGapPeriods = std::max(2, int(std::ceil(ms / (1000.0 * options.syncPeriod))));
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
