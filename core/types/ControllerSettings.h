#pragma once

#include <Eigen/Core>

namespace learnid {

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

    int dof() const { return int(kp.size()); }
};

} // namespace learnid
