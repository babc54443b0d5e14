#pragma once
// Trial plans for the master's tests: a slow sinusoid on each joint from rest at q0.

#include "model/ModelFactory.h"
#include "types/Trial.h"

#include <cmath>

namespace learnid::test {

inline TrialPlan testPlan(int samples, const Eigen::Vector2d &q0 = Eigen::Vector2d(0.3, 1.2))
{
    TrialPlan plan;
    plan.desired.samplePeriod = 0.002;
    plan.desired.q.resize(2, samples);
    plan.desired.qd.setZero(2, samples);
    plan.desired.qdd.setZero(2, samples);
    for (int k = 0; k < samples; ++k) {
        const double s = std::sin(2.0 * M_PI * k / double(samples));
        plan.desired.q.col(k) = q0 + Eigen::Vector2d(0.05 * s, -0.04 * s);
    }
    plan.feedforward.setZero(2, samples);
    for (int k = 0; k < samples; ++k)
        plan.feedforward.col(k) = Eigen::Vector2d(1.5 + 0.001 * k, -0.75);
    plan.feedforwardParameters = Eigen::Vector3d(40, 20, 30);
    plan.torqueLimit = Eigen::Vector2d(8.0, 4.0);
    plan.maxTrackingError = 1.0 * M_PI / 180.0;
    plan.motionDuration = (samples - 1) * plan.desired.samplePeriod;
    return plan;
}

inline std::shared_ptr<const RobotModel> testModel()
{
    return makeRobotModel(QStringLiteral("paper-2link"));
}

} // namespace learnid::test
