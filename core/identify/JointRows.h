#pragma once

#include "model/RobotModel.h"

#include <Eigen/Core>
#include <vector>

namespace learnid {

class TaskThreads;

/// One joint's least-squares rows over a record, stored by their columns that are not
/// identically zero: in a serial chain joint j's torque has no term of the links before j nor of
/// the other joints' friction, so the last joints' rows are mostly zero columns.
struct JointRows
{
    /// N x c: column s is the signal of W(j, columns[s]) over the rows.
    Eigen::MatrixXd a;
    /// The parameter index of each column of a, ascending; every other column is exactly 0.
    std::vector<int> columns;
};

/// The joints' indices, the joints with the most columns first (their Gram matrices cost the
/// most), in index order among equals: the order to hand joints to threads so they end together.
std::vector<int> jointsLargestFirst(const std::vector<JointRows> &rows);

/// The mid-sample rows of every joint (dof), row k = (W(q_k, qd_k, qdd_k) + W(q_k+1, ...)) / 2
/// for k < N - 1, from q [rad], qd [rad/s], qdd [rad/s^2] (dof x N, N >= 2). A column is kept
/// when its signal is nonzero (or not finite) at some sample. The regressor is evaluated a few
/// samples at a time (the whole series, dof m x N, would be as large as all the rows together),
/// on every one of `threads` (model.regressorSeries() runs on several at once: a model does not
/// change after construction); the rows do not depend on their number. Throws Error when the
/// sizes do not match.
std::vector<JointRows> midSampleJointRows(const RobotModel &model, const Eigen::MatrixXd &q,
                                          const Eigen::MatrixXd &qd, const Eigen::MatrixXd &qdd,
                                          TaskThreads &threads);

} // namespace learnid
