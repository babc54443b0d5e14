#pragma once

#include <Eigen/Core>
#include <QString>

namespace learnid {

// Range checks shared by the scenario and parameter file validation. Each throws
// learnid::Error("<key path>: <what is wrong and what is allowed>, got <value>"). Used by the io
// library only.

enum class Bounds {
    Closed,   ///< [lo, hi]
    LeftOpen, ///< (lo, hi]
    Open,     ///< (lo, hi)
};

void checkFinite(const QString &path, double value);
/// Finite and within float's range: values written to a drive's REAL32 objects.
void checkFitsReal32(const QString &path, double value);
void checkPositive(const QString &path, double value);
void checkNonNegative(const QString &path, double value);
/// >= 0 or +inf; the files write +inf as null (a figure that is unbounded or not determined).
void checkNonNegativeOrInfinite(const QString &path, double value);
void checkInterval(const QString &path, double value, double lo, double hi, Bounds bounds);
void checkIntegerRange(const QString &path, qint64 value, qint64 lo, qint64 hi);

/// The number of entries of a vector; what says what they are, e.g. "one per joint of paper-2link".
void checkLength(const QString &path, Eigen::Index size, Eigen::Index expected,
                 const QString &what);

enum class EntryRule { Finite, Positive, NonNegative, NonNegativeOrInfinite };
/// Length, then every entry ("path[i]") by rule.
void checkVector(const QString &path, const Eigen::VectorXd &values, Eigen::Index expected,
                 const QString &what, EntryRule rule);

} // namespace learnid
