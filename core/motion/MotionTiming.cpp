#include "motion/MotionTiming.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

JointTrajectory sampleMotion(int dof, const MotionTiming &timing, const MotionState &state)
{
    if (!(timing.samplePeriod > 0.0) || !(timing.motionDuration > 0.0) || timing.restBefore < 0.0 ||
        timing.restAfter < 0.0 ||
        !(timing.sampleOffset >= 0.0 && timing.sampleOffset < timing.samplePeriod)) {
        throw Error(QCoreApplication::translate(
            "CartesianLine", "invalid timing: sample period and duration must be positive, "
                             "rests non-negative, the sample offset within the period"));
    }
    const double total = timing.restBefore + timing.motionDuration + timing.restAfter;
    const int n = int(std::floor(total / timing.samplePeriod + 1e-9)) + 1;

    JointTrajectory traj;
    traj.samplePeriod = timing.samplePeriod;
    traj.q.resize(dof, n);
    traj.qd.resize(dof, n);
    traj.qdd.resize(dof, n);
    double previousT = -1.0;
    for (int k = 0; k < n; ++k) {
        const double t = k * timing.samplePeriod + timing.sampleOffset - timing.restBefore;
        const double clamped = std::clamp(t, 0.0, timing.motionDuration);
        if (clamped == previousT) {
            // At rest: the same point as the previous sample (its state, computed again from
            // the same inputs, would be the same numbers).
            traj.q.col(k) = traj.q.col(k - 1);
        } else {
            state(clamped, traj.q.col(k), traj.qd.col(k), traj.qdd.col(k));
        }
        previousT = clamped;
        // At rest the time scaling is exactly zero; clamping t makes that so without rounding.
        if (!(t > 0.0 && t < timing.motionDuration)) {
            traj.qd.col(k).setZero();
            traj.qdd.col(k).setZero();
        }
    }
    return traj;
}

} // namespace learnid
