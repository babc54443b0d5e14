#pragma once

#include <Eigen/Core>

namespace learnid {

/// The largest relative difference of x from ref over the parameters, in percent, with its sign:
/// (x_i - ref_i) / |ref_i| * 100 for the i of largest magnitude (entries with ref_i = 0 are
/// skipped). The "relative change" of an estimate from the previous one and the "error against
/// the truth" of the convergence table (CLI and GUI alike).
double largestRelativeDifferencePercent(const Eigen::VectorXd &x, const Eigen::VectorXd &ref);

} // namespace learnid
