// Speed benchmark: CPU time of a 6-trial paper-scenario session (simulation at RK4 0.2 ms,
// planning, safety checks and identification included) and of one identification update over
// 10^6 samples. Prints Markdown. Usage: learnid-bench-speed [repeats] [--session-only | --parts]
// [--law paper|improved] (--session-only skips the 10^6-sample part, e.g. to count instructions
// under callgrind; --parts also times the session's parts one by one; --law measures one law).
#include "BenchSupport.h"
#include "identify/LearningLaw.h"
#include "session/SafetyCheck.h"
#include "session/TrialPlanner.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace learnid;

namespace {

// A long trial: the paper line driven forward and back until `samples` samples.
TrialPlan longPlan(const Scenario &s, int samples)
{
    const auto model = makeRobotModel(s.model, s.urdf);
    const TrialPlan one = TrialPlanner(s, model).plan(s.simulation.trueParameters);
    TrialPlan plan = one;
    const int n = one.samples();
    for (Eigen::MatrixXd *m : {&plan.desired.q, &plan.desired.qd, &plan.desired.qdd})
        m->resize(2, samples);
    for (int k = 0; k < samples; ++k) {
        const int period = k / n;
        const int i = k % n;
        const bool back = period % 2 == 1;
        const int src = back ? n - 1 - i : i;
        plan.desired.q.col(k) = one.desired.q.col(src);
        plan.desired.qd.col(k) = (back ? -1.0 : 1.0) * one.desired.qd.col(src);
        plan.desired.qdd.col(k) = one.desired.qdd.col(src);
    }
    plan.feedforward = feedforwardTorque(*model, plan.desired, s.simulation.trueParameters);
    return plan;
}

// CPU time of each part of a session, run as the session runs them (the same plans, robot and
// estimates): planning, pre-trial check, simulation, identification update.
void printParts(const char *lawName, int repeats)
{
    Scenario s;
    s.law = QString::fromLatin1(lawName);
    auto reference = bench::makeSession(s);
    if (!reference->runTrials(6))
        return;
    const auto model = makeRobotModel(s.model, s.urdf);
    const auto law = makeLearningLaw(s.law);
    const char *names[4] = {"planning (6 plans)", "pre-trial checks (6)", "simulation (6 trials)",
                            "identification (6 updates)"};
    std::vector<double> times[4];
    for (int r = 0; r < repeats; ++r) {
        const TrialPlanner planner(s, model);
        SimulatedRobot robot(model, s.simulation.trueParameters);
        std::vector<TrialPlan> plans(6);
        std::vector<TrialRecord> records(6);
        std::vector<std::shared_ptr<LawCache>> caches(6);
        double sum[4] = {0, 0, 0, 0};
        for (int k = 0; k < 6; ++k) {
            const Eigen::VectorXd &phi = reference->estimates()[k];
            double t[5];
            t[0] = bench::cpuSeconds();
            plans[k] = planner.plan(phi);
            t[1] = bench::cpuSeconds();
            checkTrial(*model, phi, plans[k], s.stabilityMargin);
            t[2] = bench::cpuSeconds();
            records[k] = robot.runTrial(plans[k], {});
            t[3] = bench::cpuSeconds();
            std::vector<TrialData> data;
            for (int i = 0; i <= k; ++i)
                data.push_back({&plans[i], &records[i], &caches[i]});
            law->update(*model, data, phi, s.estimator);
            t[4] = bench::cpuSeconds();
            for (int i = 0; i < 4; ++i)
                sum[i] += t[i + 1] - t[i];
        }
        for (int i = 0; i < 4; ++i)
            times[i].push_back(sum[i]);
    }
    for (int i = 0; i < 4; ++i)
        std::printf("| %s | %s | %.1f ms | %d |\n", names[i], lawName,
                    1e3 * bench::median(times[i]), repeats);
}

} // namespace

int main(int argc, char **argv)
{
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
    bool sessionOnly = false;
    bool parts = false;
    std::vector<const char *> laws = {"paper", "improved"};
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--session-only") {
            sessionOnly = true;
        } else if (arg == "--parts") {
            sessionOnly = true;
            parts = true;
        } else if (arg == "--law" && i + 1 < argc) {
            const std::string law = argv[++i];
            if (law != "paper" && law != "improved") {
                std::fprintf(stderr, "unknown law %s (paper or improved)\n", law.c_str());
                return 2;
            }
            laws = {law == "paper" ? "paper" : "improved"};
        } else {
            std::fprintf(stderr, "unknown argument %s\n", arg.c_str());
            return 2;
        }
    }
    std::printf("| measurement | law | median CPU time | repeats |\n|---|---|---|---|\n");
    for (const char *law : laws) {
        std::vector<double> times;
        for (int r = 0; r < repeats; ++r) {
            Scenario s;
            s.law = QString::fromLatin1(law);
            const double t0 = bench::cpuSeconds();
            auto session = bench::makeSession(s);
            const bool ok = session->runTrials(6);
            times.push_back(bench::cpuSeconds() - t0);
            if (!ok)
                return 1;
        }
        std::printf("| 6-trial paper-scenario session, simulation included | %s | %.1f ms | %d |\n",
                    law, 1e3 * bench::median(times), repeats);
        if (parts)
            printParts(law, repeats);
    }

    if (sessionOnly)
        return 0;
    const Scenario s;
    const int samples = 1000000;
    const TrialPlan plan = longPlan(s, samples);
    const auto model = makeRobotModel(s.model, s.urdf);
    SimulatedRobot robot(model, s.simulation.trueParameters);
    const double simStart = bench::cpuSeconds();
    const TrialRecord record = robot.runTrial(plan, {});
    const double simTime = bench::cpuSeconds() - simStart;
    if (!record.completed())
        return 1;
    for (const char *name : laws) {
        const auto law = makeLearningLaw(QString::fromLatin1(name));
        std::vector<double> times;
        for (int r = 0; r < 3; ++r) {
            const double t0 = bench::cpuSeconds();
            const ParameterUpdate up =
                law->update(*model, {{&plan, &record}}, s.initialParameters, s.estimator);
            times.push_back(bench::cpuSeconds() - t0);
            if (!up.phi.allFinite())
                return 1;
        }
        std::printf("| one identification update over %d samples (2 joints) | %s | %.0f ms | 3 |\n",
                    samples, name, 1e3 * bench::median(times));
    }
    std::printf("| simulating those %d samples (RK4, 10 steps per sample) | - | %.0f ms | 1 |\n",
                samples, 1e3 * simTime);
    return 0;
}
