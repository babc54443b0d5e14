#include "identify/UniformLog.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QLocale>
#include <algorithm>
#include <cmath>
#include <vector>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(UniformLog)
};

constexpr double gapOfFilterTimeConstant = 0.5; // of 1/rho: defaultMaxGap()
constexpr double minimumGapInSteps = 2.5;       // of the log's step: one lost sample, jittered
constexpr Eigen::Index maxUpsampling = 100;     // grid samples per log sample at most
// A grid time within this fraction of a period past the last stamp still counts as covered:
// t0 + k T rounds, and the last sample must not be lost to it.
constexpr double gridTolerance = 1e-9;

QString number(double v)
{
    return QString::number(v, 'g', QLocale::FloatingPointShortest);
}

QString seconds(double t)
{
    return QString::number(t, 'g', 10);
}

QString milliseconds(double seconds)
{
    return QString::number(seconds * 1e3, 'g', 4);
}

// "line L" of sample k, or "sample k+1" in a log not read from a file.
QString lineOf(const RobotLog &log, Eigen::Index k)
{
    if (log.rows.empty())
        return Text::tr("sample %1").arg(k + 1);
    return Text::tr("line %1").arg(log.rows[size_t(k)]);
}

QString samplePlace(const RobotLog &log, Eigen::Index k)
{
    return QStringLiteral("%1: %2").arg(log.source, lineOf(log, k));
}

// " (lines A to B: stale, ...)": the stale rows the reader dropped between sample k-1 and k.
QString staleRowsBefore(const RobotLog &log, Eigen::Index k)
{
    if (log.rows.empty() || log.staleRows.empty())
        return {};
    const int after = log.rows[size_t(k - 1)], before = log.rows[size_t(k)];
    const auto first = std::upper_bound(log.staleRows.begin(), log.staleRows.end(), after);
    const auto last = std::lower_bound(first, log.staleRows.end(), before);
    if (first == last)
        return {};
    if (last - first == 1) {
        return Text::tr(" (line %1 is stale: it repeated the values of line %2 under a new time "
                        "stamp and counts as missing)")
            .arg(QString::number(*first), QString::number(after));
    }
    return Text::tr(" (lines %1 to %2 are stale: %3 rows that repeated the values of line %4 "
                    "under new time stamps and count as missing)")
        .arg(QString::number(*first), QString::number(*(last - 1)), QString::number(last - first),
             QString::number(after));
}

void checkLog(const RobotLog &log)
{
    const Eigen::Index n = log.q.rows();
    const Eigen::Index samples = log.t.size();
    const bool sizesOk = n >= 1 && log.q.cols() == samples && log.tau.rows() == n &&
                         log.tau.cols() == samples &&
                         (log.dq.size() == 0 || (log.dq.rows() == n && log.dq.cols() == samples)) &&
                         (log.rows.empty() || Eigen::Index(log.rows.size()) == samples);
    if (!sizesOk) {
        throw Error(Text::tr("%1: a log of %2 times, %3 x %4 positions, %5 x %6 velocities, "
                             "%7 x %8 torques and %9 line numbers; expected n x N for all")
                        .arg(log.source, QString::number(samples), QString::number(log.q.rows()),
                             QString::number(log.q.cols()), QString::number(log.dq.rows()),
                             QString::number(log.dq.cols()), QString::number(log.tau.rows()),
                             QString::number(log.tau.cols()), QString::number(log.rows.size())));
    }
    if (samples < 2) {
        throw Error(Text::tr("%1: %2 samples; resampling needs at least 2")
                        .arg(log.source, QString::number(samples)));
    }
    for (Eigen::Index k = 0; k < samples; ++k) {
        const bool finite = std::isfinite(log.t[k]) && log.q.col(k).allFinite() &&
                            log.tau.col(k).allFinite() &&
                            (log.dq.size() == 0 || log.dq.col(k).allFinite());
        if (!finite)
            throw Error(Text::tr("%1: a value is not a finite number").arg(samplePlace(log, k)));
        if (k > 0 && !(log.t[k] > log.t[k - 1])) {
            throw Error(Text::tr("%1: the times must increase from sample to sample, got %2 "
                                 "after %3")
                            .arg(samplePlace(log, k), number(log.t[k]), number(log.t[k - 1])));
        }
    }
    if (!std::isfinite(log.t[samples - 1] - log.t[0])) {
        throw Error(Text::tr("%1: the log spans %2 to %3 s, too long to resample")
                        .arg(log.source, number(log.t[0]), number(log.t[samples - 1])));
    }
}

