#include "model/ChainDynamics.h"

#include "model/ChainProducts.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

using chainproducts::times;

// Always inlined, as times() (ChainProducts.h).
Q_ALWAYS_INLINE Eigen::Matrix3d skew(const Eigen::Vector3d &v)
{
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(), //
        v.z(), 0.0, -v.x(),  //
        -v.y(), v.x(), 0.0;
    return s;
}

// The symmetric inertia [Ixx Ixy Ixz; Ixy Iyy Iyz; Ixz Iyz Izz] (pi[4..9]) times v, written out.
Q_ALWAYS_INLINE Eigen::Vector3d inertiaTimes(const double *pi, const Eigen::Vector3d &v)
{
    return {pi[4] * v.x() + pi[5] * v.y() + pi[7] * v.z(),
            pi[5] * v.x() + pi[6] * v.y() + pi[8] * v.z(),
            pi[7] * v.x() + pi[8] * v.y() + pi[9] * v.z()};
}

// Angular velocity w, angular acceleration wd and the linear acceleration a of a link frame's
// origin (gravity folded in as the base accelerating at -g), in that link's frame.
struct LinkMotion
{
    Eigen::Vector3d w, wd, a;
};

} // namespace

ChainDynamics::ChainDynamics(const SerialChain &chain)
    : m_chain(chain)
    , m_dof(chain.dof())
{
    if (m_dof < 1 || m_dof > maxJoints) {
        throw Error(QCoreApplication::translate("ChainDynamics",
                                                "%1 has %2 moving joints: a chain needs 1 to %3")
                        .arg(chain.name)
                        .arg(m_dof)
                        .arg(maxJoints));
    }
    for (int k = 0; k < m_dof; ++k) {
        const ChainJoint &j = chain.joints[size_t(k)];
        m_originRotation[size_t(k)] = j.origin.linear();
        m_originTranslation[size_t(k)] = j.origin.translation();
        m_axis[size_t(k)] = j.axis;
        m_prismatic[size_t(k)] = j.type == JointType::Prismatic;
        const Eigen::Matrix3d &r0 = m_originRotation[size_t(k)];
        m_rotationFixed[size_t(k)] = r0 * j.axis * j.axis.transpose();
        m_rotationCos[size_t(k)] = r0 - m_rotationFixed[size_t(k)];
        m_rotationSin[size_t(k)] = r0 * skew(j.axis);
    }
}

void ChainDynamics::place(const VectorRef &q, Placements &out) const
{
    for (size_t k = 0; k < size_t(m_dof); ++k) {
        if (m_prismatic[k]) {
            out[k].r = m_originRotation[k];
            out[k].p =
                m_originTranslation[k] + m_originRotation[k] * (m_axis[k] * q[Eigen::Index(k)]);
        } else {
            const double angle = q[Eigen::Index(k)];
            out[k].r = m_rotationFixed[k] + std::cos(angle) * m_rotationCos[k] +
                       std::sin(angle) * m_rotationSin[k];
            out[k].p = m_originTranslation[k];
        }
    }
}

namespace {

template <typename Placements, typename Axes, typename Flags>
void propagate(int n, const Placements &pl, const Axes &axis, const Flags &prismatic,
               const Eigen::Ref<const Eigen::VectorXd> &qd,
               const Eigen::Ref<const Eigen::VectorXd> &qdd, const Eigen::Vector3d &baseAccel,
               std::array<LinkMotion, ChainDynamics::maxJoints> &out)
{
    Eigen::Vector3d w = Eigen::Vector3d::Zero(), wd = Eigen::Vector3d::Zero(), a = baseAccel;
    for (size_t k = 0; k < size_t(n); ++k) {
        const Eigen::Matrix3d &r = pl[k].r;
        const Eigen::Vector3d &p = pl[k].p;
        const Eigen::Vector3d &z = axis[k];
        const double v = qd[Eigen::Index(k)], acc = qdd[Eigen::Index(k)];
        // The three vectors into frame k in one 3 x 3 product (faster than three products).
        Eigen::Matrix3d parent;
        parent.col(0) = a + wd.cross(p) + w.cross(w.cross(p));
        parent.col(1) = w;
        parent.col(2) = wd;
        const Eigen::Matrix3d local = r.transpose() * parent;
        Eigen::Vector3d ak = local.col(0);
        Eigen::Vector3d wk = local.col(1);
        Eigen::Vector3d wdk = local.col(2);
        if (prismatic[k]) {
            ak += 2.0 * v * wk.cross(z) + acc * z;
        } else {
            wdk += v * wk.cross(z) + acc * z;
            wk += v * z;
        }
        out[k] = {wk, wdk, ak};
        w = wk;
        wd = wdk;
        a = ak;
    }
}

} // namespace

