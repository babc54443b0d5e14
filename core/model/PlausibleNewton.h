#pragma once

// Internal to plausibleEstimate() (PlausibleEstimate.h): the convex problem in the standard
// parameters and its primal barrier Newton method.

#include "model/BoundingVolume.h"
#include "model/PhysicalConsistency.h"

#include <Eigen/Core>
#include <vector>

namespace learnid::detail {

/// Per link: the prior's pseudo-inertia, the divergence's weight, the thickness floor and the
/// bounding ellipsoid's inequality.
struct LinkTerms
{
    Eigen::Matrix4d priorInverse; ///< J0^-1
    double priorLogDet = 0.0;     ///< ln det J0
    double weight = 0.0;          ///< gamma_l of D(J, J0)
    double thickness = 0.0;       ///< s_l: J - s_l diag(1, 1, 1, 0) >= 0 (Sigma_c >= s_l E)
    bool hasVolume = false;
    Eigen::Matrix4d volume = Eigen::Matrix4d::Zero(); ///< Q: tr(Q J) >= 0
};

/// f(pi) = |A pi - b|^2 + sum_l gamma_l D(J_l, J0_l) + sum_i (w_i (pi_i - prior_i))^2 (joint
/// terms), to minimise subject to J_l - s_l diag(1,1,1,0) > 0, tr(Q_l J_l) > 0 and pi_i > 0 for
/// the nonnegative terms that are not fixed at 0. Convex: a quadratic, -ln det of an affine
/// matrix function, and linear terms.
struct PlausibleObjective
{
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
    Eigen::VectorXd prior; ///< p
    std::vector<LinkTerms> links;
    Eigen::VectorXd termWeights;   ///< w_i per joint term (p - 10 links)
    std::vector<char> nonnegative; ///< per index of pi: 1 for a term that must be >= 0
    std::vector<char> fixed;       ///< per index of pi: 1 for a term held at exactly 0
};

/// The result of the barrier method.
struct NewtonResult
{
    Eigen::VectorXd pi;
    double cost = 0.0; ///< f(pi)
    int steps = 0;     ///< Newton steps (each one linear solve)
    bool converged = false;
};

/// f(pi), or +infinity outside the strict constraints (the barriers' domain).
double objectiveValue(const PlausibleObjective &objective, const Eigen::VectorXd &pi);

/// Minimises f + mu phi (phi the log barriers of the constraints) by damped Newton steps from a
/// strictly feasible start, mu divided by 10 each time the Newton decrement is small, until
/// nu mu <= relativeGap f (nu the barriers' parameter; f then within that share of its
/// constrained minimum) or maxSteps steps.
NewtonResult minimiseWithBarriers(const PlausibleObjective &objective, Eigen::VectorXd start,
                                  double relativeGap, int maxSteps);

} // namespace learnid::detail
