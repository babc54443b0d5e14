#include "control/StateSpace.h"

#include <Eigen/LU>
#include <unsupported/Eigen/MatrixFunctions>

namespace learnid {

StateSpace tustin(const StateSpace &continuous, double ts)
{
    const int n = continuous.states();
    const Eigen::MatrixXd eye = Eigen::MatrixXd::Identity(n, n);
    const Eigen::MatrixXd m = (eye - 0.5 * ts * continuous.a).inverse();
    StateSpace d;
    d.a = m * (eye + 0.5 * ts * continuous.a);
    d.b = ts * m * m * continuous.b;
    d.c = continuous.c;
    d.d = continuous.d + 0.5 * ts * continuous.c * m * continuous.b;
    return d;
}

StateSpace zeroOrderHold(const StateSpace &continuous, double ts)
{
    const int n = continuous.states();
    const int m = int(continuous.b.cols());
    Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + m, n + m);
    aug.topLeftCorner(n, n) = continuous.a * ts;
    aug.topRightCorner(n, m) = continuous.b * ts;
    const Eigen::MatrixXd e = aug.exp();
    StateSpace d;
    d.a = e.topLeftCorner(n, n);
    d.b = e.topRightCorner(n, m);
    d.c = continuous.c;
    d.d = continuous.d;
    return d;
}

Eigen::VectorXd steadyState(const StateSpace &discrete, const Eigen::VectorXd &u)
{
    const int n = discrete.states();
    return (Eigen::MatrixXd::Identity(n, n) - discrete.a).partialPivLu().solve(discrete.b * u);
}

} // namespace learnid
