#pragma once

// Test support: the KUKA LWR4+ (../shared/data) and paths for payload identification.
//  - holdWristVertical(): the arm bent (shoulder 0.6 rad, elbow 1.2 rad) and the wrist's pitch
//    chosen so that the flange's z axis (joint 7's) points straight up;
//  - wristTurnPath(): from that pose only joint 7 turns: the payload turns about a vertical axis;
//  - richPath(): every joint moves by a multi-sine, the wrist tilting and turning.
// Positions, velocities and accelerations are exact derivatives of sums of sines.

#include "../support/SharedData.h"
#include "model/ChainModel.h"
#include "model/UrdfChain.h"

#include <Eigen/Core>
#include <cmath>
#include <memory>

namespace learnid::test {

inline std::shared_ptr<const ChainModel> kukaArm()
{
    const QString urdf = sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (urdf.isEmpty())
        return {};
    return std::make_shared<const ChainModel>(
        readUrdfChain(urdf), JointTerms{false, true, true, true}, QStringLiteral("lwr4"));
}

/// The bent pose with joint 7's axis vertical: joints 2, 4 and 6 turn about parallel
/// horizontal axes (+-y), so their angles, signed by their axes, must add up to 0.
inline Eigen::VectorXd holdWristVertical(const ChainModel &arm)
{
    Eigen::VectorXd q = Eigen::VectorXd::Zero(7);
    const auto sign = [&](int j) {
        return arm.chain().joints[size_t(j)].axis.y();
    };
    q[1] = 0.6;
    q[3] = 1.2;
    q[5] = -(sign(1) * q[1] + sign(3) * q[3]) / sign(5);
    return q;
}

struct JointPath
{
    Eigen::MatrixXd q, qd, qdd; ///< 7 x N
    double period = 0.002;
};

/// centre + sum_i a(j, i) sin(w(j, i) t + p(j, i)) over `seconds` at `period`.
inline JointPath sinePath(const Eigen::VectorXd &centre, const Eigen::MatrixXd &a,
                          const Eigen::MatrixXd &w, const Eigen::MatrixXd &p, double seconds,
                          double period)
{
    const int n = int(centre.size());
    const auto samples = Eigen::Index(std::lround(seconds / period)) + 1;
    JointPath path;
    path.period = period;
    path.q = centre.replicate(1, samples);
    path.qd = Eigen::MatrixXd::Zero(n, samples);
    path.qdd = Eigen::MatrixXd::Zero(n, samples);
    for (Eigen::Index k = 0; k < samples; ++k) {
        const double t = double(k) * period;
        for (int j = 0; j < n; ++j) {
            for (Eigen::Index i = 0; i < a.cols(); ++i) {
                const double phase = w(j, i) * t + p(j, i);
                path.q(j, k) += a(j, i) * std::sin(phase);
                path.qd(j, k) += a(j, i) * w(j, i) * std::cos(phase);
                path.qdd(j, k) -= a(j, i) * w(j, i) * w(j, i) * std::sin(phase);
            }
        }
    }
    return path;
}

/// Joint 7 alone turns (1.2 rad at 1.3 rad/s and 0.5 rad at 3.1 rad/s), the arm held with the
/// wrist axis vertical.
inline JointPath wristTurnPath(const ChainModel &arm, double seconds = 5.0, double period = 0.002)
{
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(7, 2), w = Eigen::MatrixXd::Ones(7, 2),
                    p = Eigen::MatrixXd::Zero(7, 2);
    a.row(6) << 1.2, 0.5;
    w.row(6) << 1.3, 3.1;
    p.row(6) << 0.0, 1.0;
    return sinePath(holdWristVertical(arm), a, w, p, seconds, period);
}

/// Every joint moves: two sines each (0.25 to 0.45 rad, 1.1 to 4.3 rad/s), around the bent
/// pose.
inline JointPath richPath(const ChainModel &arm, double seconds = 5.0, double period = 0.002)
{
    Eigen::MatrixXd a(7, 2), w(7, 2), p(7, 2);
    for (int j = 0; j < 7; ++j) {
        a.row(j) << 0.45 - 0.02 * j, 0.25;
        w.row(j) << 1.1 + 0.23 * j, 2.9 + 0.2 * j;
        p.row(j) << 0.7 * j, 1.3 * j + 0.4;
    }
    return sinePath(holdWristVertical(arm), a, w, p, seconds, period);
}

} // namespace learnid::test
