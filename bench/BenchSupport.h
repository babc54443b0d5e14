#pragma once

#include "model/ModelFactory.h"
#include "session/CommissioningSession.h"
#include "session/ScenarioRobot.h"

#include <algorithm>
#include <ctime>
#include <memory>
#include <vector>

namespace learnid::bench {

/// CPU time of this process [s] (not wall time: unaffected by other processes' load).
inline double cpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

inline double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

/// A session of the scenario on a simulated robot with the scenario's measurement options.
inline std::unique_ptr<CommissioningSession> makeSession(const Scenario &s)
{
    const auto model = makeRobotModel(s.model, s.urdf);
    return std::make_unique<CommissioningSession>(s, model, makeSimulatedRobot(s, model));
}

} // namespace learnid::bench
