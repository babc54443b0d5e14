#pragma once

#include <Eigen/Core>

namespace learnid {

/// When within its sample the model torque of a trial's feedforward is taken. The controller
/// holds the torque of sample k over [t_k, t_k + Ts) (a zero-order hold), so the torque at t_k
/// comes on average Ts / 2 early: SampleInstant is the paper's tau_f(t_k); MidSample takes
/// tau_f(t_k + Ts / 2), the hold interval's mean torque to second order in Ts, which removes the
/// hold's first-order tracking error (docs/method.md §1).
enum class FeedforwardTime { SampleInstant, MidSample };

/// Joint PID gains of the robot controller (paper eq. 24):
///   u = kp e + ki integral(e) dt + kd lambda^2 s / (s + lambda)^2 e,  e = q_d - q [rad],
/// u [N m], sampled every samplePeriod and discretised with Tustin.
struct ControllerSettings
{
    double samplePeriod = 0.002;                      ///< Ts [s]
    Eigen::VectorXd kp = Eigen::Vector2d(4500, 5000); ///< [N m/rad] (n)
    Eigen::VectorXd ki = Eigen::Vector2d(30, 30);     ///< [N m/(rad s)] (n)
    Eigen::VectorXd kd = Eigen::Vector2d(600, 600);   ///< [N m s/rad] (n)
    double lambda = 200.0;                            ///< derivative filter bandwidth [rad/s]
    FeedforwardTime feedforwardTime = FeedforwardTime::SampleInstant;

    int dof() const { return int(kp.size()); }
};

} // namespace learnid
