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

void TwoLinkKinematics::solve(const VectorRef &x, const VectorRef &near, double *q,
                              double *cs) const
{
    const double r2 = x[0] * x[0] + x[1] * x[1];
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
    const double sinRel = m_elbowSign * std::sqrt((1.0 - cosRel) * (1.0 + cosRel));
    // theta1 = alpha - beta: alpha the bearing of x, beta that of the second link's end in the
    // frame of the first link, (a, b) = (l1 + l2 cos rel, l2 sin rel).
    const double a = m_l1 + m_l2 * cosRel;
    const double b = m_l2 * sinRel;
    // cos(alpha - beta) and sin(alpha - beta) from cos alpha = x0 / |x|, cos beta = a / |(a, b)|.
    const double cNum = x[0] * a + x[1] * b;
    const double sNum = x[1] * a - x[0] * b;
    if (near.size() == 2) {
        q[0] = unwrapNear(std::atan2(sNum, cNum), near[0]); // one atan2: the branch is near's
    } else {
        q[0] = std::atan2(x[1], x[0]) - std::atan2(b, a); // in (-2 pi, 2 pi), as always
    }
    q[1] = q[0] + rel;
    const double norm = std::sqrt(r2 * (a * a + b * b));
    const double c0 = cNum / norm;
    const double s0 = sNum / norm;
    cs[0] = c0;
    cs[1] = s0;
    cs[2] = c0 * cosRel - s0 * sinRel;
    cs[3] = s0 * cosRel + c0 * sinRel;
}

void TwoLinkKinematics::inverseInto(const VectorRef &x, const VectorRef &near,
                                    Eigen::Ref<Eigen::VectorXd> out) const
{
    double q[2], cs[4];
    solve(x, near, q, cs);
    out[0] = q[0];
    out[1] = q[1];
}

void TwoLinkKinematics::jointStateInto(const VectorRef &x, const VectorRef &xd,
                                       const VectorRef &xdd, const VectorRef &near,
                                       Eigen::Ref<Eigen::VectorXd> q,
                                       Eigen::Ref<Eigen::VectorXd> qd,
                                       Eigen::Ref<Eigen::VectorXd> qdd) const
{
    double angles[2], cs[4];
    solve(x, near, angles, cs);
    const double c0 = cs[0], s0 = cs[1], c1 = cs[2], s1 = cs[3];
    q[0] = angles[0];
    q[1] = angles[1];
    // J = [-l1 s0, -l2 s1; l1 c0, l2 c1], det J = l1 l2 sin(theta2 - theta1) != 0 off the
    // singularities, which solve() keeps away from.
    const double det = m_l1 * m_l2 * (s1 * c0 - s0 * c1);
    const auto jInvTimes = [&](double v0, double v1, double &out0, double &out1) {
        out0 = (m_l2 * c1 * v0 + m_l2 * s1 * v1) / det;
        out1 = (-m_l1 * c0 * v0 - m_l1 * s0 * v1) / det;
    };
    double w0, w1;
    jInvTimes(xd[0], xd[1], w0, w1);
    qd[0] = w0;
    qd[1] = w1;
    // xdd = J qdd + Jdot qd, Jdot qd = -(l1 w0^2 (c0, s0) + l2 w1^2 (c1, s1)).
    const double jdot0 = -m_l1 * c0 * w0 * w0 - m_l2 * c1 * w1 * w1;
    const double jdot1 = -m_l1 * s0 * w0 * w0 - m_l2 * s1 * w1 * w1;
    jInvTimes(xdd[0] - jdot0, xdd[1] - jdot1, w0, w1);
    qdd[0] = w0;
    qdd[1] = w1;
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
