#pragma once

#include "model/RobotModel.h"
#include "robot/JointRealism.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace learnid {

/// The simulated arm with what real joints have beyond the rigid-body model (JointRealism):
/// Stribeck friction with stiction, rotor inertia, elastic joints, and a torque sensor with an
/// offset and a first-order lag. ArmSimulation uses it when any of these is on.
///
/// State: link angles q, qd [rad, rad/s] (n); with elastic joints also the motor angles theta,
/// theta' (n), the motor side carrying the rotor inertia Ia:
///   M(q) q'' + h(q, q') + f(q') = tau_s,   Ia theta'' = tau - tau_s,
///   tau_s = K (theta - q) + D (theta' - q')
/// and with rigid joints (M(q) + diag(Ia)) q'' + h(q, q') + f(q') = tau. h comes from the
/// robot's true parameters (linkParameters), f is the Stribeck excess.
///
/// Integration: classical RK4 at a fixed substep, the drive torque held over each sample.
/// Elastic joints make the system stiff: the substep is chosen at reset() so that h * lambda
/// <= 0.5 for the fastest spring mode, lambda_j = w_j + D_j / J_j with w_j^2 = K_j / J_j,
/// 1/J_j = (M^-1)_jj + 1/Ia_j at the rest pose. RK4's amplitude error per step is about
/// (h w)^6 / 144 and its phase error (h w)^4 / 120: below 1e-4 and 5e-4 there, so the spring
/// oscillates at its own frequency without numerical damping, at a few times the cost of an
/// implicit scheme's single step but with RK4's accuracy for the rigid part.
///
/// Stiction (how the discontinuity is handled numerically): a joint with Stribeck friction is
/// either stuck or sliding, decided at substep boundaries, never inside an RK4 step:
/// - stuck: q'' = 0 and q' = 0 are imposed (the joint is removed from the mass-matrix solve);
///   the friction is whatever torque holds it, and it stays stuck while that torque's
///   magnitude is at most Fs;
/// - sliding: friction (Fc + (Fs - Fc) exp(-(v/vs)^2)) s + Fv v, the direction s fixed over
///   the substep (the sign of q' at its start, or at break-away the sign of the torque that
///   broke it free), so every RK4 stage sees a smooth right-hand side;
/// - when a sliding joint's velocity reaches zero or changes sign in a substep, it is set to
///   zero and the joint sticks (the next boundary lets it go again if the holding torque
///   exceeds Fs). This is Karnopp's model with a zero-width velocity band: a joint at rest
///   stays exactly at rest while |tau| < Fs, at the cost of an O(h) error at each stick event.
/// A braked joint (setHeld) is held the same way without a torque bound (link and motor).
class RealisticPlant
{
public:
    using Vector = Eigen::VectorXd;

    /// truePhi: the robot's true parameters (m); realism with entries for model->dof() joints;
    /// samplePeriod [s]; minSubsteps: the least RK4 steps per sample.
    RealisticPlant(std::shared_ptr<const RobotModel> model, const Vector &truePhi,
                   const JointRealism &realism, double samplePeriod, int minSubsteps);

    /// At rest, in static equilibrium, with the encoder reading encoderAngles [rad] (n): with a
    /// motor-side encoder the link hangs on its springs below the motor angles. Joints with
    /// Stribeck friction start stuck. Chooses the substep.
    void reset(const Eigen::Ref<const Vector> &encoderAngles);
    /// One sample period under the drive torque tau [N m] (n), held.
    void advance(const Eigen::Ref<const Vector> &tau);
    /// The torque reading [N m] (n) at this sample: the drive's torque command (rigid joints) or
    /// the spring torque (elastic), through the sensor's lag, plus its offset. Call once per
    /// sample: the lag advances one sample period with each call.
    void measureTorque(const Eigen::Ref<const Vector> &command, Eigen::Ref<Vector> out);
    /// Brakes joint j (link and motor hold their angles) or releases it.
    void setHeld(int j, bool held);

    const Vector &q() const { return m_q; }
    const Vector &qd() const { return m_qd; }
    const Vector &motorAngles() const { return m_theta; }
    /// What the encoder reads: the motor angles (elastic joints, motor-side encoder) or q.
    const Vector &encoderAngles() const { return m_encoderOnMotor ? m_theta : m_q; }
    /// tau_s [N m] (n) at the current state; zero without elastic joints.
    Vector springTorque() const;
    bool stuck(int j) const { return m_stuck[size_t(j)]; }
    int substeps() const { return m_substeps; }

private:
    void accelerations(const Vector &q, const Vector &qd, const Vector &theta, const Vector &thetad,
                       const Vector &tau, Vector &qdd, Vector &thetadd);
    bool constrained(int j) const { return m_stuck[size_t(j)] || m_held[size_t(j)]; }
    void updateStiction(const Vector &tau);
    void rk4Step(const Vector &tau, double h);
    void chooseSubsteps();

    std::shared_ptr<const RobotModel> m_model;
    Vector m_phi;
    JointRealism m_r;
    double m_samplePeriod;
    int m_minSubsteps;
    int m_substeps;
    bool m_encoderOnMotor;
    Vector m_armature; ///< Ia (n), zeros when none
    Vector m_q, m_qd, m_theta, m_thetad;
    std::vector<bool> m_stuck, m_held;
    Vector m_direction; ///< sliding direction per joint, +-1
    Vector m_lagged;
    bool m_lagStarted = false;
    // working memory of accelerations() and rk4Step()
    Eigen::MatrixXd m_mass, m_a;
    Eigen::LLT<Eigen::MatrixXd> m_llt;
    Vector m_bias, m_rhs, m_hold, m_spring;
    Vector m_k[4][4]; ///< RK4 stages: q', q'', theta', theta'' of each stage
    Vector m_sq, m_sqd, m_st, m_std;
};

} // namespace learnid
