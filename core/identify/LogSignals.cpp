#include "identify/LogSignals.h"

#include "identify/FilteringEstimator.h"
#include "identify/SensorLag.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(LogSignals)
};

} // namespace

double filterSettlingTime(double rho)
{
    return 12.0 / rho;
}

Eigen::Index FilteredLog::keptSamples() const
{
    const Eigen::Index inside = q.cols() - 2 * cut;
    return inside > 0 ? (inside - 1) / stride + 1 : 0;
}

double FilteredLog::keptTime(Eigen::Index k) const
{
    return t0 + double(cut + k * stride) * period;
}

Eigen::MatrixXd FilteredLog::rows(Eigen::MatrixXd series) const
{
    const FilteringEstimator filter(rho, period);
    std::vector<double *> columns;
    for (Eigen::Index c = 0; c < series.cols(); ++c)
        columns.push_back(series.col(c).data());
    filter.zeroPhaseLowPassInPlace(columns, series.rows());
    const Eigen::Index kept = keptSamples();
    Eigen::MatrixXd out(kept, series.cols());
    for (Eigen::Index k = 0; k < kept; ++k)
        out.row(k) = series.row(cut + k * stride);
    return out;
}

FilteredLog filterLog(const UniformLog &log, const LogFilterSettings &settings)
{
    if (!(settings.rho > 0.0) || !std::isfinite(settings.rho) || !(settings.derivativeRho > 0.0) ||
        !std::isfinite(settings.derivativeRho) || settings.stride < 1 ||
        !(settings.torqueSensorLag >= 0.0) || !std::isfinite(settings.torqueSensorLag))
        throw Error(Text::tr("the log filter needs positive bandwidths, a stride of 1 or more "
                             "and a torque sensor lag of 0 s or more"));
    const bool hasVelocity = log.dq.cols() == log.q.cols() && log.dq.rows() == log.q.rows();
    if (settings.velocity == LogFilterSettings::Velocity::Measured && !hasVelocity) {
        throw Error(
            Text::tr("%1: the log has no measured velocities (dq columns) to use").arg(log.source));
    }
    const double settle = filterSettlingTime(std::min(settings.rho, settings.derivativeRho));
    const Eigen::Index cut = Eigen::Index(std::ceil(settle / log.period));
    const Eigen::Index total = log.q.cols();
    if (total < 2 * cut + 4) {
        throw Error(Text::tr("%1: %2 s of data is too short: the filter (bandwidth %3 rad/s) "
                             "needs %4 s at each end to settle, and some data between")
                        .arg(log.source)
                        .arg(double(total) * log.period, 0, 'g', 3)
                        .arg(std::min(settings.rho, settings.derivativeRho))
                        .arg(settle, 0, 'g', 3));
    }
    const bool measured =
        hasVelocity && settings.velocity != LogFilterSettings::Velocity::FromPositions;
    const int n = log.dof();
    FilteredLog out;
    out.source = log.source;
    out.period = log.period;
    out.t0 = log.t0;
    out.rho = settings.rho;
    out.cut = cut;
    out.stride = settings.stride;
    out.tau = withoutSensorLag(log.tau, log.period, settings.torqueSensorLag);
    out.q.resize(n, total);
    out.qd.resize(n, total);
    out.qdd.resize(n, total);
    const FilteringEstimator filter(settings.derivativeRho, log.period);
    Eigen::VectorXd x(total);
    Eigen::MatrixXd outputs(3, total);
    for (int j = 0; j < n; ++j) {
        x = log.q.row(j).transpose();
        filter.filterInto(x.data(), total, true, outputs.data());
        out.q.row(j) = outputs.row(0);
        if (measured) {
            x = log.dq.row(j).transpose();
            filter.filterInto(x.data(), total, true, outputs.data());
            out.qd.row(j) = outputs.row(0);
            out.qdd.row(j) = outputs.row(1);
        } else {
            out.qd.row(j) = outputs.row(1);
            out.qdd.row(j) = outputs.row(2);
        }
    }
    return out;
}

} // namespace learnid
