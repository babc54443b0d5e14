#include "canrobot/SetpointSchedule.h"

#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

// W(q, qd, qdd) phi, zero when phi does not fit the model.
Eigen::VectorXd feedforward(const RobotModel &model, const Eigen::VectorXd &q,
                            const Eigen::VectorXd &qd, const Eigen::VectorXd &qdd,
                            const Eigen::VectorXd &phi)
{
    const int n = model.dof();
    if (phi.size() != model.parameterCount() || q.size() != n)
        return Eigen::VectorXd::Zero(q.size());
    Eigen::MatrixXd w(n, model.parameterCount());
    model.regressor(q, qd, qdd, w);
    return w * phi;
}

Eigen::VectorXd gravity(const RobotModel &model, const Eigen::VectorXd &q,
                        const Eigen::VectorXd &phi)
{
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(q.size());
    return feedforward(model, q, zero, zero, phi);
}

// Quintic 10 x^3 - 15 x^4 + 6 x^5 and its first two derivatives in x.
struct Quintic
{
    double p, v, a;
};
Quintic quintic(double x)
{
    return {x * x * x * (10.0 - 15.0 * x + 6.0 * x * x), 30.0 * x * x * (1.0 - x) * (1.0 - x),
            60.0 * x * (1.0 - x) * (1.0 - 2.0 * x)};
}

// The largest |W(q, qd, qdd) phi - W(q, 0, 0) phi| / limit along the move of duration d.
double peakTorqueRatio(const RobotModel &model, const TrialPlan &plan, const Eigen::VectorXd &q0,
                       const Eigen::VectorXd &dq, double d, double ts)
{
    const int steps = std::max(1, int(std::ceil(d / ts)));
    double peak = 0.0;
    for (int i = 0; i <= steps; i += std::max(1, steps / 200)) {
        const Quintic s = quintic(double(i) / steps);
        // The part that shrinks with a longer move; gravity is held at the rests anyway.
        const Eigen::VectorXd q = q0 + s.p * dq;
        const Eigen::VectorXd tau =
            feedforward(model, q, s.v / d * dq, s.a / (d * d) * dq, plan.feedforwardParameters) -
            gravity(model, q, plan.feedforwardParameters);
        for (Eigen::Index j = 0; j < tau.size() && j < plan.torqueLimit.size(); ++j)
            if (plan.torqueLimit[j] > 0)
                peak = std::max(peak, std::abs(tau[j]) / plan.torqueLimit[j]);
    }
    return peak;
}

} // namespace

SetpointSchedule buildSetpointSchedule(const RobotModel &model, const TrialPlan &plan,
                                       const Eigen::VectorXd &q0, const ReturnMoveLimits &limits)
{
    const int n = int(q0.size());
    const double ts = plan.desired.samplePeriod;
    const int samples = plan.samples();
    const Eigen::VectorXd q1 = plan.desired.q.col(0);
    const Eigen::VectorXd dq = q1 - q0;
    // Peak speed of the quintic 10 s^3 - 15 s^4 + 6 s^5 is 15/8 |dq| / D.
    double duration =
        std::max(limits.minDuration, 1.875 * dq.cwiseAbs().maxCoeff() / limits.maxSpeed);
    // Inertial torque falls with 1/D^2; gravity does not, hence a few rounds.
    for (int round = 0; round < 8 && limits.torqueFraction > 0; ++round) {
        const double ratio = peakTorqueRatio(model, plan, q0, dq, duration, ts);
        if (ratio <= limits.torqueFraction)
            break;
        duration *= 1.1 * std::sqrt(ratio / limits.torqueFraction);
    }
    const int moveSteps = std::max(1, int(std::ceil(duration / ts - 1e-9)));
    const int holdSteps = std::max(0, int(std::lround(limits.hold / ts)));
    const int finalSteps = std::max(0, limits.finalHold);
    const int total = moveSteps + holdSteps + samples + finalSteps;

    SetpointSchedule s;
    s.q.resize(n, total);
    s.tau.resize(n, total);
    s.sample.fill(-1, total);
    const Eigen::VectorXd holdTorque = gravity(model, q1, plan.feedforwardParameters);
    int c = 0;
    const double d = moveSteps * ts;
    for (int i = 1; i <= moveSteps; ++i, ++c) {
        const Quintic x = quintic(double(i) / moveSteps);
        s.q.col(c) = q0 + x.p * dq;
        s.tau.col(c) = feedforward(model, s.q.col(c), x.v / d * dq, x.a / (d * d) * dq,
                                   plan.feedforwardParameters);
    }
    for (int i = 0; i < holdSteps; ++i, ++c) {
        s.q.col(c) = q1;
        s.tau.col(c) = holdTorque;
    }
    for (int k = 0; k < samples; ++k, ++c) {
        s.q.col(c) = plan.desired.q.col(k);
        s.tau.col(c) = plan.feedforward.col(k);
        s.sample[c] = k;
    }
    for (int i = 0; i < finalSteps; ++i, ++c) {
        s.q.col(c) = plan.desired.q.col(samples - 1);
        s.tau.col(c) = plan.feedforward.col(samples - 1);
    }
    return s;
}

} // namespace learnid
