#include "io/ValueChecks.h"

#include "io/JsonReader.h"

#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ValueChecks)
};

} // namespace

void checkFinite(const QString &path, double value)
{
    if (!std::isfinite(value))
        throwAtKey(path, Text::tr("must be a finite number, got %1").arg(describeNumber(value)));
}

void checkFitsReal32(const QString &path, double value)
{
    if (std::isfinite(value) && std::abs(value) <= double(std::numeric_limits<float>::max()))
        return;
    throwAtKey(path, Text::tr("the drives store it as REAL32, so it must be a finite number of at "
                              "most %1 in magnitude, got %2")
                         .arg(double(std::numeric_limits<float>::max()))
                         .arg(describeNumber(value)));
}

void checkPositive(const QString &path, double value)
{
    if (!std::isfinite(value) || !(value > 0.0))
        throwAtKey(path, Text::tr("must be a positive number, got %1").arg(describeNumber(value)));
}

void checkNonNegative(const QString &path, double value)
{
    if (!std::isfinite(value) || !(value >= 0.0))
        throwAtKey(
            path, Text::tr("must be zero or a positive number, got %1").arg(describeNumber(value)));
}

void checkNonNegativeOrInfinite(const QString &path, double value)
{
    if (!(value >= 0.0)) { // also NaN
        throwAtKey(path, Text::tr("must be zero, a positive number or unbounded (null), got %1")
                             .arg(describeNumber(value)));
    }
}

void checkInterval(const QString &path, double value, double lo, double hi, Bounds bounds)
{
    bool ok = std::isfinite(value) && value <= hi;
    QString allowed;
    switch (bounds) {
    case Bounds::Closed:
        ok = ok && value >= lo && value <= hi;
        allowed = Text::tr("must be from %1 to %2");
        break;
    case Bounds::LeftOpen:
        ok = ok && value > lo && value <= hi;
        allowed = Text::tr("must be greater than %1 and at most %2");
        break;
    case Bounds::Open:
        ok = ok && value > lo && value < hi;
        allowed = Text::tr("must be greater than %1 and less than %2");
        break;
    }
    if (!ok) {
        throwAtKey(path, Text::tr("%1, got %2")
                             .arg(allowed.arg(describeNumber(lo), describeNumber(hi)),
                                  describeNumber(value)));
    }
}

void checkIntegerRange(const QString &path, qint64 value, qint64 lo, qint64 hi)
{
    if (value < lo || value > hi)
        throwAtKey(path, Text::tr("must be %1, got %2").arg(integerRangeText(lo, hi)).arg(value));
}

void checkLength(const QString &path, Eigen::Index size, Eigen::Index expected, const QString &what)
{
    if (size != expected) {
        throwAtKey(path, Text::tr("must have %1 entries (%2), got %3")
                             .arg(qint64(expected))
                             .arg(what)
                             .arg(qint64(size)));
    }
}

void checkVector(const QString &path, const Eigen::VectorXd &values, Eigen::Index expected,
                 const QString &what, EntryRule rule)
{
    checkLength(path, values.size(), expected, what);
    for (Eigen::Index i = 0; i < values.size(); ++i) {
        const QString entry = jsonIndexPath(path, int(i));
        switch (rule) {
        case EntryRule::Finite:
            checkFinite(entry, values[i]);
            break;
        case EntryRule::Positive:
            checkPositive(entry, values[i]);
            break;
        case EntryRule::NonNegative:
            checkNonNegative(entry, values[i]);
            break;
        case EntryRule::NonNegativeOrInfinite:
            checkNonNegativeOrInfinite(entry, values[i]);
            break;
        }
    }
}

} // namespace learnid
