#pragma once

#include "model/RobotModel.h"
#include "model/TwoLinkArm.h"
#include "model/TwoLinkDynamics.h"
#include "robot/JointRealism.h"
#include "robot/RealisticPlant.h"

#include <Eigen/Core>
#include <QtGlobal>
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

namespace learnid {

/// How the simulated robot measures (encoder quantisation of q, white noise on tau) and what its
/// joints have beyond the rigid-body model (realism: friction, rotor inertia, elasticity, the
/// torque sensor's offset and lag).
struct MeasurementOptions
{
    qint64 encoderCounts = 0; ///< counts per revolution; 0 = ideal angle measurement
    double torqueNoise = 0.0; ///< standard deviation of torque noise as a fraction of the limit
    quint64 seed = 1;         ///< noise seed; trial i of a robot uses (seed, firstNoiseStream + i)
    /// The first noise stream of a robot's trials: two robots of one seed that stand for one
    /// machine (with and without its payload) draw disjoint streams, as its runs on one day do.
    /// std::seed_seq keeps 32 bits of each word: streams are below 2^32.
    quint64 firstNoiseStream = 0;
    int substeps = 10;    ///< RK4 steps per sample period (0.2 ms at Ts = 2 ms)
    JointRealism realism; ///< off by default: the rigid-body model of the true parameters
};

/// The physics of a simulated arm, one sample period at a time: the state q [rad], qd [rad/s]
/// (n), the true parameters, the encoder quantisation of the measured angles, the torque noise
/// of the measured torques and the RK4 integration over a sample period with the torque held.
/// Shared by SimulatedRobot (the whole trial in one loop) and the CAN drive simulator (one
/// sample per SYNC), so both move the same arm. N is the compile-time joint count (2 for the
/// paper's arm, where the simulator's speed matters) or Eigen::Dynamic; every member is inline
/// so that the hot loop of SimulatedRobot keeps fixed-size vectors and no call overhead.
///
/// A joint may be braked: it keeps its angle and has zero velocity, whatever the torque (the
/// other joints move on with the braked joint's state reset after every RK4 step; this neglects
/// the brake's reaction on them, which only matters while some joints are powered and others
/// not).
template <int N = Eigen::Dynamic> class ArmSimulation
{
public:
    using Vector = Eigen::Matrix<double, N, 1>;

    /// samplePeriod: Ts [s]; noiseStream: which noise sequence of options.seed to draw (trial i
    /// of a SimulatedRobot uses i). The arm starts at rest at q = 0.
    ArmSimulation(std::shared_ptr<const RobotModel> model, const Eigen::VectorXd &truePhi,
                  const MeasurementOptions &options, double samplePeriod, quint64 noiseStream = 0)
        : m_model(std::move(model))
        , m_phi(truePhi)
        , m_options(options)
        , m_substeps(std::max(1, options.substeps))
        , m_h(samplePeriod / m_substeps)
        , m_countAngle(options.encoderCounts > 0 ? 2.0 * M_PI / double(options.encoderCounts) : 0.0)
        , m_normal(0.0, 1.0)
        , m_twoLink(dynamic_cast<const TwoLinkArm *>(m_model.get()) != nullptr)
    {
        std::seed_seq seq{quint64(options.seed), quint64(noiseStream)};
        m_rng.seed(seq);
        const int n = m_model->dof();
        m_q = Vector::Zero(n);
        m_qd = Vector::Zero(n);
        m_braked = Eigen::Matrix<bool, N, 1>::Constant(n, false);
        m_heldQ = Vector::Zero(n);
        if (options.realism.any()) {
            m_plant = std::make_unique<RealisticPlant>(m_model, m_phi, options.realism,
                                                       samplePeriod, m_substeps);
        }
    }

    int dof() const { return int(m_q.size()); }
    const RobotModel &model() const { return *m_model; }
    const Eigen::VectorXd &trueParameters() const { return m_phi; }
    /// Another arm from now on (a payload mounted or taken off, between trials): its true
    /// parameters; the arm stays where it is, at rest (realistic joints settle again there).
    void setTrueParameters(const Eigen::VectorXd &truePhi)
    {
        m_phi = truePhi;
        m_qd.setZero();
        if (m_plant) {
            const Eigen::VectorXd encoders = m_plant->encoderAngles();
            m_plant = std::make_unique<RealisticPlant>(m_model, m_phi, m_options.realism,
                                                       samplePeriod(), m_substeps);
            m_plant->reset(encoders);
            syncFromPlant();
        }
    }
    const MeasurementOptions &options() const { return m_options; }
    double samplePeriod() const { return m_h * m_substeps; }

    /// The arm at rest with its encoders reading q0 [rad] (n) (with elastic joints and motor-side
    /// encoders the link hangs on its springs below that: RealisticPlant::reset).
    void reset(const Eigen::Ref<const Eigen::VectorXd> &q0)
    {
        m_q = q0;
        m_qd.setZero();
        m_heldQ = m_q;
        if (m_plant) {
            m_plant->reset(q0);
            syncFromPlant();
        }
    }
    /// The realistic joints' plant, or nullptr when the options have none (JointRealism).
    const RealisticPlant *plant() const { return m_plant.get(); }
    const Vector &q() const { return m_q; }
    const Vector &qd() const { return m_qd; }

    /// The angle of one encoder count [rad]; 0 for an ideal encoder.
    double countAngle() const { return m_countAngle; }
    /// The measured angles: q rounded to whole encoder counts (q itself for an ideal encoder).
    template <typename Out> void measureAngles(Out &&out) const
    {
        if (m_plant) {
            const Eigen::VectorXd &angles = m_plant->encoderAngles();
            if (m_countAngle > 0.0)
                out = (angles / m_countAngle).array().round() * m_countAngle;
            else
                out = angles;
            return;
        }
        if (m_countAngle > 0.0)
            out = (m_q / m_countAngle).array().round() * m_countAngle;
        else
            out = m_q;
    }
    /// The torque sensor's reading [N m] (n) at this sample while the drive commands command:
    /// the command itself on rigid joints, the spring torque on elastic ones, through the
    /// sensor's lag and offset (RealisticPlant::measureTorque). Noise is added apart.
    template <typename Command, typename Out> void measureTorques(const Command &command, Out &&out)
    {
        if (m_plant) {
            Eigen::VectorXd reading(dof());
            m_plant->measureTorque(command, reading);
            out = reading;
        } else {
            out = command;
        }
    }
    /// The encoder count of joint j for an encoder of countAngle [rad] per count (the nearest
    /// whole count to q_j).
    qint64 encoderCount(int j, double countAngle) const
    {
        const double angle = m_plant ? m_plant->encoderAngles()[j] : m_q[j];
        return qint64(std::llround(angle / countAngle));
    }

    /// Adds the measurement noise to measured torques tau [N m] (n): standard deviation
    /// options.torqueNoise * limit_j, drawn joint by joint from this simulation's stream.
    template <typename Tau, typename Limit> void addTorqueNoise(Tau &&tau, const Limit &limit)
    {
        if (m_options.torqueNoise <= 0.0)
            return;
        for (int j = 0; j < dof(); ++j)
            tau[j] += m_options.torqueNoise * limit[j] * m_normal(m_rng);
    }

    /// Brakes joint j (it holds its current angle, zero velocity) or releases it.
    void setBraked(int j, bool braked)
    {
        if (braked && !m_braked[j]) {
            m_heldQ[j] = m_q[j];
            m_qd[j] = 0.0;
        }
        m_braked[j] = braked;
        m_anyBraked = m_braked.any();
        if (m_plant)
            m_plant->setHeld(j, braked);
    }
    bool braked(int j) const { return m_braked[j]; }

    /// Advances the arm by one sample period under tau [N m] (n) held constant: options.substeps
    /// RK4 steps of the true dynamics. The paper's 2-link arm takes an inline path (no virtual
    /// call per step, one sin/cos per sample period: twolink::rk4Steps); it moves the arm as
    /// RobotModel::rk4Step does, to rounding.
    template <typename Tau> void integrate(const Tau &tau)
    {
        if (m_plant) {
            m_plant->advance(tau);
            syncFromPlant();
            return;
        }
        if (m_twoLink && !m_anyBraked) {
            const double t[2] = {tau[0], tau[1]};
            twolink::rk4Steps(m_q.data(), m_qd.data(), t, m_phi.data(), m_h, m_substeps);
            return;
        }
        for (int s = 0; s < m_substeps; ++s) {
            m_model->rk4Step(m_q, m_qd, tau, m_phi, m_h);
            if (m_anyBraked)
                holdBrakedJoints();
        }
    }

private:
    void syncFromPlant()
    {
        m_q = m_plant->q();
        m_qd = m_plant->qd();
    }
    void holdBrakedJoints()
    {
        for (int j = 0; j < dof(); ++j) {
            if (m_braked[j]) {
                m_q[j] = m_heldQ[j];
                m_qd[j] = 0.0;
            }
        }
    }

    std::shared_ptr<const RobotModel> m_model;
    Eigen::VectorXd m_phi;
    MeasurementOptions m_options;
    int m_substeps;
    double m_h;
    double m_countAngle;
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_normal;
    Vector m_q;
    Vector m_qd;
    Eigen::Matrix<bool, N, 1> m_braked;
    Vector m_heldQ;
    bool m_anyBraked = false;
    bool m_twoLink; ///< the model is the paper's 2-link arm (TwoLinkArm)
    std::unique_ptr<RealisticPlant> m_plant;
};

} // namespace learnid
