#pragma once

#include "model/RobotModel.h"
#include "types/JointTrajectory.h"

#include <QStringList>
#include <vector>

namespace learnid {

/// What a path lets the trials learn, before the robot moves: the regressor along the path,
/// its columns scaled as the learning laws scale them (by the estimate, or to unit norm where
/// the estimate is 0), and its singular directions. A direction is observed when its singular
/// value is above rankTolerance times the largest, as the laws decide it (ObservableUpdate.h).
struct PathIdentifiability
{
    int parameters = 0;     ///< m
    int rank = 0;           ///< observed directions
    double condition = 0.0; ///< largest / smallest observed singular value
    /// Per parameter: the share of its unit direction inside the observed directions, 0 (the
    /// path cannot see it at all) to 1 (it lies in what the path observes).
    std::vector<double> observedShare;

    /// Parameters with a share below 0.5 (mostly unseen), in order.
    std::vector<int> unseen() const;
    /// "the path observes 29 of 57 parameter directions (condition 1.2e+03)" and, if any, the
    /// unseen parameters by name.
    QStringList describe(const RobotModel &model) const;
};

/// The regressor rows of path (every sample's W, up to maxSamples samples evenly spread)
/// reduced to their triangular factor R: ||W_path x|| = ||R x|| for every x (m x m; the rows
/// themselves when there are no more than m). Column norms and singular values are W_path's.
Eigen::MatrixXd pathRegressorFactor(const RobotModel &model, const JointTrajectory &path,
                                    int maxSamples);

/// The identifiability of path for model at the estimate phi (m). Uses up to 4000 samples of
/// the path, evenly spread.
PathIdentifiability pathIdentifiability(const RobotModel &model, const JointTrajectory &path,
                                        const Eigen::VectorXd &phi, double rankTolerance);

} // namespace learnid
