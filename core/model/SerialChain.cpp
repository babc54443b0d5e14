#include "model/SerialChain.h"

namespace learnid {

namespace {

InertialParameters pack(double mass, const Eigen::Vector3d &h, const Eigen::Matrix3d &i)
{
    InertialParameters pi;
    pi << mass, h, i(0, 0), i(0, 1), i(1, 1), i(0, 2), i(1, 2), i(2, 2);
    return pi;
}

} // namespace

InertialParameters inertialParameters(double mass, const Eigen::Vector3d &c,
                                      const Eigen::Matrix3d &inertiaAtCom)
{
    // Parallel axis theorem from the centre of mass to the frame origin.
    const Eigen::Matrix3d shift =
        mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    return pack(mass, mass * c, inertiaAtCom + shift);
}

Eigen::Matrix3d rotationalInertia(const InertialParameters &pi)
{
    Eigen::Matrix3d i;
    i << pi[4], pi[5], pi[7], //
        pi[5], pi[6], pi[8],  //
        pi[7], pi[8], pi[9];
    return i;
}

InertialParameters transformedInertial(const InertialParameters &pi, const Eigen::Isometry3d &pose)
{
    // Move the reference point to the new origin d without dividing by the mass (a massless
    // or, in an estimate, negative-mass body is still a linear combination):
    //   I' = I + (m |d|^2 - 2 d.h) E + h d^T + d h^T - m d d^T,   h' = h - m d,
    // then rotate into the new axes.
    const double m = pi[0];
    const Eigen::Vector3d h = pi.segment<3>(1);
    const Eigen::Vector3d d = pose.translation();
    const Eigen::Matrix3d r = pose.linear();
    const Eigen::Matrix3d moved =
        rotationalInertia(pi) +
        (m * d.squaredNorm() - 2.0 * d.dot(h)) * Eigen::Matrix3d::Identity() + h * d.transpose() +
        d * h.transpose() - m * d * d.transpose();
    return pack(m, r.transpose() * (h - m * d), r.transpose() * moved * r);
}

} // namespace learnid
