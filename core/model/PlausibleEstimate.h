#pragma once

#include "model/BoundingVolume.h"
#include "model/Plausibility.h"

#include <Eigen/Core>
#include <QString>
#include <optional>
#include <vector>

namespace learnid {

/// Standard parameters to estimate from data rows with a geometric prior (docs/identify.md
/// "Plausible bodies", docs/robots.md §6).
struct PlausibleProblem
{
    Eigen::MatrixXd a;     ///< r x p: the data's rows in the standard parameters (weighted)
    Eigen::VectorXd b;     ///< r: their targets
    Eigen::VectorXd prior; ///< p: the CAD model, every link a real body (realBodyPrior())
    int links = 0;         ///< the first 10 links entries of pi are links' inertial parameters
    std::vector<int> nonnegative; ///< joint terms that cannot be negative (friction, armature)
    /// Per link (links entries, or empty): the ellipsoid its mass must lie in; the prior's
    /// body must lie strictly inside (fitShare > 0).
    std::vector<std::optional<BoundingEllipsoid>> volumes;
    /// When set, every link is kept inside the rule (principal moments, shape) where its prior
    /// is: an estimate that passes checkPlausibility() by construction. A prior link that breaks
    /// a part of the rule itself is not held to that part.
    std::optional<PlausibilityRule> rule;
    /// The prior's weight as a share of what the data determine best: in the prior's own metric
    /// (each link's pseudo-inertia relative to the CAD one, each joint term relative to its
    /// regressor column) the prior counts share^2 times the largest information the rows carry
    /// in any direction. Directions the rows determine much better than that follow the data;
    /// those they hardly see stay at the prior. In (0, 1).
    double priorShare = 0.03;
};

/// The result of plausibleEstimate().
struct PlausibleEstimate
{
    Eigen::VectorXd standard; ///< pi (p): every link strictly consistent, nonnegative terms >= 0
    double dataCost = 0.0;    ///< ||A pi - b||^2
    double priorCost = 0.0;   ///< the prior's terms (weighted divergences and squares)
    double linkWeight = 0.0;  ///< the weight of each link's divergence (from priorShare)
    int iterations = 0;       ///< the solver's iterations
    bool converged = false;   ///< the solver met a convergence tolerance
    QString report;           ///< the solver's one-line summary
};

/// The standard parameters that minimise
///   ||A pi - b||^2 + gamma sum_l [D(J_l, J0_l) + D_V(t_l, t0_l)] + w^2 sum_i (c_i (pi_i -
///   prior_i))^2
/// over every link's log-Cholesky parameters (consistent by construction) and the joint terms
/// (nonnegative ones bounded below by 0, so that a term the data want at 0 is exactly 0):
///  - D the log-det divergence of each link's pseudo-inertia from the prior's
///    (GeometricPrior.h): it keeps each link a body near the CAD one in the geometry of rigid
///    bodies, growing without bound towards point masses, needles and plates;
///  - D_V the same divergence of the link's bounding-ellipsoid inequality, where it has one;
///  - c_i the norm of joint term i's column of A (floored at 1e-3 of the largest), so that
///    the joint terms' prior is the ridge in the data's own scaling.
/// gamma and w follow from priorShare (PlausibleProblem). Solved by Ceres' Levenberg-Marquardt
/// (dense QR) from the prior: the problem is convex in pi and the log-Cholesky map is a
/// diffeomorphism onto the consistent interior, so its stationary point is the minimum.
///
/// Throws Error naming the argument when a size does not match, an entry is not finite, the
/// share is outside (0, 1), an index is not a nonnegative joint term, a prior link is not
/// strictly consistent, a prior term that must not be negative is, or a prior body does not lie
/// inside its volume.
PlausibleEstimate plausibleEstimate(const PlausibleProblem &problem);

} // namespace learnid
