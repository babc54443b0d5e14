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

void TwoLinkKinematics::forwardInto(const VectorRef &q, Eigen::Ref<Eigen::VectorXd> out) const
{
    out[0] = m_l1 * std::cos(q[0]) + m_l2 * std::cos(q[1]);
    out[1] = m_l1 * std::sin(q[0]) + m_l2 * std::sin(q[1]);
}

void TwoLinkKinematics::inverseInto(const VectorRef &x, const VectorRef &near,
                                    Eigen::Ref<Eigen::VectorXd> out) const
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
    out[0] = near.size() == 2 ? unwrapNear(t1, near[0]) : t1;
    out[1] = out[0] + rel;
}

void TwoLinkKinematics::jacobianInto(const VectorRef &q, Eigen::Ref<Eigen::MatrixXd> out) const
{
    out(0, 0) = -m_l1 * std::sin(q[0]);
    out(0, 1) = -m_l2 * std::sin(q[1]);
    out(1, 0) = m_l1 * std::cos(q[0]);
    out(1, 1) = m_l2 * std::cos(q[1]);
}

void TwoLinkKinematics::jacobianDotTimesQdInto(const VectorRef &q, const VectorRef &qd,
                                               Eigen::Ref<Eigen::VectorXd> out) const
{
    const double w1 = qd[0] * qd[0];
    const double w2 = qd[1] * qd[1];
    out[0] = -m_l1 * std::cos(q[0]) * w1 - m_l2 * std::cos(q[1]) * w2;
    out[1] = -m_l1 * std::sin(q[0]) * w1 - m_l2 * std::sin(q[1]) * w2;
}

} // namespace learnid
