#pragma once

#include <Eigen/Core>

namespace learnid {

/// A linear time-invariant system x' = A x + B u, y = C x + D u (continuous), or
/// x[k+1] = A x[k] + B u[k], y[k] = C x[k] + D u[k] (discrete).
struct StateSpace
{
    Eigen::MatrixXd a;
    Eigen::MatrixXd b;
    Eigen::MatrixXd c;
    Eigen::MatrixXd d;

    int states() const { return int(a.rows()); }
};

/// Bilinear (Tustin) discretisation with sample period ts [s] (trapezoidal integration of the
/// state equation). With M = (I - A ts/2)^-1:
///   Ad = M (I + A ts/2),  Bd = ts M^2 B,  Cd = C,  Dd = D + (ts/2) C M B.
StateSpace tustin(const StateSpace &continuous, double ts);

/// Zero-order-hold discretisation (exact for inputs held over each sample), via the matrix
/// exponential of [A B; 0 0] ts. C and D are unchanged.
StateSpace zeroOrderHold(const StateSpace &continuous, double ts);

/// State of a stable discrete system at rest under the constant input u: (I - A)^-1 B u.
Eigen::VectorXd steadyState(const StateSpace &discrete, const Eigen::VectorXd &u);

} // namespace learnid
