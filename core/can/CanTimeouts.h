#pragma once

namespace learnid {

/// The timeouts of a CAN trial, each a number of SYNC periods with a floor in milliseconds, so
/// that they hold at any SYNC period on a machine that also runs other work
/// (docs/can-protocol.md §8.2). Ts is the SYNC period [s].
namespace cantimeouts {

/// The master stops a trial after this long without a SYNC: 10 periods, at least 50 ms.
constexpr int syncTimeoutPeriods = 10;
constexpr int syncTimeoutFloorMs = 50;
/// A drive faults (EMCY 0x8100) after this many SYNCs in Operation enabled without a fresh
/// set-point: 3 periods, at least 50 ms (learnid-robot-sim's default of --setpoint-timeout).
constexpr int setpointTimeoutPeriods = 3;
constexpr int setpointTimeoutFloorMs = 50;
/// The producer heartbeat time written to 0x1017: 10 periods, at least 100 ms; a node is lost
/// after heartbeatLossFactor heartbeat periods without one.
constexpr int heartbeatPeriods = 10;
constexpr int heartbeatFloorMs = 100;
constexpr int heartbeatLossFactor = 3;
/// The quick stop of a trial ends at the latest this long after the master noticed the fault:
/// 20 periods (the drive needs 12), at least 100 ms.
constexpr int stopBoundPeriods = 20;
constexpr int stopBoundFloorMs = 100;
/// A replay of recorded trials waits this much longer for a SYNC, a heartbeat or the enable walk:
/// it plays the recording at the master's pace, so a pause of the master (a loaded machine) is
/// no pause of the robot's, and only a gap in the recording leaves it waiting. Added to each
/// wait, it keeps their order: a robot fallen silent misses its SYNC before its heartbeat.
constexpr int replayExtraWaitMs = 2000;

/// max(periods x Ts, floorMs) in whole milliseconds (rounded up).
int periodsWithFloorMs(double ts, int periods, int floorMs);

/// The default SYNC timeout at Ts [ms].
int syncTimeoutMs(double ts);
/// The drive's set-point timeout at Ts [SYNCs]: the periods that cover max(3 Ts, 50 ms).
int setpointTimeoutSyncs(double ts);
/// The heartbeat period at Ts [ms] (0x1017, UNSIGNED16: at most 65535).
int heartbeatPeriodMs(double ts);
/// The bound of the quick stop at Ts [ms].
int stopBoundMs(double ts);

} // namespace cantimeouts
} // namespace learnid
