// learnid-bench-zoo's law column: how well a trial tracks when its feedforward is the simulated
// robot's own joint law, the most any identified model can give the controller.
#include "zoo.h"

#include "model/ChainModel.h"
#include "session/ScenarioRobot.h"
#include "session/ScenarioRobotJoints.h"
#include "session/TrialPlanner.h"

#include <cmath>

namespace learnid::bench {

namespace {

// Sample k's desired velocity and acceleration at the instant its feedforward is built for
// (controller.feedforwardTime): t_k, or the middle of its hold (linear between the samples).
void feedforwardState(const TrialPlan &plan, int j, int k, double &qd, double &qdd)
{
    const JointTrajectory &d = plan.desired;
    qd = d.qd(j, k);
    qdd = d.qdd(j, k);
    if (plan.controller.feedforwardTime == FeedforwardTime::MidSample && k + 1 < d.samples()) {
        qd = 0.5 * (qd + d.qd(j, k + 1));
        qdd = 0.5 * (qdd + d.qdd(j, k + 1));
    }
}

} // namespace

double ownLawError(const Scenario &requested, bool rotor)
{
    const auto model = makeRobotModel(requested.model, requested.urdf); // cached
    Scenario s = withRobotDefaults(requested, *model);
    s.gentleTrials = 0; // the planned speed, as the learned trials run
    const Eigen::VectorXd truth = simulatedTrueParameters(s, *model);
    const JointRealism r = simulatedJoints(s, *model);
    // The plan's feedforward is the truth's rigid law: links, viscous friction and the model's
    // smooth Coulomb term. Exchange that term for the robot's Stribeck law with the exact sign of
    // the desired velocity, and add the rotor inertia the model leaves out.
    TrialPlan plan = TrialPlanner(s, model).plan(truth);
    const auto *chain = dynamic_cast<const ChainModel *>(model.get());
    const double vc = chain ? chain->jointTerms().coulombVelocity : 1.0;
    for (int k = 0; k < plan.samples(); ++k) {
        for (int j = 0; j < model->dof(); ++j) {
            double qd = 0, qdd = 0;
            feedforwardState(plan, j, k, qd, qdd);
            double &tau = plan.feedforward(j, k);
            if (r.stribeck()) {
                const double fc = r.coulomb[j], fs = r.staticFriction[j];
                const double v = qd / r.stribeckVelocity;
                const double sign = qd > 0.0 ? 1.0 : qd < 0.0 ? -1.0 : 0.0;
                tau += (fc + (fs - fc) * std::exp(-v * v)) * sign - fc * std::tanh(qd / vc);
            }
            if (rotor && r.armature.size() > 0)
                tau += r.armature[j] * qdd;
        }
    }
    const TrialRecord record = makeSimulatedRobot(s, model)->runTrial(plan, TrialMonitor{});
    if (!record.completed()) // stopped at the limit: the gains do not hold this robot
        return INFINITY;
    const int n = record.samples();
    return (plan.desired.q.leftCols(n) - record.q).cwiseAbs().maxCoeff() * 180.0 / M_PI;
}

} // namespace learnid::bench
