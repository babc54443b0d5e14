#pragma once

#include <Eigen/Core>
#include <QString>
#include <vector>

namespace learnid {

/// A robot's recorded joint data, sample k in column k, as read from a log its own controller
/// wrote (io/RobotLogCsv.h). The samples keep the log's own time stamps; identify/UniformLog.h
/// puts them on a uniform grid.
struct RobotLog
{
    QString source;      ///< the file it came from, for messages
    Eigen::VectorXd t;   ///< [s], strictly increasing (N)
    Eigen::MatrixXd q;   ///< n x N joint positions [rad] or [m]
    Eigen::MatrixXd dq;  ///< n x N measured velocities, or 0 x 0 when the log has none
    Eigen::MatrixXd tau; ///< n x N joint torques [N m] or forces [N]
    /// The CSV line number of each sample (1-based, header = line 1), for messages.
    std::vector<int> rows;
    /// Rows dropped because they repeated the previous time stamp with identical values.
    int repeatedSamples = 0;
    /// The CSV line numbers of stale rows, in order: rows with a new time stamp whose values
    /// (every one read) are exactly those of the sample before, a logger that sampled a state
    /// the controller had not updated. They are dropped, so that the grid interpolates across
    /// them as across missing samples (identify/UniformLog.h).
    std::vector<int> staleRows;

    int dof() const { return int(q.rows()); }
    Eigen::Index samples() const { return t.size(); }
    int staleSamples() const { return int(staleRows.size()); }
};

} // namespace learnid
