#include "can/CanTimeouts.h"

#include <algorithm>
#include <cmath>

namespace learnid::cantimeouts {

int periodsWithFloorMs(double ts, int periods, int floorMs)
{
    if (!(ts > 0))
        return floorMs;
    // 1e-9: 10 periods of 0.005 s are 50 ms, not 51 by the rounding of 1000 * 0.005.
    const int ms = int(std::ceil(periods * ts * 1000.0 - 1e-9));
    return std::max(ms, floorMs);
}

int syncTimeoutMs(double ts)
{
    return periodsWithFloorMs(ts, syncTimeoutPeriods, syncTimeoutFloorMs);
}

int setpointTimeoutSyncs(double ts)
{
    if (!(ts > 0))
        return setpointTimeoutPeriods;
    const int ms = periodsWithFloorMs(ts, setpointTimeoutPeriods, setpointTimeoutFloorMs);
    return std::max(setpointTimeoutPeriods, int(std::ceil(ms / (1000.0 * ts) - 1e-9)));
}

int heartbeatPeriodMs(double ts)
{
    return std::min(65535, periodsWithFloorMs(ts, heartbeatPeriods, heartbeatFloorMs));
}

int stopBoundMs(double ts)
{
    return periodsWithFloorMs(ts, stopBoundPeriods, stopBoundFloorMs);
}

} // namespace learnid::cantimeouts