double medianStep(const Eigen::VectorXd &t)
{
    std::vector<double> steps(size_t(t.size() - 1));
    for (size_t k = 0; k < steps.size(); ++k)
        steps[k] = t[Eigen::Index(k) + 1] - t[Eigen::Index(k)];
    const auto middle = steps.begin() + std::ptrdiff_t(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    if (steps.size() % 2 == 1)
        return *middle;
    return 0.5 * (*middle + *std::max_element(steps.begin(), middle));
}

// t0 + k T for the samples of a log taken on a fixed tick. The stamps' offsets from these
// times must spread over less than half a step: a lost or added sample moves all later offsets
// by a whole step (the LWR4+ logs spread over 1.6 to 1.8 ms of their 5 ms).
Eigen::VectorXd nominalTimes(const RobotLog &log)
{
    const Eigen::Index samples = log.t.size();
    const double t0 = log.t[0];
    const double step = (log.t[samples - 1] - t0) / double(samples - 1);
    Eigen::VectorXd times(samples);
    Eigen::Index early = 0, late = 0;
    for (Eigen::Index k = 0; k < samples; ++k) {
        times[k] = t0 + double(k) * step;
        if (log.t[k] - times[k] < log.t[early] - times[early])
            early = k;
        if (log.t[k] - times[k] > log.t[late] - times[late])
            late = k;
    }
    const double earliest = log.t[early] - times[early], latest = log.t[late] - times[late];
    if (latest - earliest > 0.5 * step) {
        throw Error(Text::tr("%1: the time stamps are off the nominal times t0 + k T (T = %2 ms) "
                             "by %3 ms at %4 (t = %5 s) and by %6 ms at %7 (t = %8 s), more than "
                             "half a step apart: the samples are not equidistant (one lost or "
                             "added?), so the nominal times do not apply")
                        .arg(log.source, milliseconds(step), milliseconds(earliest),
                             lineOf(log, early), seconds(log.t[early]), milliseconds(latest),
                             lineOf(log, late), seconds(log.t[late])));
    }
    return times;
}

// Rows of x at the grid times, linear between the samples at times around each.
Eigen::MatrixXd interpolate(const Eigen::MatrixXd &x, const Eigen::VectorXd &times, double t0,
                            double period, Eigen::Index gridSamples)
{
    Eigen::MatrixXd out(x.rows(), gridSamples);
    Eigen::Index i = 0;
    for (Eigen::Index k = 0; k < gridSamples; ++k) {
        const double tk = t0 + double(k) * period;
        while (i + 2 < times.size() && times[i + 1] <= tk)
            ++i;
        const double alpha = std::clamp((tk - times[i]) / (times[i + 1] - times[i]), 0.0, 1.0);
        out.col(k) = (1.0 - alpha) * x.col(i) + alpha * x.col(i + 1);
    }
    return out;
}

} // namespace

double defaultMaxGap(double rho, double logStep)
{
    return std::max(gapOfFilterTimeConstant / rho, minimumGapInSteps * logStep);
}

UniformLog resampleUniform(const RobotLog &log, const ResampleOptions &options)
{
    checkLog(log);
    if (!std::isfinite(options.period) || options.period < 0.0 || !(options.maxGap >= 0.0)) {
        throw Error(Text::tr("%1: the period (%2 s) and the largest gap (%3 s) must be zero "
                             "(the default) or positive")
                        .arg(log.source, number(options.period), number(options.maxGap)));
    }
    if (!(options.fitBandwidth > 0.0) || !std::isfinite(options.fitBandwidth)) {
        throw Error(Text::tr("%1: the fit's filter bandwidth rho (%2 rad/s) must be positive")
                        .arg(log.source, number(options.fitBandwidth)));
    }
    const Eigen::Index samples = log.t.size();
    const Eigen::VectorXd times = options.useNominalTimes ? nominalTimes(log) : log.t;
    const double t0 = log.t[0];
    const double span = log.t[samples - 1] - t0;

    UniformLog uniform;
    uniform.source = log.source;
    uniform.t0 = t0;
    const double logStep = options.useNominalTimes ? span / double(samples - 1) : medianStep(log.t);
    uniform.period = options.period > 0.0 ? options.period : logStep;
    const double maxGap =
        options.maxGap > 0.0 ? options.maxGap : defaultMaxGap(options.fitBandwidth, logStep);
    for (Eigen::Index k = 1; k < samples; ++k) {
        const double gap = log.t[k] - log.t[k - 1];
        if (gap > maxGap) {
            const QString allowed =
                options.maxGap > 0.0
                    ? Text::tr("%1 ms allowed (--max-gap)").arg(milliseconds(maxGap))
                    : Text::tr("%1 ms allowed (--max-gap; by default half the time constant "
                               "1/rho of the fit's filter, rho = %2 rad/s, and at least %3 of "
                               "the log's steps)")
                          .arg(milliseconds(maxGap), number(options.fitBandwidth),
                               number(minimumGapInSteps));
            throw Error(Text::tr("%1: a gap of %2 ms after the sample at t = %3 s%4, more than "
                                 "the %5")
                            .arg(samplePlace(log, k), milliseconds(gap), seconds(log.t[k - 1]),
                                 staleRowsBefore(log, k), allowed));
        }
    }

    const double steps = std::floor(span / uniform.period + gridTolerance);
    if (!(steps >= 1.0) || steps >= double(maxUpsampling * samples)) {
        throw Error(Text::tr("%1: a period of %2 ms over the log's %3 s gives %4 samples; "
                             "expected 2 to %5 (100 per sample of the log)")
                        .arg(log.source, milliseconds(uniform.period), number(span),
                             number(steps + 1.0), QString::number(maxUpsampling * samples)));
    }
    const auto gridSamples = Eigen::Index(steps) + 1;
    uniform.q = interpolate(log.q, times, t0, uniform.period, gridSamples);
    uniform.tau = interpolate(log.tau, times, t0, uniform.period, gridSamples);
    if (log.dq.size() > 0)
        uniform.dq = interpolate(log.dq, times, t0, uniform.period, gridSamples);
    if (!uniform.q.allFinite() || !uniform.tau.allFinite() || !uniform.dq.allFinite()) {
        throw Error(Text::tr("%1: values this close to the largest double cannot be interpolated")
                        .arg(log.source));
    }
    return uniform;
}

} // namespace learnid
