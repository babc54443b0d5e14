#pragma once

#include <Eigen/Core>

namespace learnid {

/// A desired joint trajectory sampled at t_k = k * samplePeriod, k = 0 .. samples()-1.
/// Column k holds sample k: q [rad], qd [rad/s], qdd [rad/s^2] (dof x samples).
struct JointTrajectory
{
    double samplePeriod = 0.0;
    Eigen::MatrixXd q;
    Eigen::MatrixXd qd;
    Eigen::MatrixXd qdd;

    int dof() const { return int(q.rows()); }
    int samples() const { return int(q.cols()); }
    double duration() const { return samples() > 0 ? (samples() - 1) * samplePeriod : 0.0; }
};

} // namespace learnid
