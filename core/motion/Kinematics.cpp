#include "motion/Kinematics.h"

#include <Eigen/LU>

namespace learnid {

void Kinematics::jointStateInto(const VectorRef &x, const VectorRef &xd, const VectorRef &xdd,
                                const VectorRef &near, Eigen::Ref<Eigen::VectorXd> q,
                                Eigen::Ref<Eigen::VectorXd> qd,
                                Eigen::Ref<Eigen::VectorXd> qdd) const
{
    inverseInto(x, near, q);
    Eigen::MatrixXd j(dof(), dof());
    jacobianInto(q, j);
    const Eigen::MatrixXd jInv = j.inverse(); // non-singular: inverseInto keeps off singularities
    qd = jInv * xd;
    Eigen::VectorXd jdotQd(dof());
    jacobianDotTimesQdInto(q, qd, jdotQd);
    qdd = jInv * (xdd - jdotQd); // xdd = J qdd + Jdot qd
}

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
