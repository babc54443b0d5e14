// ChainDynamics: the mass matrix by the composite-rigid-body algorithm, with the bias torque
// from the same placement of the frames, and the chain's poses and potential energy.

#include "model/ChainDynamics.h"
#include "model/ChainProducts.h"

namespace learnid {

using chainproducts::inertiaOf;
using chainproducts::times;

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
