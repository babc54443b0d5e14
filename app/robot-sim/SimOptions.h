#pragma once

#include "cansim/CanArmSimulator.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace learnid::robotsim {

/// Exit codes of learnid-robot-sim (docs/can-protocol.md).
enum ExitCode {
    ExitOk = 0,      ///< stopped by SIGINT, SIGTERM or stdin closing
    ExitFailure = 1, ///< the CAN device failed: cannot be created or connected, disconnected
    ExitUsage = 2,   ///< a bad option or value, an unusable scenario or state file
};

/// The command line of learnid-robot-sim.
struct SimOptions
{
    QString plugin;
    QString interface;
    QList<int> nodes;     ///< empty: joint j is node j, for every joint of the scenario's robot
    QString scenarioPath; ///< empty: the paper scenario
    QString statePath;    ///< empty: no state file
    CanSimFaults faults;
    bool uncommissioned = false; ///< the drives' joint identity 0x2400 is 0
    /// The arm starts without the scenario's payload; "mount" on stdin mounts it.
    bool payloadOff = false;
    int setPointTimeoutSyncs = 0; ///< 0: 3 SYNC periods, at least 50 ms (can/CanTimeouts.h)
};

struct SimCommandLine
{
    enum class Command { Run, Help, Version, None } command = Command::None;
    SimOptions options;
    QString error; ///< for Command::None: which option and value are wrong
    QString usage;
};

/// Parses arguments (arguments[0] is the program). Errors name the option and the value.
SimCommandLine parseSimCommandLine(const QStringList &arguments);

} // namespace learnid::robotsim
