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

private:
    double m_l1;
    double m_l2;
    int m_elbowSign;
};

} // namespace learnid
