#pragma once

// The geometric prior of plausibleEstimate() (PlausibleEstimate.h) as least-squares residuals
// of a link's standard parameters pi (10, PhysicalConsistency.h), templated for Ceres' automatic
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

/// The pseudo-inertia J of a link's standard parameters pi10 (PhysicalConsistency.h), for any
/// scalar type.
template <typename T> Eigen::Matrix<T, 4, 4> pseudoInertiaOf(const T *pi)
{
    const T half = T(0.5) * (pi[4] + pi[6] + pi[9]);
    Eigen::Matrix<T, 4, 4> j;
    j << half - pi[4], -pi[5], -pi[7], pi[1], //
        -pi[5], half - pi[6], -pi[8], pi[2],  //
        -pi[7], -pi[8], half - pi[9], pi[3],  //
        pi[1], pi[2], pi[3], pi[0];
    return j;
}

/// The upper triangular U with J = U U^T (the Cholesky factor of J with rows and columns
/// reversed), for any scalar type; false when J is not positive definite.
template <typename T> bool upperFactor(const Eigen::Matrix<T, 4, 4> &j, Eigen::Matrix<T, 4, 4> &u)
{
    using std::sqrt;
    u.setZero();
    for (int c = 3; c >= 0; --c) {
        T d = j(c, c);
        for (int k = c + 1; k < 4; ++k)
            d -= u(c, k) * u(c, k);
        if (!(d > T(0.0)))
            return false;
        u(c, c) = sqrt(d);
        for (int r = 0; r < c; ++r) {
            T x = j(r, c);
            for (int k = c + 1; k < 4; ++k)
                x -= u(r, k) * u(c, k);
            u(r, c) = x / u(c, c);
        }
    }
    return true;
}

/// The log-det (Bregman, entropic) divergence of a link's pseudo-inertia J from the prior's J0,
/// D(J, J0) = tr(J0^-1 J) - ln det(J0^-1 J) - 4 (Lee, Wensing and Park, IEEE T-RO 2020), as 10
/// residuals whose squares sum to weight * D. With J = U U^T and J0 = U0 U0^T (upperFactor()),
/// V = U0^-1 U is upper triangular, tr(J0^-1 J) = |V|_F^2 and ln det = 2 sum ln V_ii, so
///   D = sum_{i<j} V_ij^2 + sum_i (V_ii^2 - 1 - 2 ln V_ii).
/// D is convex in pi, 0 at J0, invariant under a change of
/// the link frame or of units, and grows without bound as J approaches singular (a point mass,
/// a needle, a plate) or infinite.
struct LogDetDivergence
{
    Eigen::Matrix4d priorFactorInverse; ///< U0^-1
    Eigen::Vector4d priorLogDiagonal;   ///< ln U0_ii
    double rootWeight = 1.0;            ///< sqrt(weight)

    /// Throws Error unless the prior link's J0 is positive definite and weight >= 0.
    LogDetDivergence(const Eigen::Matrix<double, 10, 1> &priorPi, double weight);

    template <typename T> bool operator()(const T *pi, T *residual) const
    {
        using std::log;
        Eigen::Matrix<T, 4, 4> u;
        if (!upperFactor(pseudoInertiaOf(pi), u))
            return false;
        const Eigen::Matrix<T, 4, 4> v = priorFactorInverse.cast<T>() * u;
        const T w(rootWeight);
        residual[0] = w * v(0, 1);
        residual[1] = w * v(0, 2);
        residual[2] = w * v(0, 3);
        residual[3] = w * v(1, 2);
        residual[4] = w * v(1, 3);
        residual[5] = w * v(2, 3);
        for (int i = 0; i < 4; ++i)
            residual[6 + i] = w * bregmanRoot(T(2.0) * (log(u(i, i)) - T(priorLogDiagonal[i])));
        return true;
    }
};

