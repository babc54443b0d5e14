#pragma once

// Internal to plausibleEstimate() (PlausibleEstimate.h): one Ceres solve of its problem at given
// weights, from given values.

#include "model/PlausibleEstimate.h"

#include <QString>
#include <vector>

namespace learnid::detail {

/// The prior's weights: per link its divergences' (gamma_l), per joint term its residual's
/// scale (w c_i).
struct PlausibleWeights
{
    std::vector<double> links;
    Eigen::VectorXd terms;
};

/// What one solve did.
struct PlausibleStage
{
    int iterations = 0;
    bool converged = false;
    double finalCost = 0.0; ///< the whole cost (data and prior)
    QString report;         ///< Ceres' one-line summary
};

/// Minimises plausibleEstimate()'s cost at weights over links (each link's 10 standard
/// parameters) and termValues (the joint terms), starting from their values (strictly inside
/// every barrier); prior the prior's links.
PlausibleStage solvePlausibleStage(const PlausibleProblem &problem,
                                   const std::vector<Vector10d> &prior,
                                   const PlausibleWeights &weights, std::vector<Vector10d> &links,
                                   Eigen::VectorXd &termValues);

} // namespace learnid::detail
