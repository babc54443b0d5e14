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

    /// x(q) into out (n).
    virtual void forwardInto(const VectorRef &q, Eigen::Ref<Eigen::VectorXd> out) const = 0;
    /// Joint angles reaching x on the configured branch (elbow) into out; throws Error when out
    /// of reach. near: a previous solution whose 2 pi branch the result keeps (may be empty).
    virtual void inverseInto(const VectorRef &x, const VectorRef &near,
                             Eigen::Ref<Eigen::VectorXd> out) const = 0;
    /// dx/dq into out (n x n).
    virtual void jacobianInto(const VectorRef &q, Eigen::Ref<Eigen::MatrixXd> out) const = 0;
    /// dJ/dt * qd into out (n): the velocity product term of xdd = J qdd + Jdot qd.
    virtual void jacobianDotTimesQdInto(const VectorRef &q, const VectorRef &qd,
                                        Eigen::Ref<Eigen::VectorXd> out) const = 0;

    /// The joint state that moves the task point along x [m], xd [m/s], xdd [m/s^2] (n):
    /// q = inverse(x, near), qd = J^-1 xd, qdd = J^-1 (xdd - Jdot qd), into q [rad], qd [rad/s],
    /// qdd [rad/s^2] (n). Throws Error as inverseInto(). The default evaluates the functions
    /// above; arms override it to share their trigonometry (the planner calls it every sample).
    virtual void jointStateInto(const VectorRef &x, const VectorRef &xd, const VectorRef &xdd,
                                const VectorRef &near, Eigen::Ref<Eigen::VectorXd> q,
                                Eigen::Ref<Eigen::VectorXd> qd,
                                Eigen::Ref<Eigen::VectorXd> qdd) const;

    /// Allocating conveniences of the above, for code outside hot loops.
    Eigen::VectorXd forward(const VectorRef &q) const;
    Eigen::VectorXd inverse(const VectorRef &x, const VectorRef &near) const;
    Eigen::MatrixXd jacobian(const VectorRef &q) const;
    Eigen::VectorXd jacobianDotTimesQd(const VectorRef &q, const VectorRef &qd) const;
};

} // namespace learnid
