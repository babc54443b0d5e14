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
    /// Joint terms held at the prior's value: what the data do not determine (a joint that never
    /// moves has no friction to fit).
    std::vector<int> heldAtPrior;
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
    int iterations = 0;       ///< Newton steps
    bool converged = false;   ///< the duality gap closed to its tolerance
    QString report;           ///< what the solver did, in one line
};

/// The standard parameters that minimise
///   ||A pi - b||^2 + gamma sum_l D(J_l, J0_l) + sum_i (w_i (pi_i - prior_i))^2
/// subject to, per link, J_l - s_l diag(1, 1, 1, 0) >= 0 (a thickness floor: Sigma_c >= s_l E,
/// when a rule is given) and tr(Q_l J_l) >= 0 (its bounding ellipsoid, when it has one), and
/// pi_i >= 0 for the nonnegative joint terms:
///  - D the log-det (Bregman) divergence of each link's pseudo-inertia from the prior's,
///    tr(J0^-1 J) - ln det(J0^-1 J) - 4 (Lee, Wensing and Park, IEEE T-RO 2020): it keeps each link
///    near its CAD body in the geometry of rigid bodies, and grows without bound towards point
///    masses, needles and plates;
///  - s_l from the rule and the CAD body (thicknessFloor in PlausibleEstimate.cpp): every
///    principal moment at least the rule's share of the CAD link's smallest, with 10 % margin;
///  - gamma = 2 w^2, w = priorShare times the largest singular value of A's link columns in the
///    divergence's own metric (PlausibleProblem::priorShare);
///  - w_i = priorShare times the norm of joint term i's column of A (1 where it is 0).
/// The problem is convex in pi; a primal barrier Newton method with exact Hessians solves it
/// (PlausibleNewton.h) to within 1e-10 of the optimal cost. A nonnegative term the optimum puts
/// at its bound comes out exactly 0 (below PlausibilityRule::termFloor it is set to 0 and the
/// rest solved again with it held there).
///
/// Throws Error naming the argument when a size does not match, an entry is not finite, the
/// share is outside (0, 1), an index is not a nonnegative joint term, a prior link is not
/// strictly consistent, a prior term that must not be negative is, or a prior body does not lie
/// inside its volume.
PlausibleEstimate plausibleEstimate(const PlausibleProblem &problem);

} // namespace learnid
