#pragma once

#include "canrobot/CanRobotOptions.h"

#include <QStringList>

namespace learnid {

/// Which robot a session drives, as the technician chose it (the window's robot panel, the
/// command line's --robot): the scenario's simulated robot, CiA 402 drives on a CAN bus, or
/// recorded candump logs answering in place of the drives.
struct RobotRequest
{
    enum class Kind { Simulated, Can, Replay };
    Kind kind = Kind::Simulated;
    CanRobotOptions can;      ///< Can: plugin, interface, nodes, ...; Replay: the nodes
    QStringList candumpFiles; ///< Replay: one log per trial, in trial order
};

} // namespace learnid
