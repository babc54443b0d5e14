#pragma once

#include <Eigen/Core>
#include <QByteArray>
#include <QString>

namespace learnid {

/// A recorded production path: joint angles at strictly increasing times.
struct PathSamples
{
    Eigen::VectorXd t; ///< [s] (N)
    Eigen::MatrixXd q; ///< [rad] (n x N), sample k in column k

    int dof() const { return int(q.rows()); }
    int samples() const { return int(q.cols()); }
};

/// A production path file as CSV: a header line `t,q1,...,qn`, then one row per sample: the
/// time [s] and the n joint angles [rad], comma separated. Lines whose first non-blank character
/// is '#' are comments and blank lines are skipped, anywhere; \r\n is accepted, spaces around
/// fields are ignored, a UTF-8 byte order mark is skipped. Numbers as QByteArray::toDouble reads
/// them (C locale).
///
/// Throws Error "<sourceName>: line <L>, column <C> (<name>): <problem>" (column: the field's
/// number, 1 for t) for a wrong header, a wrong number of fields, a field that is not a number
/// or not finite, a time that does not increase, and "<sourceName>: line <L>: ..." for an empty
/// file or fewer than 4 samples. With expectedJoints > 0, a header with another number of
/// joints is refused too.
PathSamples readPathCsv(const QByteArray &csv, const QString &sourceName, int expectedJoints = 0);

/// readFile() then readPathCsv() with the path as the source name; a missing or unreadable
/// file throws Error naming the path and the reason.
PathSamples readPathCsvFile(const QString &path, int expectedJoints = 0);

/// The path as readPathCsv() reads it back bit for bit: header, one row per sample, numbers in
/// the shortest form that reads back to the same double, lines ending with \n. Throws Error
/// when t and q differ in length.
QByteArray pathCsv(const PathSamples &path);

} // namespace learnid
