// learnid-bench-chain, speed of whole sessions (issue 13): 6 learning trials of the LWR4+,
// simulation included, CPU time, with the share of the simulated robot.
#include "chain.h"

#include "BenchSupport.h"

#include <cstdio>

namespace learnid::bench {

namespace {

/// The simulated robot, its trials timed: how much of a session is simulation.
class TimedRobot final : public Robot
{
public:
    explicit TimedRobot(std::shared_ptr<Robot> robot)
        : m_robot(std::move(robot))
    {}
    QString description() const override { return m_robot->description(); }
    TrialRecord runTrial(const TrialPlan &plan, const TrialMonitor &monitor) override
    {
        const double t0 = cpuSeconds();
        TrialRecord r = m_robot->runTrial(plan, monitor);
        seconds += cpuSeconds() - t0;
        samples += r.samples();
        return r;
    }
    QString applyParameters(const Eigen::VectorXd &phi) override
    {
        return m_robot->applyParameters(phi);
    }
    Eigen::VectorXd storedParameters() const override { return m_robot->storedParameters(); }
    double seconds = 0.0;
    long samples = 0;

private:
    std::shared_ptr<Robot> m_robot;
};

} // namespace

void printChainSessions(const ChainOptions &o)
{
    std::printf("| 6-trial session, simulation included | sessions | median CPU | of it "
                "simulation | per sample | the rest: planning, checks, updates | samples "
                "simulated | target | |\n|---|---|---|---|---|---|---|---|---|\n");
    struct Row
    {
        const char *name;
        bool noisy;
        int repetitions;
        int sessions;
    };
    const int few = std::max(1, o.repeats / 3);
    const Row rows[] = {
        {"tst_chainsession's settings, noise free", false, 0, few},
        {"tst_chainsession's settings, 2^20 counts, 1 % torque noise", true, 0, few},
        {"the settings chosen, noise free, 1 run per trial", false, 1, few},
        {"the settings chosen, 2^20 counts, 1 % torque noise, 1 run per trial", true, 1, few},
        {"the accuracy scenario as chosen, runs per trial:", true, o.repetitions, 1}};
    for (const Row &row : rows) {
        ChainOptions ro = row.repetitions == 0 ? testSettings(o) : o;
        ro.repetitions = std::max(1, row.repetitions);
        std::vector<double> total, sim, rest;
        long samples = 0;
        for (int r = 0; r < row.sessions; ++r) {
            const Scenario requested = chainScenario(ro, 1, row.noisy);
            const auto model = makeRobotModel(requested.model, requested.urdf); // cached
            const double t0 = cpuSeconds();
            const Scenario s = resolvedChainScenario(ro, *model, 1, row.noisy);
            auto robot = std::make_shared<TimedRobot>(makeSimulatedRobot(s, model));
            CommissioningSession session(s, model, robot);
            const bool ok = session.runTrials(6);
            total.push_back(cpuSeconds() - t0);
            sim.push_back(robot->seconds);
            rest.push_back(total.back() - robot->seconds);
            samples = robot->samples;
            if (!ok) {
                total.clear();
                std::printf("| %s: failed: %s |\n", row.name,
                            qPrintable(session.history().constLast().message));
                break;
            }
        }
        if (total.empty())
            continue;
        const double t = median(total);
        std::printf(
            "| %s%s | %d | %.0f ms | %.0f ms | %.0f µs | %.0f ms | %ld | < 1 s | %s |\n", row.name,
            row.repetitions > 1 ? qPrintable(QStringLiteral(" %1").arg(row.repetitions)) : "",
            row.sessions, 1e3 * t, 1e3 * median(sim), 1e6 * median(sim) / double(samples),
            1e3 * median(rest), samples, t < 1.0 ? "met" : "**not met**");
    }
    std::printf("\n(Each session builds itself (perturbed truth, planner) and runs 6 learning "
                "trials: planning, pre-trial checks, simulation, identification; the model comes "
                "from makeRobotModel's cache.)\n\n");
}

} // namespace learnid::bench
