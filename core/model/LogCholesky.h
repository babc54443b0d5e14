#pragma once

#include "model/PhysicalConsistency.h"

namespace learnid {

/// The log-Cholesky parameters of one link (Rucker and Wensing, "Smooth parameterization of
/// rigid-body inertia", IEEE RA-L 2022): theta (10) = [alpha, d1, d2, d3, s12, s23, s13, t1,
/// t2, t3] with
///   U = e^alpha [[e^d1, s12, s13, t1], [0, e^d2, s23, t2], [0, 0, e^d3, t3], [0, 0, 0, 1]]
/// and the pseudo-inertia J = U U^T. Every finite theta gives a strictly consistent link (J
/// positive definite), and every such link has exactly one theta: a smooth, unconstrained
/// coordinate for estimation. Units: alpha = log sqrt(m [kg]), d dimensionless, s and t [m].

/// pi10 (see Vector10d) of theta (10). Throws Error unless theta has 10 finite entries.
Vector10d inertialFromLogCholesky(const Eigen::Ref<const Eigen::VectorXd> &theta);
/// The same, and jacobian(i, k) = d pi_i / d theta_k (analytic: dJ = dU U^T + U dU^T, mapped
/// to pi by inertialFromPseudoInertia(), which is linear).
Vector10d inertialFromLogCholesky(const Eigen::Ref<const Eigen::VectorXd> &theta,
                                  Matrix10d &jacobian);

/// The curvature of w . pi(theta): sum_i weights_i d2 pi_i / dtheta dtheta^T (10 x 10, weights
/// 10), the second-order term of a least-squares Hessian in theta. Throws Error unless theta and
/// weights have 10 finite entries.
Matrix10d logCholeskyCurvature(const Eigen::Ref<const Eigen::VectorXd> &theta,
                               const Eigen::Ref<const Eigen::VectorXd> &weights);

/// theta of a strictly consistent pi10 (J = U U^T, U upper triangular with positive diagonal:
/// the Cholesky factor of J with rows and columns reversed). Throws Error when pi10 does not
/// have 10 finite entries or J is not positive definite (the message gives m and lambda_min).
Vector10d logCholeskyFromInertial(const Eigen::Ref<const Eigen::VectorXd> &pi10);

} // namespace learnid
