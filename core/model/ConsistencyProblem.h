#pragma once

// Internal to nearestConsistentEstimate() (PhysicalConsistency.h): the validated problem and
// its interior-point solution in the standard parameters, the start of the log-Cholesky
// Levenberg-Marquardt.

#include "model/PhysicalConsistency.h"

#include <Eigen/Core>
#include <vector>

namespace learnid::detail {

/// ||M pi - y||^2 with M = [A; w D] ((r + p) x p) and y = [b; w D prior] (r + p): the cost of
/// nearestConsistentEstimate() as one least-squares problem.
struct ConsistencyProblem
{
    Eigen::MatrixXd m;
    Eigen::VectorXd y;
    int links = 0;
    std::vector<char> nonnegative; ///< per index of pi (p): 1 where pi_i must be >= 0

    /// The barrier parameter nu: 4 per link (J is 4 x 4), 1 per nonnegative term.
    int barrierTerms() const;
};

/// The problem of nearestConsistentEstimate(), its arguments checked (throws Error as
/// documented there).
ConsistencyProblem consistencyProblem(const Eigen::MatrixXd &a, const Eigen::VectorXd &b,
                                      const Eigen::VectorXd &prior,
                                      const Eigen::VectorXd &priorScale, double priorWeight,
                                      int links, const std::vector<int> &nonnegativeIndices);

/// A strictly consistent copy of pi (p): each link's J with its eigenvalues floored at
/// floorShare lambda_max (the fallback's block where J has no positive eigenvalue), each
/// nonnegative term floored at floorShare of max(|pi_i|, |fallback_i|) (1e-16 if both are 0).
Eigen::VectorXd strictlyConsistent(const ConsistencyProblem &problem, const Eigen::VectorXd &pi,
                                   const Eigen::VectorXd &fallback, double floorShare);

/// The minimiser of ||M pi - y||^2 over the consistent set, by a primal log-barrier method:
/// Newton steps on ||M pi - y||^2 - mu (sum_l log det J_l + sum_i log pi_i) from a strictly
/// consistent start, mu divided by 50 once centred (from 0.1 of the start's cost / nu), until nu mu
/// <= relativeGap ||M pi - y||^2 (the cost is then within about that share of the optimum) or
/// maxSteps Newton steps. The problem is convex in pi, so this converges whatever the conditioning;
/// every iterate is strictly consistent. steps receives the Newton steps taken.
Eigen::VectorXd interiorPointEstimate(const ConsistencyProblem &problem, Eigen::VectorXd pi,
                                      double relativeGap, int maxSteps, int &steps);

} // namespace learnid::detail
