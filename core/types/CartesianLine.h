#pragma once

#include <Eigen/Core>
#include <cmath>

namespace learnid {

/// A straight Cartesian line traversed with quintic time scaling
/// s(u) = 10u^3 - 15u^4 + 6u^5, u = t / T (zero velocity and acceleration at both ends).
struct CartesianLine
{
    Eigen::Vector2d start{0.5, 0.5}; ///< [m]
    double length = 0.5;             ///< [m]
    double directionDeg = 135.0;     ///< [deg] from the base x axis

    Eigen::Vector2d direction() const
    {
        const double a = directionDeg * M_PI / 180.0;
        return {std::cos(a), std::sin(a)};
    }
    Eigen::Vector2d end() const { return start + length * direction(); }
};

} // namespace learnid
