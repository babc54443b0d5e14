#include "model/GeometricPrior.h"

#include "model/Error.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <QCoreApplication>

namespace learnid::detail {

LogDetDivergence::LogDetDivergence(const Eigen::Matrix<double, 10, 1> &priorPi, double weight)
{
    Eigen::Matrix4d u0;
    if (!priorPi.allFinite() || !upperFactor(pseudoInertiaOf(priorPi.data()), u0) ||
        !(weight >= 0.0) || !std::isfinite(weight))
        throw Error(QCoreApplication::translate("PlausibleEstimate",
                                                "The log-det divergence needs a prior link that "
                                                "is strictly a real body and a weight that is not "
                                                "negative."));
    priorFactorInverse = u0.triangularView<Eigen::Upper>().solve(Eigen::Matrix4d::Identity());
    priorLogDiagonal = u0.diagonal().array().log();
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
