// plausibleEstimate() of PlausibleEstimate.h: the problem checked, its weights, and the
// continuation over the prior's weight; the Ceres problem itself is in PlausibleSolver.cpp.

#include "model/PlausibleEstimate.h"

#include "model/Error.h"
#include "model/GeometricPrior.h"
#include "model/PlausibleSolver.h"

#include <Eigen/SVD>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PlausibleEstimate)
};

void checkProblem(const PlausibleProblem &pr)
{
    const Eigen::Index p = pr.prior.size();
    if (pr.links < 0 || p < 10 * Eigen::Index(pr.links) || pr.a.cols() != p ||
        pr.b.size() != pr.a.rows())
        throw Error(Text::tr("The estimation problem's sizes do not match: A is %1 x %2, b has "
                             "%3 entries, the prior %4 for %5 links.")
                        .arg(pr.a.rows())
                        .arg(pr.a.cols())
                        .arg(pr.b.size())
                        .arg(p)
                        .arg(pr.links));
    if (!pr.a.allFinite() || !pr.b.allFinite() || !pr.prior.allFinite())
        throw Error(Text::tr("The estimation problem has entries that are not finite."));
    if (!(pr.priorShare > 0.0 && pr.priorShare < 1.0))
        throw Error(
            Text::tr("The prior share must lie between 0 and 1, not %1.").arg(pr.priorShare));
    if (!pr.volumes.empty() && pr.volumes.size() != size_t(pr.links))
        throw Error(
            Text::tr("%1 bounding volumes for %2 links.").arg(pr.volumes.size()).arg(pr.links));
    for (const int i : pr.nonnegative) {
        if (i < 10 * pr.links || i >= p)
            throw Error(Text::tr("Index %1 is not a joint term.").arg(i));
        if (pr.prior[i] < 0.0)
            throw Error(
                Text::tr("The prior's joint term %1 is negative (%2).").arg(i).arg(pr.prior[i]));
    }
    for (int l = 0; l < pr.links; ++l) {
        if (!pr.volumes.empty() && pr.volumes[size_t(l)] &&
            !(pr.volumes[size_t(l)]->fitShare(pr.prior.segment<10>(10 * l)) > 0.0))
            throw Error(Text::tr("The prior's link %1 does not lie inside its bounding volume.")
                            .arg(l + 1));
    }
}

// Per link the 10 directions of the divergence's own metric: pi of U0 B_k U0^T for an orthonormal
// basis B_k of symmetric 4 x 4 matrices, so that D(J0 + dJ, J0) ~ |v|^2 / 2 for dJ = sum v_k ...
Matrix10d divergenceDirections(const Eigen::Matrix4d &u0)
{
    Matrix10d out;
    int k = 0;
    for (int i = 0; i < 4; ++i) {
        for (int j = i; j < 4; ++j, ++k) {
            Eigen::Matrix4d b = Eigen::Matrix4d::Zero();
            b(i, j) = b(j, i) = i == j ? 1.0 : std::sqrt(0.5);
            out.col(k) = inertialFromPseudoInertia(u0 * b * u0.transpose());
        }
    }
    return out;
}

double largestSingularValue(const Eigen::MatrixXd &m)
{
    return m.rows() > 0 && m.cols() > 0 ? Eigen::JacobiSVD<Eigen::MatrixXd>(m).singularValues()[0]
                                        : 0.0;
}

} // namespace

PlausibleEstimate plausibleEstimate(const PlausibleProblem &pr)
{
    checkProblem(pr);
    const int n = pr.links;
    const Eigen::Index p = pr.prior.size(), terms = p - 10 * n;

    // The prior's own metric: per link the divergence's directions, per joint term its column.
    // Each block's prior counts share^2 of what the data determine best within that block, so a
    // light wrist link's directions are weighed against what the data say of that link, not
    // against the heavy links' gravity.
    std::vector<Vector10d> prior(static_cast<size_t>(n));
    detail::PlausibleWeights weights;
    weights.links.assign(static_cast<size_t>(n), 1.0);
    for (int l = 0; l < n; ++l) {
        prior[size_t(l)] = pr.prior.segment<10>(10 * l);
        Eigen::Matrix4d u0;
        if (!detail::upperFactor(pseudoInertia(prior[size_t(l)]), u0))
            throw Error(Text::tr("The prior's link %1 is not strictly a real body (its "
                                 "pseudo-inertia is not positive definite).")
                            .arg(l + 1));
        const double largest =
            largestSingularValue(pr.a.middleCols<10>(10 * l) * divergenceDirections(u0));
        // gamma / 2 per unit of |v|^2 (D ~ |v|^2 / 2); without data the prior alone decides.
        weights.links[size_t(l)] = largest > 0.0 ? 2.0 * std::pow(pr.priorShare * largest, 2) : 1.0;
    }
    weights.terms = pr.a.rightCols(terms).colwise().norm().transpose();
    for (Eigen::Index i = 0; i < terms; ++i)
        weights.terms[i] = weights.terms[i] > 0.0 ? pr.priorShare * weights.terms[i] : 1.0;

    PlausibleEstimate result;
    result.linkWeight = n > 0 ? *std::min_element(weights.links.begin(), weights.links.end()) : 0.0;
    // Continuation: from a prior 100^2 times stronger (close to the CAD model, an easy problem)
    // to the asked one in two steps, each stage starting where the last ended. Levenberg-
    // Marquardt from the CAD model straight to a weak prior creeps along the barriers' curved
    // valleys (hundreds of steps without converging on the KUKA LWR4+ logs).
    std::vector<Vector10d> links = prior;
    Eigen::VectorXd termValues = pr.prior.tail(terms);
    detail::PlausibleStage stage;
    for (const double factor : {1e4, 1e3, 1e2, 1e1, 1.0}) {
        detail::PlausibleWeights w = weights;
        for (double &x : w.links)
            x *= factor;
        w.terms *= std::sqrt(factor);
        stage = detail::solvePlausibleStage(pr, prior, w, links, termValues);
        result.iterations += stage.iterations;
    }
    result.standard.resize(p);
    for (int l = 0; l < n; ++l)
        result.standard.segment<10>(10 * l) = links[size_t(l)];
    result.standard.tail(terms) = termValues;
    result.dataCost = (pr.a * result.standard - pr.b).squaredNorm();
    result.priorCost = std::max(0.0, 2.0 * stage.finalCost - result.dataCost);
    result.converged = stage.converged;
    result.report = stage.report;
    return result;
}

} // namespace learnid