void ChainDynamics::regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                              Eigen::Ref<Eigen::MatrixXd> out) const
{
    Placements pl;
    place(q, pl);
    std::array<LinkMotion, maxJoints> motion;
    propagate(m_dof, pl, m_axis, m_prismatic, qd, qdd, -m_chain.gravity, motion);
    // Joint i's unit motion (linear v at the frame origin, angular w) in frame k, k >= i: the
    // power it draws from link k's wrench [f; n] is v.f + w.n, which is tau_i's share.
    std::array<Eigen::Vector3d, maxJoints> sv, sw;
    for (int k = 0; k < m_dof; ++k) {
        const size_t uk = size_t(k);
        const Eigen::Matrix3d rt = pl[uk].r.transpose();
        for (int i = 0; i < k; ++i) {
            const size_t ui = size_t(i);
            sv[ui] = times(rt, sv[ui] + sw[ui].cross(pl[uk].p));
            sw[ui] = times(rt, sw[ui]);
        }
        sv[uk] = m_prismatic[uk] ? m_axis[uk] : Eigen::Vector3d::Zero();
        sw[uk] = m_prismatic[uk] ? Eigen::Vector3d::Zero() : m_axis[uk];

        // Link k's wrench, linear in its parameters:
        //   f = a m + ([wd]x + [w]x[w]x) h,   n = -[a]x h + (L(wd) + [w]x L(w)) I,
        // with L(v) [Ixx, Ixy, Iyy, Ixz, Iyz, Izz]^T = I v.
        const LinkMotion &lm = motion[uk];
        // Both written out ([w]x[w]x = w w^T - |w|^2 E): as products of Eigen's small matrices
        // they took a third of the regressor's time.
        const double wx = lm.w.x(), wy = lm.w.y(), wz = lm.w.z();
        const double dx = lm.wd.x(), dy = lm.wd.y(), dz = lm.wd.z();
        Eigen::Matrix3d forceFromH;
        forceFromH << -(wy * wy + wz * wz), wx * wy - dz, wx * wz + dy, //
            wx * wy + dz, -(wx * wx + wz * wz), wy * wz - dx,           //
            wx * wz - dy, wy * wz + dx, -(wx * wx + wy * wy);
        const Eigen::Matrix3d momentFromH = -skew(lm.a);
        Eigen::Matrix<double, 3, 6> momentFromI;
        momentFromI << dx, dy - wz * wx, -wz * wy, dz + wy * wx, wy * wy - wz * wz, wy * wz, //
            wz * wx, dx + wz * wy, dy, wz * wz - wx * wx, dz - wx * wy, -wx * wz,            //
            -wy * wx, wx * wx - wy * wy, wx * wy, dx - wy * wz, dy + wx * wz, dz;
        const Eigen::Index col = Eigen::Index(10) * k;
        for (Eigen::Index c = col; c < col + 10; ++c) // link k does not load the joints after it
            std::fill_n(out.col(c).data() + k + 1, m_dof - k - 1, 0.0);
        for (int i = 0; i <= k; ++i) {
            const size_t ui = size_t(i);
            out(i, col) = sv[ui].dot(lm.a);
            out.block<1, 3>(i, col + 1) =
                sv[ui].transpose() * forceFromH + sw[ui].transpose() * momentFromH;
            out.block<1, 6>(i, col + 4) = sw[ui].transpose() * momentFromI;
        }
    }
}

void ChainDynamics::inverseDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                                    const VectorRef &pi, Eigen::Ref<Eigen::VectorXd> out,
                                    double gravityScale) const
{
    Placements pl;
    place(q, pl);
    inverseDynamicsPlaced(pl, qd, qdd, pi, out, gravityScale);
}

void ChainDynamics::inverseDynamicsPlaced(const Placements &pl, const VectorRef &qd,
                                          const VectorRef &qdd, const VectorRef &pi,
                                          Eigen::Ref<Eigen::VectorXd> out,
                                          double gravityScale) const
{
    std::array<LinkMotion, maxJoints> motion;
    propagate(m_dof, pl, m_axis, m_prismatic, qd, qdd, -gravityScale * m_chain.gravity, motion);
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    for (int k = m_dof - 1; k >= 0; --k) {
        const size_t uk = size_t(k);
        const double *p = pi.data() + 10 * k;
        const Eigen::Vector3d h(p[1], p[2], p[3]);
        const LinkMotion &lm = motion[uk];
        Eigen::Vector3d f = p[0] * lm.a + lm.wd.cross(h) + lm.w.cross(lm.w.cross(h));
        Eigen::Vector3d n =
            inertiaTimes(p, lm.wd) + lm.w.cross(inertiaTimes(p, lm.w)) + h.cross(lm.a);
        if (k + 1 < m_dof) { // the wrench the next link exerts, brought into this frame
            const Eigen::Vector3d childForce = times(pl[uk + 1].r, force);
            f += childForce;
            n += times(pl[uk + 1].r, moment) + pl[uk + 1].p.cross(childForce);
        }
        force = f;
        moment = n;
        out[k] = m_axis[uk].dot(m_prismatic[uk] ? force : moment);
    }
}

} // namespace learnid
