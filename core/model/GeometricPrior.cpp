#include "model/GeometricPrior.h"

#include "model/Error.h"
#include "model/LogCholesky.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <QCoreApplication>

namespace learnid::detail {

LogDetDivergence::LogDetDivergence(const Eigen::Matrix<double, 10, 1> &priorTheta, double weight)
{
    if (!priorTheta.allFinite() || !(weight >= 0.0) || !std::isfinite(weight))
        throw Error(QCoreApplication::translate("PlausibleEstimate",
                                                "The log-det divergence needs a finite prior and "
                                                "a weight that is not negative."));
    const Eigen::Matrix4d u0 = logCholeskyFactor(priorTheta.data());
    priorFactorInverse = u0.triangularView<Eigen::Upper>().solve(Eigen::Matrix4d::Identity());
    priorLogDiagonal << priorTheta[0] + priorTheta[1], priorTheta[0] + priorTheta[2],
        priorTheta[0] + priorTheta[3], priorTheta[0];
    rootWeight = std::sqrt(weight);
}

double logDetDivergence(const Eigen::Matrix4d &j, const Eigen::Matrix4d &j0)
{
    const Eigen::LLT<Eigen::Matrix4d> l0(j0), l(j);
    if (l0.info() != Eigen::Success || l.info() != Eigen::Success)
        throw Error(QCoreApplication::translate("PlausibleEstimate",
                                                "The log-det divergence needs two positive "
                                                "definite pseudo-inertias."));
    const Eigen::Matrix4d m = l0.solve(j);
    const double logDet = 2.0 * (Eigen::Matrix4d(l.matrixL()).diagonal().array().log().sum() -
                                 Eigen::Matrix4d(l0.matrixL()).diagonal().array().log().sum());
    return m.trace() - logDet - 4.0;
}

} // namespace learnid::detail
