#pragma once

#include "model/SerialChain.h"

#include <Eigen/Core>
#include <array>

namespace learnid {

/// Rigid-body dynamics of a serial chain in its standard inertial parameters pi (10 per link,
/// link k's at 10 k, SerialChain.h's order), gravity included:
///   tau = M(q, pi) qdd + c(q, qd, pi) + g(q, pi) = Y(q, qd, qdd) pi.
/// Newton-Euler in link frames (the body-regressor form pinocchio uses): velocities and
/// accelerations outward, each body's wrench at its frame origin (linear in its pi), wrenches
/// inward projected on the joint axes. The mass matrix by the composite-rigid-body algorithm.
/// Everything works on the stack: no allocation, chains of up to maxJoints joints.
/// q [rad or m] (n), qd (n), qdd (n), tau [N m or N] (n).
class ChainDynamics
{
public:
    static constexpr int maxJoints = 16;
    using VectorRef = Eigen::Ref<const Eigen::VectorXd>;

    /// Throws Error when the chain has no joint or more than maxJoints.
    explicit ChainDynamics(const SerialChain &chain);

    int dof() const { return m_dof; }
    int inertialCount() const { return 10 * m_dof; }
    const SerialChain &chain() const { return m_chain; }

    /// Y(q, qd, qdd) into out (n x 10 n); gravity enters through the base's acceleration -g.
    void regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                   Eigen::Ref<Eigen::MatrixXd> out) const;
    /// tau = Y pi into out (n) by recursive Newton-Euler; gravityScale 0 leaves gravity out.
    void inverseDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                         const VectorRef &pi, Eigen::Ref<Eigen::VectorXd> out,
                         double gravityScale = 1.0) const;
    /// M(q, pi) into out (n x n).
    void massMatrix(const VectorRef &q, const VectorRef &pi, Eigen::Ref<Eigen::MatrixXd> out) const;
    /// massMatrix() and the bias torque inverseDynamics(q, qd, 0) at once, the joint frames
    /// placed once: what forward dynamics needs at every step of the simulator.
    void massMatrixAndBias(const VectorRef &q, const VectorRef &qd, const VectorRef &pi,
                           Eigen::Ref<Eigen::MatrixXd> mass,
                           Eigen::Ref<Eigen::VectorXd> bias) const;
    /// -sum_k m_k g . (position of link k's centre of mass) [J]: U(q, pi), linear in pi.
    double potentialEnergy(const VectorRef &q, const VectorRef &pi) const;
    /// Pose of each moving joint's frame in the base link's frame (n).
    std::vector<Eigen::Isometry3d> framePoses(const VectorRef &q) const;

private:
    struct Placement // frame k in frame k-1 at the current q
    {
        Eigen::Matrix3d r;
        Eigen::Vector3d p;
    };
    using Placements = std::array<Placement, maxJoints>;
    void place(const VectorRef &q, Placements &out) const;
    void massMatrixPlaced(const Placements &pl, const VectorRef &pi,
                          Eigen::Ref<Eigen::MatrixXd> out) const;
    void inverseDynamicsPlaced(const Placements &pl, const VectorRef &qd, const VectorRef &qdd,
                               const VectorRef &pi, Eigen::Ref<Eigen::VectorXd> out,
                               double gravityScale) const;

    SerialChain m_chain;
    int m_dof = 0;
    std::array<Eigen::Matrix3d, maxJoints> m_originRotation;
    std::array<Eigen::Vector3d, maxJoints> m_originTranslation;
    std::array<Eigen::Vector3d, maxJoints> m_axis;
    /// A revolute joint's placement R0 Rot(a, q) = F + cos q C + sin q S with F = R0 a a^T,
    /// C = R0 - F and S = R0 [a]x (Rodrigues' formula, precomputed per joint).
    std::array<Eigen::Matrix3d, maxJoints> m_rotationFixed, m_rotationCos, m_rotationSin;
    std::array<bool, maxJoints> m_prismatic{};
};

} // namespace learnid
