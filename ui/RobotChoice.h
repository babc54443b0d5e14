#pragma once

#include "canrobot/CanRobotOptions.h"

namespace learnid {

/// Which robot a session drives: the simulated robot of the scenario, or CiA 402 drives on a
/// CAN bus reached with the given options.
struct RobotChoice
{
    bool can = false;
    CanRobotOptions canOptions;
};

} // namespace learnid
