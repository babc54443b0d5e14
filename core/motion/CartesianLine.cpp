#include "motion/CartesianLine.h"

#include "model/Error.h"

#include <Eigen/LU>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

// lineStateInto() with the line's direction precomputed (planLine() calls it every sample).
void lineStateAlong(const Kinematics &kinematics, const CartesianLine &line,
                    const Eigen::Vector2d &dir, double T, double t,
                    const Eigen::Ref<const Eigen::VectorXd> &near, Eigen::Ref<Eigen::VectorXd> q,
                    Eigen::Ref<Eigen::VectorXd> qd, Eigen::Ref<Eigen::VectorXd> qdd)
{
    const double u = std::clamp(t / T, 0.0, 1.0);
    const double u2 = u * u;
    const double s = u2 * u * (10.0 - 15.0 * u + 6.0 * u2);
    const double sd = 30.0 * u2 * (1.0 - 2.0 * u + u2) / T;
    const double sdd = 60.0 * u * (1.0 - 3.0 * u + 2.0 * u2) / (T * T);

    const Eigen::Vector2d x = line.start + s * line.length * dir;
    const Eigen::Vector2d xd = sd * line.length * dir;
    const Eigen::Vector2d xdd = sdd * line.length * dir;
    kinematics.jointStateInto(x, xd, xdd, near, q, qd, qdd);
}

} // namespace

void lineStateInto(const Kinematics &kinematics, const CartesianLine &line, double T, double t,
                   const Eigen::Ref<const Eigen::VectorXd> &near, Eigen::Ref<Eigen::VectorXd> q,
                   Eigen::Ref<Eigen::VectorXd> qd, Eigen::Ref<Eigen::VectorXd> qdd)
{
    lineStateAlong(kinematics, line, line.direction(), T, t, near, q, qd, qdd);
}

JointState lineStateAt(const Kinematics &kinematics, const CartesianLine &line, double T, double t,
                       const Eigen::VectorXd &near)
{
    JointState state{Eigen::VectorXd(2), Eigen::VectorXd(2), Eigen::VectorXd(2)};
    lineStateInto(kinematics, line, T, t, near, state.q, state.qd, state.qdd);
    return state;
}

JointTrajectory planLine(const Kinematics &kinematics, const CartesianLine &line,
                         const MotionTiming &timing)
{
    if (kinematics.dof() != 2)
        throw Error(QCoreApplication::translate("CartesianLine", "a planar line needs 2 joints"));
    Eigen::Vector2d near = kinematics.inverse(line.start, Eigen::VectorXd());
    const Eigen::Vector2d dir = line.direction();
    return sampleMotion(2, timing,
                        [&](double t, Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                            Eigen::Ref<Eigen::VectorXd> qdd) {
                            lineStateAlong(kinematics, line, dir, timing.motionDuration, t, near, q,
                                           qd, qdd);
                            near = q;
                        });
}

} // namespace learnid
