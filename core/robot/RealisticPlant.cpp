#include "robot/RealisticPlant.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

/// h * lambda of the fastest spring mode per RK4 step (see the class comment).
constexpr double kStepTimesRate = 0.5;
/// Fixed-point iterations for the link's sag on its springs at rest (|dg/dq| / K << 1).
constexpr int kSagIterations = 8;

} // namespace

RealisticPlant::RealisticPlant(std::shared_ptr<const RobotModel> model, const Vector &truePhi,
                               const JointRealism &realism, double samplePeriod, int minSubsteps)
    : m_model(std::move(model))
    , m_phi(realism.linkParameters.size() > 0 ? realism.linkParameters : truePhi)
    , m_r(realism)
    , m_samplePeriod(samplePeriod)
    , m_minSubsteps(std::max(1, minSubsteps))
    , m_substeps(m_minSubsteps)
    , m_encoderOnMotor(realism.elastic() && !realism.linkSideEncoder)
{
    const int n = m_model->dof();
    m_armature = realism.armature.size() == n ? realism.armature : Vector(Vector::Zero(n));
    if (m_r.coulomb.size() != n)
        m_r.coulomb = Vector::Zero(n);
    if (m_r.damping.size() != n)
        m_r.damping = Vector::Zero(n);
    for (Vector *v : {&m_q, &m_qd, &m_theta, &m_thetad, &m_bias, &m_rhs, &m_hold, &m_spring, &m_sq,
                      &m_sqd, &m_st, &m_std, &m_lagged})
        v->setZero(n);
    for (auto &stage : m_k)
        for (Vector &v : stage)
            v.setZero(n);
    m_direction = Vector::Ones(n);
    m_stuck.assign(size_t(n), false);
    m_held.assign(size_t(n), false);
    m_mass.setZero(n, n);
    m_a.setZero(n, n);
    // Allocates the factor once. Not `m_llt = LLT(n)`: Eigen leaves a sized LLT's info unset, and
    // moving it reads that value (UBSan: invalid ComputationInfo).
    m_llt.compute(Eigen::MatrixXd::Identity(n, n));
}

void RealisticPlant::reset(const Eigen::Ref<const Vector> &encoderAngles)
{
    const int n = m_model->dof();
    m_q = encoderAngles;
    m_qd.setZero();
    m_theta = m_q;
    m_thetad.setZero();
    if (m_r.elastic()) {
        // At rest the springs carry the link's static torque g(q) = h(q, 0).
        if (m_encoderOnMotor) {
            for (int i = 0; i < kSagIterations; ++i) {
                m_model->biasTorque(m_q, m_qd, m_phi, m_bias);
                m_q = m_theta - m_bias.cwiseQuotient(m_r.stiffness);
            }
        } else {
            m_model->biasTorque(m_q, m_qd, m_phi, m_bias);
            m_theta = m_q + m_bias.cwiseQuotient(m_r.stiffness);
        }
    }
    for (int j = 0; j < n; ++j)
        m_stuck[size_t(j)] = m_r.stribeck();
    m_direction.setOnes();
    m_lagStarted = false;
    chooseSubsteps();
}

void RealisticPlant::chooseSubsteps()
{
    m_substeps = m_minSubsteps;
    if (!m_r.elastic())
        return;
    m_model->massMatrix(m_q, m_phi, m_mass);
    const Eigen::MatrixXd inverse = m_mass.inverse();
    double fastest = 0.0;
    for (int j = 0; j < m_model->dof(); ++j) {
        const double inverseInertia = inverse(j, j) + 1.0 / m_armature[j];
        const double rate =
            std::sqrt(m_r.stiffness[j] * inverseInertia) + m_r.damping[j] * inverseInertia;
        fastest = std::max(fastest, rate);
    }
    const double needed = std::ceil(m_samplePeriod * fastest / kStepTimesRate);
    m_substeps = std::max(m_minSubsteps, int(std::min(needed, 1e6)));
}

void RealisticPlant::setHeld(int j, bool held)
{
    if (held && !m_held[size_t(j)]) {
        m_qd[j] = 0.0;
        m_thetad[j] = 0.0;
    }
    m_held[size_t(j)] = held;
}

RealisticPlant::Vector RealisticPlant::springTorque() const
{
    if (!m_r.elastic())
        return Vector::Zero(m_model->dof());
    return m_r.stiffness.cwiseProduct(m_theta - m_q) + m_r.damping.cwiseProduct(m_thetad - m_qd);
}

