#pragma once

#include "can/BusLoad.h"
#include "types/DriveIdentity.h"

#include <QCanBusDevice>
#include <QList>
#include <QString>
#include <functional>

namespace learnid {

/// How the CAN robot reaches its drives and how long it waits for them (docs/can-protocol.md,
/// "Master side"). One CANopen node per joint, in joint order.
struct CanRobotOptions
{
    QString plugin = QStringLiteral("socketcan"); ///< QCanBus plugin name
    QString interface = QStringLiteral("can0");   ///< the plugin's interface name
    QList<int> nodes{1, 2};                       ///< node id of joint 1, 2, ...
    int connectTimeoutMs = 3000; ///< virtualcan stays "connecting" on an unreachable host
    int sdoTimeoutMs = 500;      ///< per SDO request
    /// Written to 0x1017 of every node (a node is lost after 3 periods without a heartbeat);
    /// 0: cantimeouts::heartbeatPeriodMs at the SYNC period (10 periods, at least 100 ms).
    int heartbeatPeriodMs = 0;
    int enableTimeoutMs = 500; ///< CiA 402 enable walk
    /// No SYNC for this long aborts a trial (at least 2 periods); 0: cantimeouts::syncTimeoutMs
    /// at the SYNC period (10 periods, at least 50 ms).
    int syncTimeoutMs = 0;
    double syncPeriod = 0.002;       ///< the SYNC period the robot side produces [s]
    double bitrate = 1'000'000.0;    ///< [bit/s]
    double maxBusLoadPercent = 70.0; ///< refuse to connect above this computed load
    QString candumpDir;              ///< when set, trial-NNN.log per trial (can-utils format)
    /// The robot's identity in 0x2400:01 of its drives; 0: objects::robotIdentityOf(model id).
    quint32 robotIdentity = 0;
    /// The first-time procedure (docs/can-protocol.md §2.4): the technician confirmed that each
    /// node is the drive of its joint; drives never commissioned (or for another robot) are
    /// accepted, and apply stores their joint identity.
    bool commissioning = false;
    /// The drives' 0x1018 per joint from a parameter file, compared before any motion; empty:
    /// not compared.
    QList<DriveIdentity> recordedDrives;
    /// Read and check every node's identity before a trial or apply; off only for a replay of
    /// recorded trials (whose logs begin at the trial's first NMT command).
    bool checkJointIdentity = true;
    /// Added to a trial's waits for a SYNC, a heartbeat and the enable walk [ms]; 0 but in a
    /// replay (replayOptions).
    int extraWaitMs = 0;
};

/// The options of a replay of recorded trials (CandumpReplayDevice): the device candump/replay,
/// no identity check (the logs begin at each trial's first NMT command), and waits longer by
/// cantimeouts::replayExtraWaitMs. A trial that the recording ends on a timeout (a silent robot)
/// ends the same way in the replay, only later.
CanRobotOptions replayOptions(CanRobotOptions options);

/// Creates the (not yet connected) CAN device in the calling thread; on failure returns null
/// and sets error. The default factory asks QCanBus for plugin and interface.
using CanDeviceFactory = std::function<QCanBusDevice *(QString *error)>;
CanDeviceFactory qcanbusDeviceFactory(const QString &plugin, const QString &interface);

/// The cyclic traffic of the options' configuration (SYNC, one RPDO and one TPDO per node at
/// the SYNC period, on the options' bitrate).
BusLoadConfig busLoadConfig(const CanRobotOptions &options);

/// The cyclic load of the options' configuration: estimateBusLoad(busLoadConfig(options)).
BusLoad configuredBusLoad(const CanRobotOptions &options);

/// The offer when the load is above the limit: the shortest SYNC period in whole milliseconds
/// (what 0x60C2 and the robot side's SYNC grid take, docs/can-protocol.md §8.5) from 1 to
/// 255 ms at which the options' nodes stay within maxBusLoadPercent, by the same
/// estimateBusLoad; 0 when none does.
int shortestFittingSyncPeriodMs(const CanRobotOptions &options);

/// Why the bus load of the options is above maxBusLoadPercent, with the figures and the
/// shortest SYNC period that fits (the scenario's controller.samplePeriod), or empty.
QString busLoadError(const CanRobotOptions &options);

/// Why the node list or the timing options cannot work (invalid or repeated node ids,
/// non-positive times), or empty; the bus load is not looked at.
QString canNodeOptionsError(const CanRobotOptions &options);

/// canNodeOptionsError, then busLoadError: why the options cannot work, or empty.
QString canRobotOptionsError(const CanRobotOptions &options);

/// Sets the time without SYNC that stops a trial [ms] (0: the default of the SYNC period).
void setSyncTimeoutMs(CanRobotOptions &options, int ms);

/// Sets the SYNC period [s] (the scenario's controller.samplePeriod, which the robot side
/// produces); a SYNC timeout given in ms stays, the default ones follow the period.
void setSyncPeriod(CanRobotOptions &options, double seconds);

/// The SYNC timeout in force [ms]: syncTimeoutMs (at least 2 periods), or the default at the
/// SYNC period (cantimeouts::syncTimeoutMs).
int effectiveSyncTimeoutMs(const CanRobotOptions &options);

/// The heartbeat period in force [ms]: heartbeatPeriodMs, or cantimeouts::heartbeatPeriodMs.
int effectiveHeartbeatPeriodMs(const CanRobotOptions &options);

/// Nodes 1, 2, ..., joints: joint j is node j (the default of --nodes for an n-joint robot).
QList<int> defaultNodeList(int joints);

/// "1,2,3" -> {1, 2, 3}; on failure returns empty and sets error (naming the bad element).
QList<int> parseNodeList(const QString &text, QString *error);

} // namespace learnid
