#pragma once

namespace learnid {

/// Settings shared by the learning laws.
struct EstimatorSettings
{
    double rho = 40.0;           ///< bandwidth of F(s) = rho^3/(s + rho)^3 [rad/s]
    double rankTolerance = 1e-3; ///< relative singular value below which a direction is kept
    bool accumulate = true;      ///< improved law: fit all valid trials so far, not the last
};

} // namespace learnid
