#include "model/BoundingVolume.h"

#include "model/Error.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(BoundingVolume)
};

// A^T A of the ellipsoid, A = axes^-1.
Eigen::Matrix3d shapeMatrix(const BoundingEllipsoid &e)
{
    const Eigen::Matrix3d a = e.axes.inverse();
    return a.transpose() * a;
}

} // namespace

Eigen::Matrix4d BoundingEllipsoid::constraintMatrix() const
{
    const Eigen::Matrix3d s = shapeMatrix(*this);
    Eigen::Matrix4d q;
    q.topLeftCorner<3, 3>() = -s;
    q.topRightCorner<3, 1>() = s * centre;
    q.bottomLeftCorner<1, 3>() = (s * centre).transpose();
    q(3, 3) = 1.0 - centre.dot(s * centre);
    return q;
}

double BoundingEllipsoid::normalisedDistance(const Eigen::Vector3d &x) const
{
    const Eigen::Vector3d d = x - centre;
    return d.dot(shapeMatrix(*this) * d);
}

double BoundingEllipsoid::fitShare(const Eigen::Ref<const Eigen::VectorXd> &pi10) const
{
    const Eigen::Matrix4d j = pseudoInertia(pi10);
    return (constraintMatrix().cwiseProduct(j)).sum() / j(3, 3);
}

BoundingEllipsoid ellipsoidAroundBox(const Eigen::Vector3d &lower, const Eigen::Vector3d &upper)
{
    if (!lower.allFinite() || !upper.allFinite() || (upper - lower).minCoeff() < 0.0 ||
        (upper - lower).maxCoeff() <= 0.0)
        throw Error(Text::tr("A bounding box needs its upper corner above its lower one."));
    const Eigen::Vector3d half =
        (0.5 * (upper - lower)).cwiseMax(0.5e-3 * (upper - lower).maxCoeff());
    BoundingEllipsoid e;
    e.centre = 0.5 * (lower + upper);
    // The box's corners (+-h) lie on the ellipsoid with semi-axes sqrt(3) h: sum h^2 / (3 h^2) = 1.
    e.axes = (std::sqrt(3.0) * half).asDiagonal();
    return e;
}

BoundingEllipsoid ellipsoidFromInertia(const Eigen::Ref<const Eigen::VectorXd> &pi10, double margin,
                                       double minimumAxis)
{
    if (pi10.size() != 10 || !pi10.allFinite() || !(pi10[0] > 0.0))
        throw Error(Text::tr("A link without positive mass has no inertia ellipsoid."));
    if (!(margin > 1.0) || !std::isfinite(margin) || !(minimumAxis >= 0.0))
        throw Error(Text::tr("The inertia ellipsoid's margin must be above 1."));
    const double m = pi10[0];
    const Eigen::Vector3d c = pi10.segment<3>(1) / m;
    // Second moments about the centre of mass: Sigma_c = Sigma - m c c^T.
    const Eigen::Matrix4d j = pseudoInertia(pi10);
    const Eigen::Matrix3d sigma = j.topLeftCorner<3, 3>() - m * c * c.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(sigma);
    // A solid ellipsoid of semi-axes a_i has Sigma_c = m diag(a_i^2) / 5.
    const Eigen::Vector3d semi =
        (margin * (5.0 * eig.eigenvalues().cwiseMax(0.0) / m).cwiseSqrt()).cwiseMax(minimumAxis);
    BoundingEllipsoid e;
    e.centre = c;
    e.axes = eig.eigenvectors() * semi.asDiagonal();
    e.source = VolumeSource::CadInertia;
    return e;
}

} // namespace learnid
