#pragma once

#include "control/StateSpace.h"
#include "types/ControllerSettings.h"

#include <Eigen/Core>
#include <vector>

namespace learnid {

/// Continuous state space of one joint's PID with filtered derivative (3 states: the integral
/// of e and the two states of lambda^2 s/(s + lambda)^2); input e [rad], output u [N m].
StateSpace pidStateSpace(double kp, double ki, double kd, double lambda);

/// The discrete joint controllers of a ControllerSettings: one Tustin-discretised PID per joint.
class PidController
{
public:
    explicit PidController(const ControllerSettings &settings);

    int dof() const { return int(m_joints.size()); }
    /// The discrete state space of joint j (for the closed-loop stability check).
    const StateSpace &joint(int j) const { return m_discrete[j]; }

    void reset();
    /// u[k] from e[k] = q_d[k] - q[k] (n), then advances the state.
    void step(const Eigen::Ref<const Eigen::VectorXd> &e, Eigen::Ref<Eigen::VectorXd> u);

private:
    struct Joint
    {
        Eigen::Matrix3d a;
        Eigen::Vector3d b;
        Eigen::RowVector3d c;
        double d = 0.0;
        Eigen::Vector3d x = Eigen::Vector3d::Zero();
    };
    std::vector<Joint> m_joints;
    std::vector<StateSpace> m_discrete;
};

} // namespace learnid
