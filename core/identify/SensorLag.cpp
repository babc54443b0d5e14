#include "identify/SensorLag.h"

#include <cmath>

namespace learnid {

Eigen::MatrixXd withoutSensorLag(const Eigen::MatrixXd &readings, double samplePeriod, double lag)
{
    if (!(lag > 0.0) || readings.cols() < 2)
        return readings;
    const double a = -std::expm1(-samplePeriod / lag); // 1 - exp(-Ts / lag), exact for small Ts
    Eigen::MatrixXd out = readings;
    out.rightCols(readings.cols() - 1) =
        readings.leftCols(readings.cols() - 1) +
        (readings.rightCols(readings.cols() - 1) - readings.leftCols(readings.cols() - 1)) / a;
    return out;
}

} // namespace learnid
