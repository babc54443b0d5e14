#pragma once

// Test support: runs the learning loop of a scenario directly on the planner, the simulated
// robot and a law, without the session, so law tests depend on nothing above identify/.

#include "identify/LearningLaw.h"
#include "model/ModelFactory.h"
#include "robot/SimulatedRobot.h"
#include "session/TrialPlanner.h"

#include <cmath>
#include <deque>
#include <vector>

namespace learnid::test {

struct LearningRun
{
    std::vector<Eigen::VectorXd> estimates;  ///< phi_0 .. phi_N
    std::vector<double> maxTrackingErrorDeg; ///< of the trial run with estimate k
    std::vector<ParameterUpdate> updates;
};

inline LearningRun runLearning(const Scenario &scenario, int trials)
{
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    const TrialPlanner planner(scenario, model);
    MeasurementOptions options;
    options.encoderCounts = scenario.simulation.encoderCounts;
    options.torqueNoise = scenario.simulation.torqueNoise;
    options.seed = scenario.simulation.seed;
    SimulatedRobot robot(model, scenario.simulation.trueParameters, options);
    const auto law = makeLearningLaw(scenario.law);

    LearningRun run;
    run.estimates.push_back(scenario.initialParameters);
    std::deque<TrialPlan> plans; // deque: stable addresses for TrialData
    std::deque<TrialRecord> records;
    for (int k = 0; k < trials; ++k) {
        plans.push_back(planner.plan(run.estimates.back()));
        records.push_back(robot.runTrial(plans.back(), {}));
        const TrialPlan &plan = plans.back();
        const TrialRecord &record = records.back();
        run.maxTrackingErrorDeg.push_back((plan.desired.q - record.q).cwiseAbs().maxCoeff() *
                                          180.0 / M_PI);
        std::vector<TrialData> data;
        for (size_t i = 0; i < plans.size(); ++i)
            data.push_back({&plans[i], &records[i]});
        run.updates.push_back(law->update(*model, data, run.estimates.back(), scenario.estimator));
        run.estimates.push_back(run.updates.back().phi);
    }
    return run;
}

/// (phi - truth) / truth, per parameter.
inline Eigen::VectorXd relativeError(const Eigen::VectorXd &phi, const Eigen::VectorXd &truth)
{
    return (phi - truth).cwiseQuotient(truth);
}

} // namespace learnid::test
