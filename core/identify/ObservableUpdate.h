#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace learnid {

/// Outcome of one least-squares parameter update.
struct ParameterUpdate
{
    Eigen::VectorXd phi;          ///< updated estimate (m)
    Eigen::VectorXd phiStd;       ///< estimated standard deviation per parameter; +inf where kept
    double condition = 0.0;       ///< cond(W^T W) of the regressor, columns scaled to unit norm
    int rank = 0;                 ///< observable directions used in the update
    Eigen::VectorXd residualRms;  ///< RMS of b - A phi per joint [N m] (n)
    std::vector<bool> observable; ///< per parameter: false when it lies in the kept directions
};

/// How white torque noise w reached the targets b = ... + H w through a linear filter H acting on
/// each joint's signal (identity for unfiltered rows). Filtered residuals are correlated, so
/// the covariance of the estimate is the sandwich
///   sigma_w^2 (B^T B)^-1 (H^T B)^T (H^T B) (B^T B)^-1,  sigma_w^2 = residual variance / gain.
struct NoiseShaping
{
    double varianceGain = 1.0;         ///< variance of H w over variance of w (sum of h_k^2)
    Eigen::MatrixXd transposedApplied; ///< H^T applied to each column of A, per joint; empty: H = I
};

/// Least-squares update that changes only what the data observe (docs/method.md §2.3):
///   phi = phiPrev + D V_r x,  x = argmin || Wr (b - A phiPrev - A D V_r x) ||
/// V_r: the right singular directions of A D whose singular value is above tolerance * the
/// largest, D = diag(max(|phiPrev|, |scaleFloor|)), so singular values compare the torque each
/// direction explains (scaleFloor, e.g. the prior: a parameter moved near 0 does not freeze).
/// Observability is decided on the unweighted A D (a property of the trajectory, not of the
/// noise weights; with jointLevels, each joint's rows divided by the RMS of its targets);
/// directions below the tolerance keep phiPrev's component, and so do the directions whose
/// standard deviation, in units of D, is above maxRelativeStd (after a partial trial).
/// A: stacked regressor rows, sample-major: row k*n + j is joint j of sample k (N n x m).
/// b: stacked targets [N m] (N n). n: joints. rowWeight: a weight per row (N n), e.g. the
/// inverse of the residual noise of the row's joint and trial; empty means 1.
/// noise: how the torque noise reached b, for the standard deviations (see NoiseShaping).
/// Works on column-scaled Gram matrices (one pass over the rows); tolerance must be >= 1e-6.
ParameterUpdate observableUpdate(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 const Eigen::VectorXd &rowWeight = {},
                                 const struct NoiseShaping &noise = {},
                                 const Eigen::VectorXd &scaleFloor = {},
                                 double maxRelativeStd = std::numeric_limits<double>::infinity(),
                                 bool jointLevels = false);

/// The same update from blocks of rows reduced to their Gram quantities (GramBlock; e.g. one
/// block per trial, each joint's rows weighted by the block's weight of that joint): equal to
/// observableUpdate() of the stacked rows up to rounding, in O(blocks n m^2). The residual RMS
/// and the standard deviations come from the blocks' exact residual expansion.
/// varianceGain: NoiseShaping::varianceGain of the rows (1 when unfiltered); the blocks' shaped
/// Gram matrices, when every block has them, give the covariance sandwich.
ParameterUpdate observableUpdate(const std::vector<const class GramBlock *> &blocks,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 double varianceGain = 1.0, const Eigen::VectorXd &scaleFloor = {},
                                 double maxRelativeStd = std::numeric_limits<double>::infinity(),
                                 bool jointLevels = false);

} // namespace learnid
