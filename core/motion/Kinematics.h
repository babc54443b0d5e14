#pragma once

#include <Eigen/Core>
#include <QString>

namespace learnid {

/// Position kinematics of an arm in a Cartesian task space of the same dimension as its joint
/// space (n joints, n task coordinates). q [rad] (n), x [m] (n).
class Kinematics
{
public:
    using VectorRef = Eigen::Ref<const Eigen::VectorXd>;

    virtual ~Kinematics() = default;
    virtual int dof() const = 0;
    virtual Eigen::VectorXd forward(const VectorRef &q) const = 0;
    /// Joint angles reaching x on the configured branch (elbow); throws Error when out of reach.
    /// near: a previous solution whose 2 pi branch the result keeps (for continuous paths).
    virtual Eigen::VectorXd inverse(const VectorRef &x, const VectorRef &near) const = 0;
    /// dx/dq (n x n).
    virtual Eigen::MatrixXd jacobian(const VectorRef &q) const = 0;
    /// dJ/dt * qd (n): the velocity product term of xdd = J qdd + Jdot qd.
    virtual Eigen::VectorXd jacobianDotTimesQd(const VectorRef &q, const VectorRef &qd) const = 0;
};

} // namespace learnid
