#include "model/CadPrior.h"

#include "model/PhysicalConsistency.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

constexpr double eigenvalueTolerance = 1e-12; ///< relative to a link's largest
constexpr double eigenvalueFloor = 1e-6;      ///< relative to a link's largest, and absolute

} // namespace

Eigen::VectorXd realBodyPrior(const Eigen::VectorXd &cad, int links,
                              const std::vector<int> &nonnegative)
{
    Eigen::VectorXd prior = cad;
    for (const int i : nonnegative)
        prior[i] = std::max(prior[i], 0.0);
    for (const LinkConsistency &l : checkConsistency(cad, links, eigenvalueTolerance)) {
        if (l.consistent && !l.degenerate)
            continue;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(
            pseudoInertia(cad.segment<10>(10 * l.link)));
        const double floor = eigenvalueFloor * std::max(eig.eigenvalues().maxCoeff(), 1.0);
        const Eigen::Vector4d values = eig.eigenvalues().cwiseMax(floor);
        prior.segment<10>(10 * l.link) = inertialFromPseudoInertia(
            eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose());
    }
    return prior;
}

Eigen::VectorXd priorScale(const Eigen::VectorXd &prior, int links)
{
    Eigen::VectorXd scale(prior.size());
    for (Eigen::Index i = 0; i < prior.size(); ++i) {
        const Eigen::Index block = i < 10 * links ? (i / 10) * 10 : i;
        const Eigen::Index size = i < 10 * links ? 10 : 1;
        const double floor = 1e-3 * prior.segment(block, size).cwiseAbs().maxCoeff() + 1e-9;
        scale[i] = 1.0 / std::max(std::abs(prior[i]), floor);
    }
    return scale;
}

} // namespace learnid
