#pragma once

#include "identify/UniformLog.h"

#include <Eigen/Core>
#include <QString>

namespace learnid {

/// How a recorded log is turned into the signals of the fit (docs/identify.md): the improved
/// law's method on recorded data. q is smoothed and differentiated by a zero-phase filter; the
/// regressor Y(q, qd, qdd) is evaluated on that; then Y's columns and the measured torque are
/// filtered alike by F(s)F(-s) of bandwidth rho. Y phi = tau is linear in phi, so filtering both
/// sides with one filter keeps it exact (F[Y] phi = F[tau]) whatever F does to the motion's own
/// frequencies: no bias from a passband that is not flat, only the noise above rho is gone.
struct LogFilterSettings
{
    /// [rad/s] F(s) = rho^3 / (s + rho)^3 (FilteringEstimator) on Y and tau, run forward and
    /// backward. 50 rad/s: the torque sensors' noise above 20 rad/s (3 Hz) is gone
    /// (learnid-bench-realdata, docs/identify.md).
    double rho = 50.0;
    /// [rad/s] The same filter's bandwidth for q -> (q, qd, qdd): encoders are quiet, so it
    /// can be wide, keeping the motion's own frequencies.
    double derivativeRho = 200.0;
    /// Where qd comes from: Measured, the log's velocities (filtered the same way, qdd their
    /// derivative); FromPositions, both from q; Auto, the measured ones when the log has them.
    enum class Velocity { Auto, Measured, FromPositions } velocity = Velocity::Auto;
    /// Keep every stride-th sample after filtering: F removes what a coarser grid would alias
    /// (|F|^2 < 1e-4 above 6 rho), so stride 1 to 4 at 200 Hz changes the fit by noise only.
    int stride = 1;
    /// [s] The torque sensors' first-order lag, undone on the log's grid before the fit
    /// (SensorLag.h; --torque-sensor-lag). 0: the torques are taken as measured.
    double torqueSensorLag = 0.0;
};

/// A log ready for the fit: the motion estimated from q over the whole log, the torque as
/// measured, and how rows are filtered and kept.
struct FilteredLog
{
    QString source;
    double period = 0.0;        ///< [s] of the log's grid
    double t0 = 0.0;            ///< [s] time of sample 0
    Eigen::MatrixXd q, qd, qdd; ///< n x N, zero-phase estimates (derivativeRho)
    Eigen::MatrixXd tau;        ///< n x N, as measured (the sensors' lag undone)
    double rho = 50.0;          ///< the filter of rows()
    Eigen::Index cut = 0;       ///< samples dropped at each end after filtering (settling)
    int stride = 1;

    int dof() const { return int(q.rows()); }
    /// Samples rows() keeps.
    Eigen::Index keptSamples() const;
    /// Time of kept sample k [s].
    double keptTime(Eigen::Index k) const;
    /// series (N x c, one signal per column, sample k in row k) filtered zero-phase by F(rho),
    /// the first and last `cut` samples dropped and every stride-th kept (keptSamples() x c).
    Eigen::MatrixXd rows(Eigen::MatrixXd series) const;
};

/// The time F(s)F(-s) needs to forget how a record starts or ends: 12 / rho (the impulse
/// response of F has decayed to below 1e-3 of its peak).
double filterSettlingTime(double rho);

/// The log's motion estimated zero-phase from q (or the measured velocities), the torque as is.
/// Throws Error naming the log when it is shorter than twice the settling time of the slower
/// filter plus 4 samples, when settings are out of range, or when Measured velocities are asked
/// for and the log has none.
FilteredLog filterLog(const UniformLog &log, const LogFilterSettings &settings);

} // namespace learnid
