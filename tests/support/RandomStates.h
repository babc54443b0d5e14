#pragma once
// Random joint states for comparing two dynamics models: q in [-2, 2] rad, qd in [-1.5, 1.5]
// rad/s, qdd in [-4, 4] rad/s^2, drawn uniformly from a fixed seed.
#include <Eigen/Core>
#include <functional>
#include <random>

namespace learnid::test {

inline void
forRandomStates(int joints, unsigned seed, int count,
                const std::function<void(const Eigen::VectorXd &q, const Eigen::VectorXd &qd,
                                         const Eigen::VectorXd &qdd)> &check)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Eigen::VectorXd q(joints), qd(joints), qdd(joints);
    for (int state = 0; state < count; ++state) {
        for (int j = 0; j < joints; ++j) {
            q[j] = 2.0 * unit(random);
            qd[j] = 1.5 * unit(random);
            qdd[j] = 4.0 * unit(random);
        }
        check(q, qd, qdd);
    }
}

} // namespace learnid::test
