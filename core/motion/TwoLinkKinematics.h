#pragma once

#include "motion/Kinematics.h"

namespace learnid {

/// Planar 2-link arm with absolute joint angles (theta2 measured from the base x axis, as in
/// the paper): x = l1 (cos t1, sin t1) + l2 (cos t2, sin t2).
/// elbowSign +1 selects theta2 - theta1 in (0, pi): the paper's start -16.87 deg / 106.87 deg.
class TwoLinkKinematics final : public Kinematics
{
public:
    TwoLinkKinematics(double l1, double l2, int elbowSign = +1);

    int dof() const override { return 2; }
    void forwardInto(const VectorRef &q, Eigen::Ref<Eigen::VectorXd> out) const override;
    void inverseInto(const VectorRef &x, const VectorRef &near,
                     Eigen::Ref<Eigen::VectorXd> out) const override;
    void jacobianInto(const VectorRef &q, Eigen::Ref<Eigen::MatrixXd> out) const override;
    void jacobianDotTimesQdInto(const VectorRef &q, const VectorRef &qd,
                                Eigen::Ref<Eigen::VectorXd> out) const override;
    /// One acos and two atan2 per call: the sines and cosines of the joint angles follow from
    /// the triangle of the links algebraically.
    void jointStateInto(const VectorRef &x, const VectorRef &xd, const VectorRef &xdd,
                        const VectorRef &near, Eigen::Ref<Eigen::VectorXd> q,
                        Eigen::Ref<Eigen::VectorXd> qd,
                        Eigen::Ref<Eigen::VectorXd> qdd) const override;

private:
    /// Inverse kinematics of x with cos and sin of both joint angles: c0, s0, c1, s1.
    void solve(const VectorRef &x, const VectorRef &near, double *q, double *cs) const;

    double m_l1;
    double m_l2;
    int m_elbowSign;
};

} // namespace learnid
