#pragma once

#include "model/PhysicalConsistency.h"

#include <Eigen/Core>
#include <QString>

namespace learnid {

/// Where a link's bounding volume comes from (docs/robots.md §6).
enum class VolumeSource {
    Geometry,   ///< the URDF's collision or visual shapes of the link (and links fixed to it)
    CadInertia, ///< no usable geometry: the CAD body's inertia ellipsoid, enlarged by a margin
};

/// The region a link's mass must lie in: the ellipsoid {x : |A (x - centre)| <= 1} in the
/// link's frame [m] (A = axes^-1). Used as the linear matrix inequality tr(Q J) >= 0 on the
/// link's pseudo-inertia J (pseudoInertia()): necessary for a mass density inside the ellipsoid
/// and, with J positive semidefinite, sufficient for one (Wensing, Kim and Slotine, "Linear
/// matrix inequalities for physically consistent inertial parameter identification", IEEE
/// RA-L 2018, Theorem 1).
struct BoundingEllipsoid
{
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< [m], link frame
    /// The semi-axes as columns [m] (an invertible 3 x 3 matrix R diag(a)): x = centre + axes u,
    /// |u| <= 1.
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    VolumeSource source = VolumeSource::Geometry;
    QString description; ///< what it was made from, for reports: "2 cylinders, 1 sphere"

    /// Q (4 x 4, symmetric) with [x; 1]^T Q [x; 1] = 1 - |A (x - centre)|^2, so that
    /// tr(Q J) = m - integral |A (x - centre)|^2 dm.
    Eigen::Matrix4d constraintMatrix() const;
    /// |A (x - centre)|^2: at most 1 inside.
    double normalisedDistance(const Eigen::Vector3d &x) const;
    /// tr(Q J) / m for a link's standard parameters pi10 (m > 0): 1 - the mean of
    /// |A (x - centre)|^2 over the mass. Not negative when the mass can lie inside.
    double fitShare(const Eigen::Ref<const Eigen::VectorXd> &pi10) const;
};

/// The smallest ellipsoid around the axis-aligned box [lower, upper] (link frame, [m]): the
/// box's half sizes times sqrt(3), centred. Throws Error unless upper > lower in every axis
/// (a flat box is given a thickness of 1e-3 of its largest side first).
BoundingEllipsoid ellipsoidAroundBox(const Eigen::Vector3d &lower, const Eigen::Vector3d &upper);

/// The ellipsoid of a link from its CAD inertia when it has no geometry: the solid ellipsoid of
/// uniform density with the same mass, centre of mass and second moments about it (semi-axes
/// sqrt(5 sigma_i), sigma_i the eigenvalues of the second-moment matrix about the centre of
/// mass), scaled by `margin` (> 1) about the centre of mass, each semi-axis at least
/// `minimumAxis` [m] so that a point-mass CAD link still gets a volume. Throws Error when the
/// mass is not positive or margin <= 1.
BoundingEllipsoid ellipsoidFromInertia(const Eigen::Ref<const Eigen::VectorXd> &pi10, double margin,
                                       double minimumAxis);

/// The margin ellipsoidFromInertia() is used with by default: 2 (each semi-axis twice the
/// CAD body's, eight times its volume); the CAD model's masses and centres of mass can be off by
/// tens of percent, its shape rarely by a factor of two.
constexpr double cadVolumeMargin = 2.0;
/// The smallest semi-axis given to a CAD-derived ellipsoid [m].
constexpr double cadVolumeMinimumAxis = 0.02;

} // namespace learnid
