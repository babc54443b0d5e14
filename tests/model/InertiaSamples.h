#pragma once

// Test support for the physical-consistency tests: bodies whose inertia is known in closed form.

#include "model/PhysicalConsistency.h"

#include <Eigen/Dense>

namespace learnid::test {

struct Box
{
    double mass;
    Eigen::Vector3d size;   // edge lengths along the box's own axes [m]
    Eigen::Matrix3d axes;   // box axes in the link frame (columns)
    Eigen::Vector3d centre; // centre of mass in the link frame [m]
};

inline Box sampleBox()
{
    const Eigen::Matrix3d axes =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
    return {3.0, {0.4, 0.2, 0.1}, axes, {0.3, -0.1, 0.05}};
}

// pi10 from the textbook inertia of a box, I_c = m/12 diag(b^2 + c^2, ...), moved to the origin
// by the parallel-axis theorem.
inline Vector10d inertialOf(double m, const Eigen::Matrix3d &inertiaAtCentre,
                            const Eigen::Vector3d &c)
{
    const Eigen::Matrix3d i =
        inertiaAtCentre + m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    Vector10d pi;
    pi << m, m * c.x(), m * c.y(), m * c.z(), i(0, 0), i(0, 1), i(1, 1), i(0, 2), i(1, 2), i(2, 2);
    return pi;
}

inline Vector10d boxInertial(const Box &box)
{
    const Eigen::Vector3d s2 = box.size.cwiseAbs2();
    const Eigen::Vector3d diag(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
    const Eigen::Matrix3d ic =
        box.axes * (box.mass / 12.0 * diag).asDiagonal() * box.axes.transpose();
    return inertialOf(box.mass, ic, box.centre);
}

// The second moments of the box, integral of [r; 1][r; 1]^T dm, in closed form: a uniform
// interval of length a has variance a^2 / 12.
inline Eigen::Matrix4d boxSecondMoments(const Box &box)
{
    const Eigen::Matrix3d spread =
        box.axes * (box.mass / 12.0 * box.size.cwiseAbs2()).asDiagonal() * box.axes.transpose();
    Eigen::Matrix4d j;
    j.topLeftCorner<3, 3>() = spread + box.mass * box.centre * box.centre.transpose();
    j.topRightCorner<3, 1>() = box.mass * box.centre;
    j.bottomLeftCorner<1, 3>() = box.mass * box.centre.transpose();
    j(3, 3) = box.mass;
    return j;
}

// A link's J moved by eps along its eigenvector of least eigenvalue, as pi10.
inline Vector10d shiftedLeastEigenvalue(const Vector10d &pi, double eps)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(pseudoInertia(pi));
    const Eigen::Vector4d v = eigen.eigenvectors().col(0);
    return inertialFromPseudoInertia(pseudoInertia(pi) + eps * v * v.transpose());
}

} // namespace learnid::test
