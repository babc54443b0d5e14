#pragma once

// The geometric prior of plausibleEstimate() (PlausibleEstimate.h) as least-squares residuals
// of a link's log-Cholesky parameters theta (LogCholesky.h), templated for Ceres' automatic
// derivatives. Internal to core/model; public for its tests.

#include <Eigen/Core>
#include <cmath>

namespace learnid::detail {

/// sign(y) sqrt(e^y - 1 - y): the signed root of the Bregman divergence of -log between x and 1
/// at y = ln x (x - 1 - ln x). Analytic in y (e^y - 1 - y = y^2 q(y), q > 0), so a residual
/// whose square is that divergence, smooth through its minimum at y = 0. A series below
/// |y| = 1e-3 avoids the cancellation of e^y - 1 - y.
template <typename T> T bregmanRoot(const T &y)
{
    using std::abs;
    using std::expm1;
    using std::sqrt;
    T q;
    if (abs(y) < T(1e-3))
        q = T(0.5) + y * (T(1.0 / 6.0) + y * (T(1.0 / 24.0) + y * (T(1.0 / 120.0) + y / T(720.0))));
    else
        q = (expm1(y) - y) / (y * y);
    return y * sqrt(q);
}

/// U of theta (J = U U^T), LogCholesky.h's layout.
template <typename T> Eigen::Matrix<T, 4, 4> logCholeskyFactor(const T *theta)
{
    using std::exp;
    const T s = exp(theta[0]);
    Eigen::Matrix<T, 4, 4> u;
    u << s * exp(theta[1]), s * theta[4], s * theta[6], s * theta[7], //
        T(0.0), s * exp(theta[2]), s * theta[5], s * theta[8],        //
        T(0.0), T(0.0), s * exp(theta[3]), s * theta[9],              //
        T(0.0), T(0.0), T(0.0), s;
    return u;
}

/// The log-det (Bregman, entropic) divergence of a link's pseudo-inertia J from the prior's J0,
/// D(J, J0) = tr(J0^-1 J) - ln det(J0^-1 J) - 4 (Lee, Wensing and Park, IEEE T-RO 2020), as 10
/// residuals whose squares sum to weight * D. With J = U U^T and J0 = U0 U0^T, V = U0^-1 U is
/// upper triangular, tr(J0^-1 J) = |V|_F^2 and ln det = 2 sum ln V_ii, so
///   D = sum_{i<j} V_ij^2 + sum_i (V_ii^2 - 1 - 2 ln V_ii)
/// and ln V_ii = ln U_ii - ln U0_ii is linear in theta. D is 0 at J0, invariant under a change of
/// the link frame or of units, and grows without bound as J approaches singular (a point mass,
/// a needle, a plate) or infinite.
struct LogDetDivergence
{
    Eigen::Matrix4d priorFactorInverse; ///< U0^-1
    Eigen::Vector4d priorLogDiagonal;   ///< ln U0_ii
    double rootWeight = 1.0;            ///< sqrt(weight)

    /// Throws Error unless priorTheta has 10 finite entries and weight >= 0.
    LogDetDivergence(const Eigen::Matrix<double, 10, 1> &priorTheta, double weight);

    template <typename T> bool operator()(const T *theta, T *residual) const
    {
        const Eigen::Matrix<T, 4, 4> v = priorFactorInverse.cast<T>() * logCholeskyFactor(theta);
        const T w(rootWeight);
        residual[0] = w * v(0, 1);
        residual[1] = w * v(0, 2);
        residual[2] = w * v(0, 3);
        residual[3] = w * v(1, 2);
        residual[4] = w * v(1, 3);
        residual[5] = w * v(2, 3);
        for (int i = 0; i < 4; ++i) {
            const T logU = i < 3 ? theta[0] + theta[1 + i] : theta[0];
            residual[6 + i] = w * bregmanRoot(T(2.0) * (logU - T(priorLogDiagonal[i])));
        }
        return true;
    }
};

/// A bounding ellipsoid's inequality tr(Q J) > 0 (BoundingVolume.h) kept by the Bregman
/// divergence of -log between t = tr(Q J) and the prior's t0 > 0: one residual whose square is
/// weight * (t/t0 - 1 - ln(t/t0)). It is the log-det divergence of the 1 x 1 block that the
/// ellipsoid adds to J (J and t together positive: Wensing, Kim and Slotine 2018), so a body
/// approaching the volume's boundary costs without bound, as one approaching a needle does.
/// Infeasible theta (t <= 0) is refused (the solver then takes a shorter step).
struct VolumeDivergence
{
    Eigen::Matrix4d q; ///< BoundingEllipsoid::constraintMatrix()
    double priorShare; ///< t0 > 0
    double rootWeight; ///< sqrt(weight)

    template <typename T> bool operator()(const T *theta, T *residual) const
    {
        using std::log;
        const Eigen::Matrix<T, 4, 4> u = logCholeskyFactor(theta);
        const T t = (q.cast<T>().cwiseProduct(u * u.transpose())).sum();
        if (!(t > T(0.0)))
            return false;
        residual[0] = T(rootWeight) * bregmanRoot(log(t / T(priorShare)));
        return true;
    }
};

/// D(J, J0) of two pseudo-inertias (4 x 4, positive definite) computed directly, for tests and
/// reports: tr(J0^-1 J) - ln det(J0^-1 J) - 4.
double logDetDivergence(const Eigen::Matrix4d &j, const Eigen::Matrix4d &j0);

} // namespace learnid::detail