/// A bounding ellipsoid's inequality tr(Q J) > 0 (BoundingVolume.h) kept by the Bregman
/// divergence of -log between t = tr(Q J) and the prior's t0 > 0: one residual whose square is
/// weight * (t/t0 - 1 - ln(t/t0)). It is the log-det divergence of the 1 x 1 block that the
/// ellipsoid adds to J (J and t together positive: Wensing, Kim and Slotine 2018), so a body
/// approaching the volume's boundary costs without bound, as one approaching a needle does.
/// Infeasible pi (t <= 0) is refused (the solver then takes a shorter step).
struct VolumeDivergence
{
    Eigen::Matrix4d q; ///< BoundingEllipsoid::constraintMatrix()
    double priorShare; ///< t0 > 0
    double rootWeight; ///< sqrt(weight)

    template <typename T> bool operator()(const T *pi, T *residual) const
    {
        using std::log;
        const T t = (q.cast<T>().cwiseProduct(pseudoInertiaOf(pi))).sum();
        if (!(t > T(0.0)))
            return false;
        residual[0] = T(rootWeight) * bregmanRoot(log(t / T(priorShare)));
        return true;
    }
};

/// The plausibility rule (Plausibility.h) as two linear matrix inequalities on a link's second
/// moments about its centre of mass, Sigma_c = Sigma - h h^T / m (I_c = tr(Sigma_c) E - Sigma_c):
///  - moments: I_c - mu E >= 0 (every principal moment at least mu);
///  - shape: Sigma_c - kappa tr(Sigma_c) E >= 0 with kappa = eps / (2 + eps), which is
///    I1 + I2 >= (1 + eps) I3 (I1 + I2 - I3 = 2 sigma_min, I3 = tr(Sigma_c) - sigma_min).
/// Each is kept by the Bregman divergence of -ln det between the matrix M and the prior's M0:
/// one residual whose square is weight * (det M / det M0 - 1 - ln(det M / det M0)), without
/// bound as M approaches singular; pi where M is not positive definite is refused.
struct RuleBarrier
{
    bool shape = false;     ///< false: the moments' inequality; true: the shape's
    double bound = 0.0;     ///< mu [kg m^2], or kappa
    double priorLogDet = 0; ///< ln det M0
    double rootWeight = 1;  ///< sqrt(weight)

    template <typename T>
    static Eigen::Matrix<T, 3, 3> matrix(const T *pi, bool shape, double bound)
    {
        const Eigen::Matrix<T, 4, 4> j = pseudoInertiaOf(pi);
        const Eigen::Matrix<T, 3, 1> h = j.template topRightCorner<3, 1>();
        const Eigen::Matrix<T, 3, 3> sigma =
            j.template topLeftCorner<3, 3>() - h * h.transpose() / j(3, 3);
        const Eigen::Matrix<T, 3, 3> e = Eigen::Matrix<T, 3, 3>::Identity();
        if (shape)
            return sigma - T(bound) * sigma.trace() * e;
        return sigma.trace() * e - sigma - T(bound) * e;
    }

    template <typename T> bool operator()(const T *pi, T *residual) const
    {
        using std::log;
        const Eigen::Matrix<T, 3, 3> m = matrix(pi, shape, bound);
        // Positive definite by Sylvester's criterion: every leading minor positive.
        const T minor2 = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
        const T det = m.determinant();
        if (!(m(0, 0) > T(0.0)) || !(minor2 > T(0.0)) || !(det > T(0.0)))
            return false;
        residual[0] = T(rootWeight) * bregmanRoot(log(det) - T(priorLogDet));
        return true;
    }
};

/// D(J, J0) of two pseudo-inertias (4 x 4, positive definite) computed directly, for tests and
/// reports: tr(J0^-1 J) - ln det(J0^-1 J) - 4.
double logDetDivergence(const Eigen::Matrix4d &j, const Eigen::Matrix4d &j0);

} // namespace learnid::detail
