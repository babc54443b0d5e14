#pragma once

#include "types/RobotLog.h"

#include <Eigen/Core>
#include <QString>

namespace learnid {

/// A robot's log on a uniform time grid: sample k at t0 + k * period, in column k.
struct UniformLog
{
    QString source;      ///< the file it came from, for messages
    double period = 0.0; ///< [s]
    double t0 = 0.0;     ///< [s] the time of sample 0: the log's first time stamp
    Eigen::MatrixXd q;   ///< n x K joint positions [rad] or [m]
    Eigen::MatrixXd dq;  ///< n x K measured velocities, or 0 x 0 when the log has none
    Eigen::MatrixXd tau; ///< n x K joint torques [N m] or forces [N]

    int dof() const { return int(q.rows()); }
    Eigen::Index samples() const { return q.cols(); }
    double time(Eigen::Index k) const { return t0 + double(k) * period; }
};

/// The longest step between two time stamps that the fit tolerates by default [s]: half the
/// time constant 1/rho of the fit's filter F(s) = rho^3/(s+rho)^3, run forward and backward
/// (LogSignals.h), and at least 2.5 of the log's steps: one lost sample, with the stamps' jitter
/// (a log coarser than the bound is fitted at the resolution it has).
///
/// Why: across a gap g linear interpolation errs by e(t) = x''/2 (t - a)(t - b) (a, b the
/// stamps around it), whose integral is -x'' g^3 / 12. The filter, whose impulse response
/// h = f * f(-t) peaks at h(0) = 3 rho / 16 (|h''| at most rho^3 / 16), spreads that over its
/// width of a few 1/rho: the filtered torque errs by at most rho g^3 |tau''| / 64, the filtered
/// acceleration by rho^3 g^3 |q''| / 192. For a component at the highest frequency the filter
/// keeps (rho; above it |F|^2 < 1/8) that is (rho g)^3 / 64 of its amplitude: at g = 1/(2 rho),
/// 0.2 %, and only within a few 1/rho of the gap. A robot's motion lies far below rho (50 rad/s,
/// 8 Hz): for 1 Hz and an 8.5 ms gap the error is 2e-5 of the torque. The bound follows the
/// filter: a wider one (larger rho) keeps more of the motion and tolerates shorter gaps.
///
/// rho: [rad/s] > 0; logStep: [s] the log's typical step, >= 0.
double defaultMaxGap(double rho, double logStep);

struct ResampleOptions
{
    double period =
        0.0; ///< [s]; 0: the median time step of the log (the nominal step with useNominalTimes)
    /// [s] the longest step allowed between two samples (--max-gap); 0: defaultMaxGap() for
    /// fitBandwidth and the log's step.
    double maxGap = 0.0;
    /// [rad/s] the bandwidth rho of the filter the fit applies (LogFilterSettings::rho), for the
    /// default maxGap.
    double fitBandwidth = 50.0;
    /// Take sample k of the log as taken at t0 + k T, T = (t_N-1 - t0) / (N - 1), and its time
    /// stamp as the noise. Off by default; see resampleUniform().
    bool useNominalTimes = false;
};

/// The log on the grid t0 + k * period, k = 0 .. K-1, covering [t.front(), t.back()]: each
/// signal (q, dq, tau) interpolated linearly between the two samples around each grid time.
///
/// Why linear interpolation is enough for identification: the dynamics to identify (rigid
/// bodies, friction) and the excitation trajectories lie far below the Nyquist frequency of the
/// logs (100 Hz at 200 Hz, 250 Hz at 500 Hz); the error of the interpolant is at most
/// h^2 / 8 * max|q''| for a step h (5 ms and 10 rad/s^2: 3e-5 rad);
/// and the fit later low-pass filters both sides of W(q, qd, qdd) phi = tau with the same
/// zero-phase filter, so what interpolation does to the signals it does alike to regressor and
/// torque. The interpolation is symmetric between the two neighbours: no sample is shifted in
/// time (a zero-order hold would delay everything by half a step). On a grid time that equals a
/// time stamp the sample is taken as it is, bit for bit.
///
/// useNominalTimes: a controller that samples on a fixed tick but stamps the samples with a
/// jittery clock is better read with t_k = t0 + k T. The KUKA LWR4+ logs are of this kind: of
/// their steps more than 0.2 ms off 5 ms (3.2 to 6.8 ms), 29 of 31 are made up within the next
/// one to three steps, the stamps stay within 1.8 ms of t0 + k 5 ms, and around a late stamp
/// the central differences of q match the logged dq 2 to 26 times better with the nominal step
/// than with the stamps. T is the mean step, not the median, so that the log keeps its recorded
/// length (the LWR4+ median, 4.9989 ms against a mean of 5.0000 ms, would drift 5 ms over
/// 25 s). A log whose stamps spread around t0 + k T by more than half a step lost or gained
/// samples (the double pendulum's logs: 2 ms ticks with missed ones of up to 8.4 ms, never
/// made up) and is refused: its stamps are the truth. The option is off by default because only
/// the stamps are right for a log of the second kind, and a log of the first kind read by its
/// stamps is off by at most the jitter, at the few samples around a late stamp.
///
/// Throws Error "<source>: line L: a gap of X ms after the sample at t = Y s, more than the
/// Z ms allowed (--max-gap ...)" for a step between two consecutive time stamps longer than
/// maxGap (naming the stale rows that the reader dropped in it, RobotLog::staleRows),
/// and Error naming the source for a log of mismatched sizes, non-finite values, times that do
/// not increase, fewer than 2 samples, a negative or non-finite period or maxGap, a fitBandwidth
/// that is not positive and finite, a period that
/// gives fewer than 2 grid samples or more than 100 times the log's, and nominal times that
/// do not apply.
UniformLog resampleUniform(const RobotLog &log, const ResampleOptions &options = {});

} // namespace learnid
