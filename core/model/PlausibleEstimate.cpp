// plausibleEstimate() of PlausibleEstimate.h: the problem checked, its weights and constraints;
// the barrier Newton method that solves it is in PlausibleNewton.cpp.

#include "model/PlausibleEstimate.h"

#include "model/Error.h"
#include "model/PlausibleNewton.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
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
    for (const int i : pr.heldAtPrior)
        if (i < 10 * pr.links || i >= p)
            throw Error(Text::tr("Index %1 is not a joint term.").arg(i));
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
Matrix10d divergenceDirections(const Eigen::Matrix4d &u0) // any factor J0 = u0 u0^T
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

// The thickness floor s of a prior link under rule (docs/robots.md §6): Sigma_c >= s E gives
// every principal moment >= 2 s (I_k = sigma_i + sigma_j) and I1 + I2 - I3 = 2 sigma_min >= 2 s.
// s = 1.1 max(share I_min / 2, margin I3) of the CAD body keeps the moments' rule with 10 %
// margin, and the triangle rule while I3 stays below 2.2 times the CAD link's; it is capped at
// half the CAD body's own sigma_min, so that the prior lies strictly inside.
double thicknessFloor(const Vector10d &prior, const PlausibilityRule &rule)
{
    const double m = prior[0];
    const Eigen::Vector3d c = prior.segment<3>(1) / m;
    const Eigen::Matrix3d sigma =
        pseudoInertia(prior).topLeftCorner<3, 3>() - m * c * c.transpose();
    const Eigen::Vector3d s =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(sigma, Eigen::EigenvaluesOnly).eigenvalues();
    const double smallestMoment = s[0] + s[1], largestMoment = s[1] + s[2];
    return std::min(1.1 * std::max(0.5 * rule.minMomentShare * smallestMoment,
                                   rule.triangleMargin * largestMoment),
                    0.5 * s[0]);
}

} // namespace

PlausibleEstimate plausibleEstimate(const PlausibleProblem &pr)
{
    checkProblem(pr);
    const int n = pr.links;
    const Eigen::Index p = pr.prior.size(), terms = p - 10 * n;

    detail::PlausibleObjective o;
    o.a = pr.a;
    o.b = pr.b;
    o.prior = pr.prior;
    o.nonnegative.assign(size_t(p), 0);
    o.fixed.assign(size_t(p), 0);
    for (const int i : pr.nonnegative)
        o.nonnegative[size_t(i)] = 1;
    // The links' prior counts share^2 of what the data determine best of the links, in the
    // divergence's own metric: directions the data determine much better than that follow the
    // data, those they hardly see stay at the prior. Without data the prior alone decides.
    Eigen::MatrixXd scaled(pr.a.rows(), 10 * n);
    for (int l = 0; l < n; ++l) {
        const Vector10d prior = pr.prior.segment<10>(10 * l);
        const Eigen::Matrix4d j0 = pseudoInertia(prior);
        const Eigen::LLT<Eigen::Matrix4d> llt(j0);
        if (llt.info() != Eigen::Success)
            throw Error(Text::tr("The prior's link %1 is not strictly a real body (its "
                                 "pseudo-inertia is not positive definite).")
                            .arg(l + 1));
        detail::LinkTerms t;
        t.priorInverse = llt.solve(Eigen::Matrix4d::Identity());
        t.priorLogDet = 2.0 * Eigen::Matrix4d(llt.matrixL()).diagonal().array().log().sum();
        scaled.middleCols<10>(10 * l) =
            pr.a.middleCols<10>(10 * l) * divergenceDirections(llt.matrixL());
        if (pr.rule)
            t.thickness = thicknessFloor(prior, *pr.rule);
        if (!pr.volumes.empty() && pr.volumes[size_t(l)]) {
            t.hasVolume = true;
            t.volume = pr.volumes[size_t(l)]->constraintMatrix();
        }
        o.links.push_back(t);
    }
    // D ~ |v|^2 / 2 in the divergence's directions: gamma / 2 = share^2 largest^2. A joint term
    // is weighed against its own column (a friction or offset is determined alone, or not at
    // all): w_i = share |A_i|, 1 where the data do not see it.
    const double largest = largestSingularValue(scaled.leftCols(10 * n));
    const double w = largest > 0.0 ? pr.priorShare * largest : 1.0;
    for (detail::LinkTerms &t : o.links)
        t.weight = 2.0 * w * w;
    o.termWeights = pr.a.rightCols(terms).colwise().norm().transpose();
    for (Eigen::Index i = 0; i < terms; ++i)
        o.termWeights[i] = o.termWeights[i] > 0.0 ? pr.priorShare * o.termWeights[i] : 1.0;

    // The prior is strictly feasible but for nonnegative terms at 0, which start just inside.
    Eigen::VectorXd start = pr.prior;
    for (const int i : pr.nonnegative)
        start[i] = std::max(start[i], 1e-3 * std::abs(pr.prior[i]) + 1e-6);
    for (const int i : pr.heldAtPrior) {
        start[i] = pr.prior[i];
        o.fixed[size_t(i)] = 1;
    }
    constexpr double gap = 1e-10;
    constexpr int maxSteps = 400;
    detail::NewtonResult r = detail::minimiseWithBarriers(o, start, gap, maxSteps);
    int steps = r.steps;
    // A term the barrier left within termFloor of 0 is at its bound: exactly 0 (no denormal or
    // 1e-9 N m), and the rest re-centred with it held there.
    bool snapped = false;
    for (const int i : pr.nonnegative) {
        if (!o.fixed[size_t(i)] && r.pi[i] < PlausibilityRule().termFloor) {
            r.pi[i] = 0.0;
            o.fixed[size_t(i)] = 1;
            snapped = true;
        }
    }
    if (snapped) {
        r = detail::minimiseWithBarriers(o, r.pi, gap, maxSteps);
        steps += r.steps;
    }

    PlausibleEstimate result;
    result.standard = r.pi;
    result.dataCost = (pr.a * r.pi - pr.b).squaredNorm();
    result.priorCost = r.cost - result.dataCost;
    result.linkWeight = 2.0 * w * w;
    result.iterations = steps;
    result.converged = r.converged;
    result.report = Text::tr("%n Newton step(s)", nullptr, steps);
    return result;
}

} // namespace learnid
