#include "model/ChainDynamics.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QtGlobal>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

// The small helpers below are always inlined: GCC otherwise calls them (and Eigen's fixed-size
// products inside them) out of line in the recursions, which cost a quarter of their time
// (learnid-bench-chain, docs/benchmarks.md).
Q_ALWAYS_INLINE Eigen::Matrix3d skew(const Eigen::Vector3d &v)
{
    Eigen::Matrix3d s;
    s << 0.0, -v.z(), v.y(), //
        v.z(), 0.0, -v.x(),  //
        -v.y(), v.x(), 0.0;
    return s;
}

Eigen::Matrix3d inertiaOf(const double *pi)
{
    Eigen::Matrix3d i;
    i << pi[4], pi[5], pi[7], //
        pi[5], pi[6], pi[8],  //
        pi[7], pi[8], pi[9];
    return i;
}

// r v and the symmetric inertia [Ixx Ixy Ixz; Ixy Iyy Iyz; Ixz Iyz Izz] (pi[4..9]) times v,
// written out.
Q_ALWAYS_INLINE Eigen::Vector3d times(const Eigen::Matrix3d &r, const Eigen::Vector3d &v)
{
    return r.col(0) * v.x() + r.col(1) * v.y() + r.col(2) * v.z();
}

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

void ChainDynamics::massMatrixAndBias(const VectorRef &q, const VectorRef &qd, const VectorRef &pi,
                                      Eigen::Ref<Eigen::MatrixXd> mass,
                                      Eigen::Ref<Eigen::VectorXd> bias) const
{
    Placements pl;
    place(q, pl);
    massMatrixPlaced(pl, pi, mass);
    const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, maxJoints, 1> zero =
        Eigen::VectorXd::Zero(m_dof);
    inverseDynamicsPlaced(pl, qd, zero, pi, bias, 1.0);
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

void ChainDynamics::massMatrix(const VectorRef &q, const VectorRef &pi,
                               Eigen::Ref<Eigen::MatrixXd> out) const
{
    Placements pl;
    place(q, pl);
    massMatrixPlaced(pl, pi, out);
}

void ChainDynamics::massMatrixPlaced(const Placements &pl, const VectorRef &pi,
                                     Eigen::Ref<Eigen::MatrixXd> out) const
{
    // Composite rigid-body algorithm on 10-parameter bodies: the subtree from link k on, as a
    // mass m, first moment h = m c and rotational inertia I about frame k's origin, in frame k
    // (3 x 3 algebra: a third of the flops of 6 x 6 spatial matrices). A body moved into its
    // parent's frame (x_parent = R x + p) has h' = R h + m p and
    //   I' = R I R^T + m (|p|^2 E - p p^T) + 2 (p . R h) E - p (R h)^T - (R h) p^T.
    std::array<double, maxJoints> mass;
    std::array<Eigen::Vector3d, maxJoints> first;
    std::array<Eigen::Matrix3d, maxJoints> rotational;
    for (size_t k = 0; k < size_t(m_dof); ++k) {
        const double *p = pi.data() + 10 * k;
        mass[k] = p[0];
        first[k] = Eigen::Vector3d(p[1], p[2], p[3]);
        rotational[k] = inertiaOf(p);
    }
    for (size_t k = size_t(m_dof) - 1; k > 0; --k) {
        const Eigen::Matrix3d &r = pl[k].r;
        const Eigen::Vector3d &p = pl[k].p;
        const Eigen::Vector3d rh = times(r, first[k]);
        const double m = mass[k];
        Eigen::Matrix3d moved = r * rotational[k] * r.transpose();
        moved.diagonal().array() += m * p.squaredNorm() + 2.0 * p.dot(rh);
        moved.noalias() -= m * p * p.transpose() + p * rh.transpose() + rh * p.transpose();
        mass[k - 1] += m;
        first[k - 1] += rh + m * p;
        rotational[k - 1] += moved;
    }
    for (size_t k = 0; k < size_t(m_dof); ++k) {
        // The force [f; n] that moving joint k alone at unit rate needs of its subtree, in
        // frame k: revolute about z, f = z x h, n = I z; prismatic along z, f = m z, n = h x z.
        const Eigen::Vector3d &z = m_axis[k];
        Eigen::Vector3d f = m_prismatic[k] ? Eigen::Vector3d(mass[k] * z) : z.cross(first[k]);
        Eigen::Vector3d n = m_prismatic[k] ? first[k].cross(z) : times(rotational[k], z);
        out(Eigen::Index(k), Eigen::Index(k)) = z.dot(m_prismatic[k] ? f : n);
        for (size_t j = k; j > 0; --j) { // the same force seen from joint j - 1
            f = times(pl[j].r, f);
            n = times(pl[j].r, n) + pl[j].p.cross(f);
            const double mjk = m_axis[j - 1].dot(m_prismatic[j - 1] ? f : n);
            out(Eigen::Index(j - 1), Eigen::Index(k)) = mjk;
            out(Eigen::Index(k), Eigen::Index(j - 1)) = mjk;
        }
    }
}

double ChainDynamics::potentialEnergy(const VectorRef &q, const VectorRef &pi) const
{
    const std::vector<Eigen::Isometry3d> poses = framePoses(q);
    Eigen::Vector3d firstMoment = Eigen::Vector3d::Zero(); // sum of m * (centre of mass)
    for (int k = 0; k < m_dof; ++k) {
        const double *p = pi.data() + 10 * k;
        const Eigen::Isometry3d &t = poses[size_t(k)];
        firstMoment += p[0] * t.translation() + t.linear() * Eigen::Vector3d(p[1], p[2], p[3]);
    }
    return -m_chain.gravity.dot(firstMoment);
}

std::vector<Eigen::Isometry3d> ChainDynamics::framePoses(const VectorRef &q) const
{
    Placements pl;
    place(q, pl);
    std::vector<Eigen::Isometry3d> poses(size_t(m_dof), Eigen::Isometry3d::Identity());
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    for (size_t k = 0; k < size_t(m_dof); ++k) {
        Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
        local.linear() = pl[k].r;
        local.translation() = pl[k].p;
        t = t * local;
        poses[k] = t;
    }
    return poses;
}

} // namespace learnid
