#include "motion/Kinematics.h"

namespace learnid {

Eigen::VectorXd Kinematics::forward(const VectorRef &q) const
{
    Eigen::VectorXd x(dof());
    forwardInto(q, x);
    return x;
}

Eigen::VectorXd Kinematics::inverse(const VectorRef &x, const VectorRef &near) const
{
    Eigen::VectorXd q(dof());
    inverseInto(x, near, q);
    return q;
}

Eigen::MatrixXd Kinematics::jacobian(const VectorRef &q) const
{
    Eigen::MatrixXd j(dof(), dof());
    jacobianInto(q, j);
    return j;
}

Eigen::VectorXd Kinematics::jacobianDotTimesQd(const VectorRef &q, const VectorRef &qd) const
{
    Eigen::VectorXd out(dof());
    jacobianDotTimesQdInto(q, qd, out);
    return out;
}

} // namespace learnid
