#include "motion/TwoLinkKinematics.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {
// The 2 pi multiple of `angle` closest to `reference`.
double unwrapNear(double angle, double reference)
{
    const double twoPi = 2.0 * M_PI;
    return angle + twoPi * std::round((reference - angle) / twoPi);
}
} // namespace

TwoLinkKinematics::TwoLinkKinematics(double l1, double l2, int elbowSign)
    : m_l1(l1)
    , m_l2(l2)
    , m_elbowSign(elbowSign >= 0 ? 1 : -1)
{}

Eigen::VectorXd TwoLinkKinematics::forward(const VectorRef &q) const
{
    return Eigen::Vector2d(m_l1 * std::cos(q[0]) + m_l2 * std::cos(q[1]),
                           m_l1 * std::sin(q[0]) + m_l2 * std::sin(q[1]));
}

Eigen::VectorXd TwoLinkKinematics::inverse(const VectorRef &x, const VectorRef &near) const
{
    const double r2 = x.squaredNorm();
    const double cosRel = (r2 - m_l1 * m_l1 - m_l2 * m_l2) / (2.0 * m_l1 * m_l2);
    // A margin keeps the arm away from the stretched and folded singularities, where
    // qd = J^-1 xd is unbounded.
    if (std::abs(cosRel) > 1.0 - 1e-9) {
        throw Error(QCoreApplication::translate(
                        "TwoLinkKinematics",
                        "point (%1, %2) m is out of reach or at a singularity of the arm "
                        "(link lengths %3 m and %4 m)")
                        .arg(x[0], 0, 'f', 4)
                        .arg(x[1], 0, 'f', 4)
                        .arg(m_l1)
                        .arg(m_l2));
    }
    const double rel = m_elbowSign * std::acos(cosRel);
    const double t1 = std::atan2(x[1], x[0])
                      - std::atan2(m_l2 * std::sin(rel), m_l1 + m_l2 * std::cos(rel));
    Eigen::Vector2d q(t1, t1 + rel);
    if (near.size() == 2) {
        q[0] = unwrapNear(q[0], near[0]);
        q[1] = q[0] + rel;
    }
    return q;
}

Eigen::MatrixXd TwoLinkKinematics::jacobian(const VectorRef &q) const
{
    Eigen::Matrix2d j;
    j << -m_l1 * std::sin(q[0]), -m_l2 * std::sin(q[1]), m_l1 * std::cos(q[0]),
        m_l2 * std::cos(q[1]);
    return j;
}

Eigen::VectorXd TwoLinkKinematics::jacobianDotTimesQd(const VectorRef &q, const VectorRef &qd) const
{
    const double w1 = qd[0] * qd[0];
    const double w2 = qd[1] * qd[1];
    return Eigen::Vector2d(-m_l1 * std::cos(q[0]) * w1 - m_l2 * std::cos(q[1]) * w2,
                           -m_l1 * std::sin(q[0]) * w1 - m_l2 * std::sin(q[1]) * w2);
}

} // namespace learnid
