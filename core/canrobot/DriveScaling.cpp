#include "canrobot/DriveScaling.h"

#include <cmath>
#include <limits>

namespace learnid {

double DriveScaling::radPerIncrement() const
{
    return 2.0 * M_PI * double(revolutions) / double(increments);
}

qint32 DriveScaling::toIncrements(double rad) const
{
    const double v = std::round(rad / radPerIncrement());
    if (!std::isfinite(v))
        return 0;
    return qint32(
        qBound<double>(std::numeric_limits<qint32>::min(), v, std::numeric_limits<qint32>::max()));
}

qint16 DriveScaling::toPermille(double newtonMetre) const
{
    const double v = std::round(newtonMetre / newtonMetrePerPermille());
    if (!std::isfinite(v))
        return 0;
    return qint16(
        qBound<double>(std::numeric_limits<qint16>::min(), v, std::numeric_limits<qint16>::max()));
}

} // namespace learnid
