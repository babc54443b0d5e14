#include "model/LogCholesky.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <array>
#include <cmath>

namespace learnid {

namespace {

void requireTenFinite(const Eigen::Ref<const Eigen::VectorXd> &v, const char *name)
{
    if (v.size() != 10)
        throw Error(
            QCoreApplication::translate("PhysicalConsistency", "%1 has %2 entries; a link has 10.")
                .arg(QLatin1String(name))
                .arg(v.size()));
    for (int i = 0; i < 10; ++i)
        if (!std::isfinite(v[i]))
            throw Error(QCoreApplication::translate("PhysicalConsistency", "%1[%2] is not finite.")
                            .arg(QLatin1String(name))
                            .arg(i));
}

// U / e^alpha: the unit-scaled upper factor of theta.
Eigen::Matrix4d scaledFactor(const Eigen::Ref<const Eigen::VectorXd> &theta)
{
    Eigen::Matrix4d u;
    u << std::exp(theta[1]), theta[4], theta[6], theta[7], //
        0.0, std::exp(theta[2]), theta[5], theta[8],       //
        0.0, 0.0, std::exp(theta[3]), theta[9],            //
        0.0, 0.0, 0.0, 1.0;
    return u;
}

using FactorDerivatives = std::array<Eigen::Matrix4d, 10>;

// U of theta, and du[k] = dU / dtheta_k (du[0] = U: every entry carries e^alpha).
Eigen::Matrix4d factorAndDerivatives(const Eigen::Ref<const Eigen::VectorXd> &theta,
                                     FactorDerivatives &du)
{
    const double scale = std::exp(theta[0]);
    const Eigen::Matrix4d u = scale * scaledFactor(theta);
    // The entry of U each of theta[1..9] sits at: e^d1, e^d2, e^d3, s12, s23, s13, t1, t2, t3.
    static const int row[10] = {0, 0, 1, 2, 0, 1, 0, 0, 1, 2};
    static const int col[10] = {0, 0, 1, 2, 1, 2, 2, 3, 3, 3};
    du[0] = u;
    for (int k = 1; k < 10; ++k) {
        du[size_t(k)].setZero();
        du[size_t(k)](row[k], col[k]) = k <= 3 ? u(row[k], col[k]) : scale; // (e^d)' = e^d
    }
    return u;
}

} // namespace

Vector10d inertialFromLogCholesky(const Eigen::Ref<const Eigen::VectorXd> &theta)
{
    requireTenFinite(theta, "theta");
    const Eigen::Matrix4d u = std::exp(theta[0]) * scaledFactor(theta);
    return inertialFromPseudoInertia(u * u.transpose());
}

Vector10d inertialFromLogCholesky(const Eigen::Ref<const Eigen::VectorXd> &theta,
                                  Matrix10d &jacobian)
{
    requireTenFinite(theta, "theta");
    FactorDerivatives du;
    const Eigen::Matrix4d u = factorAndDerivatives(theta, du);
    for (int k = 0; k < 10; ++k) {
        const Eigen::Matrix4d duUt = du[size_t(k)] * u.transpose();
        jacobian.col(k) = inertialFromPseudoInertia(duUt + duUt.transpose());
    }
    return inertialFromPseudoInertia(u * u.transpose());
}

Matrix10d logCholeskyCurvature(const Eigen::Ref<const Eigen::VectorXd> &theta,
                               const Eigen::Ref<const Eigen::VectorXd> &weights)
{
    requireTenFinite(theta, "theta");
    requireTenFinite(weights, "weights");
    FactorDerivatives du;
    const Eigen::Matrix4d u = factorAndDerivatives(theta, du);
    // d2J/da db = d2U U^T + U d2U^T + dU_a dU_b^T + dU_b dU_a^T, where d2U/da db is dU/db
    // for a = alpha (every entry carries e^alpha), dU/dd_i for a = b = d_i, and 0 otherwise.
    Matrix10d curvature;
    for (int a = 0; a < 10; ++a) {
        for (int b = a; b < 10; ++b) {
            Eigen::Matrix4d d2j = du[size_t(a)] * du[size_t(b)].transpose();
            d2j += d2j.transpose().eval();
            if (a == 0 || (a == b && a <= 3)) {
                const Eigen::Matrix4d d2uUt = du[size_t(b)] * u.transpose();
                d2j += d2uUt + d2uUt.transpose();
            }
            curvature(a, b) = curvature(b, a) = weights.dot(inertialFromPseudoInertia(d2j));
        }
    }
    return curvature;
}

Vector10d logCholeskyFromInertial(const Eigen::Ref<const Eigen::VectorXd> &pi10)
{
    requireTenFinite(pi10, "pi");
    const Eigen::Matrix4d j = pseudoInertia(pi10);
    // J = U U^T with U upper: the Cholesky factor L of the reversed J (P J P, P the exchange
    // matrix) gives U = P L P.
    const Eigen::LLT<Eigen::Matrix4d> llt(j.reverse());
    const Eigen::Matrix4d u = Eigen::Matrix4d(llt.matrixL()).reverse();
    if (llt.info() != Eigen::Success || !(u.diagonal().array() > 0.0).all()) {
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(j, Eigen::EigenvaluesOnly);
        throw Error(QCoreApplication::translate(
                        "PhysicalConsistency",
                        "The link is not strictly physically consistent (mass %1 kg, smallest "
                        "pseudo-inertia eigenvalue %2); it has no log-Cholesky parameters.")
                        .arg(pi10[0])
                        .arg(eigen.eigenvalues()[0]));
    }
    const Eigen::Matrix4d unit = u / u(3, 3);
    Vector10d theta;
    theta << std::log(u(3, 3)), std::log(unit(0, 0)), std::log(unit(1, 1)), std::log(unit(2, 2)),
        unit(0, 1), unit(1, 2), unit(0, 2), unit(0, 3), unit(1, 3), unit(2, 3);
    return theta;
}

} // namespace learnid