void RealisticPlant::accelerations(const Vector &q, const Vector &qd, const Vector &theta,
                                   const Vector &thetad, const Vector &tau, Vector &qdd,
                                   Vector &thetadd)
{
    const int n = m_model->dof();
    m_model->massMatrix(q, m_phi, m_mass);
    m_model->biasTorque(q, qd, m_phi, m_bias);
    const bool elastic = m_r.elastic();
    if (elastic) {
        m_spring = m_r.stiffness.cwiseProduct(theta - q) + m_r.damping.cwiseProduct(thetad - qd);
        m_rhs = m_spring - m_bias;
    } else {
        m_mass.diagonal() += m_armature;
        m_rhs = tau - m_bias;
    }
    m_a = m_mass;
    m_hold = m_rhs;
    for (int j = 0; j < n; ++j) {
        if (constrained(j)) {
            m_a.row(j).setZero();
            m_a.col(j).setZero();
            m_a(j, j) = 1.0;
            m_hold[j] = 0.0;
        } else if (m_r.stribeck()) {
            const double v = qd[j] / m_r.stribeckVelocity;
            const double fc = m_r.coulomb[j];
            m_hold[j] -= (fc + (m_r.staticFriction[j] - fc) * std::exp(-v * v)) * m_direction[j];
        }
    }
    m_llt.compute(m_a);
    qdd = m_llt.solve(m_hold);
    // The torque the constraint supplies at a stuck joint (the friction that holds it).
    m_hold.noalias() = m_rhs - m_mass * qdd;
    if (elastic) {
        for (int j = 0; j < n; ++j)
            thetadd[j] = m_held[size_t(j)] ? 0.0 : (tau[j] - m_spring[j]) / m_armature[j];
    }
}

void RealisticPlant::updateStiction(const Vector &tau)
{
    const int n = m_model->dof();
    bool anyStuck = false;
    for (int j = 0; j < n; ++j) {
        if (m_stuck[size_t(j)] && !m_held[size_t(j)])
            anyStuck = true;
        else if (m_qd[j] != 0.0)
            m_direction[j] = m_qd[j] > 0.0 ? 1.0 : -1.0;
    }
    if (!anyStuck)
        return;
    accelerations(m_q, m_qd, m_theta, m_thetad, tau, m_sqd, m_std);
    for (int j = 0; j < n; ++j) {
        if (m_stuck[size_t(j)] && std::abs(m_hold[j]) > m_r.staticFriction[j]) {
            m_stuck[size_t(j)] = false; // breaks away in the direction of the holding torque
            m_direction[j] = m_hold[j] > 0.0 ? 1.0 : -1.0;
        }
    }
}

void RealisticPlant::rk4Step(const Vector &tau, double h)
{
    // m_k[s] = {q', q'', theta', theta''} of stage s.
    const double c[4] = {0.0, 0.5 * h, 0.5 * h, h};
    for (int s = 0; s < 4; ++s) {
        if (s == 0) {
            m_sq = m_q;
            m_sqd = m_qd;
            m_st = m_theta;
            m_std = m_thetad;
        } else {
            m_sq = m_q + c[s] * m_k[s - 1][0];
            m_sqd = m_qd + c[s] * m_k[s - 1][1];
            m_st = m_theta + c[s] * m_k[s - 1][2];
            m_std = m_thetad + c[s] * m_k[s - 1][3];
        }
        m_k[s][0] = m_sqd;
        m_k[s][2] = m_std;
        accelerations(m_sq, m_sqd, m_st, m_std, tau, m_k[s][1], m_k[s][3]);
    }
    const double w = h / 6.0;
    m_q += w * (m_k[0][0] + 2.0 * m_k[1][0] + 2.0 * m_k[2][0] + m_k[3][0]);
    m_qd += w * (m_k[0][1] + 2.0 * m_k[1][1] + 2.0 * m_k[2][1] + m_k[3][1]);
    if (m_r.elastic()) {
        m_theta += w * (m_k[0][2] + 2.0 * m_k[1][2] + 2.0 * m_k[2][2] + m_k[3][2]);
        m_thetad += w * (m_k[0][3] + 2.0 * m_k[1][3] + 2.0 * m_k[2][3] + m_k[3][3]);
    }
}

void RealisticPlant::advance(const Eigen::Ref<const Vector> &tauHeld)
{
    const Vector tau = tauHeld;
    const double h = m_samplePeriod / m_substeps;
    const int n = m_model->dof();
    for (int s = 0; s < m_substeps; ++s) {
        if (m_r.stribeck())
            updateStiction(tau);
        rk4Step(tau, h);
        if (!m_r.stribeck())
            continue;
        for (int j = 0; j < n; ++j) {
            // Reached or crossed zero velocity: stick (the next substep may let it go).
            if (!constrained(j) && m_qd[j] * m_direction[j] <= 0.0) {
                m_qd[j] = 0.0;
                m_stuck[size_t(j)] = true;
            }
        }
    }
}

void RealisticPlant::measureTorque(const Eigen::Ref<const Vector> &command, Eigen::Ref<Vector> out)
{
    const Vector raw = m_r.elastic() ? springTorque() : Vector(command);
    if (m_r.sensorLag > 0.0) {
        // The lag's exact response to the raw torque held over one sample period.
        const double alpha = 1.0 - std::exp(-m_samplePeriod / m_r.sensorLag);
        if (!m_lagStarted)
            m_lagged = raw;
        else
            m_lagged += alpha * (raw - m_lagged);
        m_lagStarted = true;
        out = m_lagged;
    } else {
        out = raw;
    }
    if (m_r.sensorOffset.size() == out.size())
        out += m_r.sensorOffset;
}

} // namespace learnid
