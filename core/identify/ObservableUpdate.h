#pragma once

#include <Eigen/Core>
#include <vector>

namespace learnid {

/// Outcome of one least-squares parameter update.
struct ParameterUpdate
{
    Eigen::VectorXd phi;         ///< updated estimate (m)
    Eigen::VectorXd phiStd;      ///< estimated standard deviation per parameter; +inf where kept
    double condition = 0.0;      ///< cond(W^T W) of the regressor, columns scaled to unit norm
    int rank = 0;                ///< observable directions used in the update
    Eigen::VectorXd residualRms; ///< RMS of b - A phi per joint [N m] (n)
    std::vector<bool> observable; ///< per parameter: false when it lies in the kept directions
};

/// Least-squares update that changes only what the data observe (DESIGN.md §1.6):
///   phi = phiPrev + V_r S_r^-1 U_r^T (b - A phiPrev)
/// over the singular directions of A D whose singular value is above tolerance * the largest,
/// D = diag(|phiPrev|) (so singular values compare the torque each direction explains).
/// Directions below the tolerance keep phiPrev's component.
/// A: stacked regressor rows, sample-major: row k*n + j is joint j of sample k (N n x m).
/// b: stacked targets [N m] (N n). n: joints. rowWeight: a weight per row (N n), e.g. the
/// inverse of the residual noise of the row's joint and trial; empty means 1.
/// Tall systems are reduced by a Householder QR before the SVD of the m x m factor.
ParameterUpdate observableUpdate(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 const Eigen::VectorXd &rowWeight = {});

} // namespace learnid
