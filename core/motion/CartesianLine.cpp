#include "motion/CartesianLine.h"

#include "model/Error.h"

#include <Eigen/LU>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

Eigen::Vector2d CartesianLine::direction() const
{
    const double a = directionDeg * M_PI / 180.0;
    return {std::cos(a), std::sin(a)};
}

JointState lineStateAt(const Kinematics &kinematics, const CartesianLine &line, double T, double t,
                       const Eigen::VectorXd &near)
{
    const double u = std::clamp(t / T, 0.0, 1.0);
    const double u2 = u * u;
    const double s = u2 * u * (10.0 - 15.0 * u + 6.0 * u2);
    const double sd = 30.0 * u2 * (1.0 - 2.0 * u + u2) / T;
    const double sdd = 60.0 * u * (1.0 - 3.0 * u + 2.0 * u2) / (T * T);

    const Eigen::Vector2d dir = line.direction();
    const Eigen::VectorXd x = line.start + s * line.length * dir;
    const Eigen::VectorXd xd = sd * line.length * dir;
    const Eigen::VectorXd xdd = sdd * line.length * dir;

    JointState state;
    state.q = kinematics.inverse(x, near);
    const Eigen::MatrixXd j = kinematics.jacobian(state.q);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(j);
    state.qd = lu.solve(xd);
    // xdd = J qdd + Jdot qd
    state.qdd = lu.solve(xdd - kinematics.jacobianDotTimesQd(state.q, state.qd));
    return state;
}

JointTrajectory planLine(const Kinematics &kinematics, const CartesianLine &line,
                         const MotionTiming &timing)
{
    if (!(timing.samplePeriod > 0.0) || !(timing.motionDuration > 0.0) || timing.restBefore < 0.0
        || timing.restAfter < 0.0) {
        throw Error(QCoreApplication::translate(
            "CartesianLine", "invalid timing: sample period and duration must be positive, "
                             "rests non-negative"));
    }
    const double total = timing.restBefore + timing.motionDuration + timing.restAfter;
    const int n = int(std::floor(total / timing.samplePeriod + 1e-9)) + 1;
    const int dof = kinematics.dof();

    JointTrajectory traj;
    traj.samplePeriod = timing.samplePeriod;
    traj.q.resize(dof, n);
    traj.qd.resize(dof, n);
    traj.qdd.resize(dof, n);

    Eigen::VectorXd near;
    for (int k = 0; k < n; ++k) {
        const double t = k * timing.samplePeriod - timing.restBefore;
        const JointState st = lineStateAt(kinematics, line, timing.motionDuration,
                                          std::clamp(t, 0.0, timing.motionDuration), near);
        traj.q.col(k) = st.q;
        // At rest the time scaling is exactly zero; clamping t makes that so without rounding.
        const bool moving = t > 0.0 && t < timing.motionDuration;
        traj.qd.col(k) = moving ? st.qd : Eigen::VectorXd::Zero(dof);
        traj.qdd.col(k) = moving ? st.qdd : Eigen::VectorXd::Zero(dof);
        near = st.q;
    }
    return traj;
}

} // namespace learnid
