#include "model/PhysicalConsistency.h"

#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

QString translated(const char *text)
{
    return QCoreApplication::translate("PhysicalConsistency", text);
}

void requireFinite(const Eigen::VectorXd &v, const char *name)
{
    for (Eigen::Index i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]))
            throw Error(translated("%1[%2] is not finite.").arg(QLatin1String(name)).arg(i));
}

} // namespace

Eigen::Matrix4d pseudoInertia(const Eigen::Ref<const Eigen::VectorXd> &pi10)
{
    if (pi10.size() != 10)
        throw Error(translated("pi has %1 entries; a link has 10.").arg(pi10.size()));
    Eigen::Matrix3d inertia;
    inertia << pi10[4], pi10[5], pi10[7], //
        pi10[5], pi10[6], pi10[8],        //
        pi10[7], pi10[8], pi10[9];
    Eigen::Matrix4d j;
    j.topLeftCorner<3, 3>() = 0.5 * inertia.trace() * Eigen::Matrix3d::Identity() - inertia;
    j.topRightCorner<3, 1>() = pi10.segment<3>(1);
    j.bottomLeftCorner<1, 3>() = pi10.segment<3>(1).transpose();
    j(3, 3) = pi10[0];
    return j;
}

Vector10d inertialFromPseudoInertia(const Eigen::Matrix4d &j)
{
    const Eigen::Matrix3d sigma = j.topLeftCorner<3, 3>().selfadjointView<Eigen::Upper>();
    // tr(Sigma) = tr(I) / 2, so I = tr(Sigma) E - Sigma.
    const Eigen::Matrix3d inertia = sigma.trace() * Eigen::Matrix3d::Identity() - sigma;
    Vector10d pi;
    pi << j(3, 3), j(0, 3), j(1, 3), j(2, 3), inertia(0, 0), inertia(0, 1), inertia(1, 1),
        inertia(0, 2), inertia(1, 2), inertia(2, 2);
    return pi;
}

std::vector<LinkConsistency> checkConsistency(const Eigen::VectorXd &standard, int links,
                                              double tolerance)
{
    if (links < 0 || standard.size() < 10 * Eigen::Index(links))
        throw Error(translated("The standard vector has %1 entries, too few for %2 links "
                               "(10 parameters each).")
                        .arg(standard.size())
                        .arg(links));
    if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
        throw Error(translated("The consistency tolerance is %1; it must be finite and >= 0.")
                        .arg(tolerance));
    requireFinite(standard, "standard");
    std::vector<LinkConsistency> verdicts;
    verdicts.reserve(size_t(links));
    for (int l = 0; l < links; ++l) {
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(
            pseudoInertia(standard.segment<10>(10 * l)), Eigen::EigenvaluesOnly);
        LinkConsistency v;
        v.link = l;
        v.mass = standard[10 * l];
        v.minEigenvalue = eigen.eigenvalues()[0];
        v.maxEigenvalue = eigen.eigenvalues()[3];
        const double margin = tolerance * std::max(v.maxEigenvalue, 0.0);
        v.consistent = v.mass > 0.0 && v.minEigenvalue >= -margin;
        v.degenerate = v.consistent && v.minEigenvalue <= margin;
        verdicts.push_back(v);
    }
    return verdicts;
}

std::vector<int> negativeJointTerms(const Eigen::VectorXd &standard,
                                    const std::vector<int> &nonnegativeIndices)
{
    std::vector<int> negative;
    for (const int i : nonnegativeIndices) {
        if (i < 0 || i >= standard.size())
            throw Error(translated("Nonnegative index %1 is outside the standard vector "
                                   "(%2 entries).")
                            .arg(i)
                            .arg(standard.size()));
        if (!std::isfinite(standard[i]))
            throw Error(translated("%1[%2] is not finite.").arg(QLatin1String("standard")).arg(i));
        if (standard[i] < 0.0)
            negative.push_back(i);
    }
    return negative;
}

} // namespace learnid
