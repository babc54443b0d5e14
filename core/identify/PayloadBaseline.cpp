#include "identify/PayloadBaseline.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadBaseline)
};

// The log's samples [from, to) that baseline sample k + shift covers.
struct Overlap
{
    Eigen::Index from = 0, to = 0;
    Eigen::Index size() const { return std::max<Eigen::Index>(0, to - from); }
};

Overlap overlapOf(const FilteredLog &log, const FilteredLog &b, Eigen::Index shift)
{
    return {std::max<Eigen::Index>(0, -shift),
            std::min<Eigen::Index>(log.q.cols(), b.q.cols() - shift)};
}

double meanSquaredAngle(const FilteredLog &log, const FilteredLog &b, Eigen::Index shift)
{
    const Overlap o = overlapOf(log, b, shift);
    if (o.size() == 0)
        return std::numeric_limits<double>::infinity();
    return (log.q.middleCols(o.from, o.size()) - b.q.middleCols(o.from + shift, o.size()))
               .squaredNorm() /
           double(o.size() * log.q.rows());
}

// The shift within +-maxShift whose angles match best, among those covering enough of the log
// (a search over whole samples: the logs share one grid, and a fraction of a sample moves the
// residual by far less than the noise at the rates logs are filtered at).
BaselineAlignment align(const FilteredLog &log, const FilteredLog &b,
                        const BaselineSettings &settings)
{
    BaselineAlignment a;
    a.baseline = b.source;
    a.log = log.source;
    const auto reach =
        Eigen::Index(std::floor(std::max(0.0, settings.maxShift) / log.period + 1e-9));
    double best = std::numeric_limits<double>::infinity();
    const auto needed = Eigen::Index(std::ceil(settings.minOverlap * double(log.q.cols())));
    for (Eigen::Index shift = -reach; shift <= reach; ++shift) {
        if (overlapOf(log, b, shift).size() < needed)
            continue;
        const double cost = meanSquaredAngle(log, b, shift);
        if (cost < best) {
            best = cost;
            a.shift = shift;
        }
    }
    if (!std::isfinite(best)) {
        throw Error(Text::tr("%1 covers less than %2 % of %3 within a shift of %4 s: a baseline "
                             "runs the same timed path without the payload")
                        .arg(b.source)
                        .arg(100.0 * settings.minOverlap)
                        .arg(log.source)
                        .arg(settings.maxShift));
    }
    a.shiftSeconds = double(a.shift) * log.period;
    a.angleRmsDeg = std::sqrt(best) * 180.0 / M_PI;
    return a;
}

void checkComparable(const FilteredLog &log, const FilteredLog &b, bool sameLength)
{
    if (b.dof() != log.dof() || std::abs(b.period - log.period) > 1e-9 * log.period ||
        (sameLength && b.q.cols() != log.q.cols())) {
        throw Error(Text::tr("%1 (%2 joints, %3 samples of %4 s) is not a baseline of %5 "
                             "(%6 joints, %7 samples of %8 s): a baseline runs the same "
                             "timed path without the payload")
                        .arg(b.source)
                        .arg(b.dof())
                        .arg(b.q.cols())
                        .arg(b.period)
                        .arg(log.source)
                        .arg(log.dof())
                        .arg(log.q.cols())
                        .arg(log.period));
    }
    if (!b.q.allFinite() || !b.qd.allFinite() || !b.qdd.allFinite() || !b.tau.allFinite())
        throw Error(Text::tr("%1: the filtered signals are not finite").arg(b.source));
}

} // namespace

FilteredLog withBaselineSubtracted(const PayloadModel &model, const FilteredLog &log,
                                   const std::vector<FilteredLog> &baselines,
                                   const BaselineSettings &settings,
                                   std::vector<BaselineAlignment> *alignments)
{
    if (baselines.empty())
        return log;
    std::vector<BaselineAlignment> laid;
    Overlap common{0, log.q.cols()};
    for (const FilteredLog &b : baselines) {
        checkComparable(log, b, settings.maxShift <= 0.0);
        const BaselineAlignment a = align(log, b, settings); // maxShift 0: shift 0 only
        if (a.angleRmsDeg > settings.maxAngleRmsDeg) {
            throw Error(Text::tr("%1 does not follow the path of %2: their joint angles differ by "
                                 "%3 deg RMS (at most %4 deg) after a shift of %5 s")
                            .arg(b.source, log.source)
                            .arg(a.angleRmsDeg, 0, 'g', 3)
                            .arg(settings.maxAngleRmsDeg)
                            .arg(a.shiftSeconds));
        }
        const Overlap o = overlapOf(log, b, a.shift);
        common = {std::max(common.from, o.from), std::min(common.to, o.to)};
        laid.push_back(a);
    }
    if (double(common.size()) < settings.minOverlap * double(log.q.cols())) {
        throw Error(Text::tr("the baselines together cover less than %1 % of %2")
                        .arg(100.0 * settings.minOverlap)
                        .arg(log.source));
    }
    Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(model.dof(), common.size());
    for (size_t i = 0; i < baselines.size(); ++i) {
        const FilteredLog &b = baselines[i];
        for (Eigen::Index k = 0; k < common.size(); ++k) {
            const Eigen::Index j = common.from + k + laid[i].shift;
            mean.col(k) += b.tau.col(j) - model.armTorqueAt(b.q.col(j), b.qd.col(j), b.qdd.col(j));
        }
    }
    FilteredLog out = log;
    const auto cut = [&](const Eigen::MatrixXd &m) {
        return Eigen::MatrixXd(m.middleCols(common.from, common.size()));
    };
    out.q = cut(log.q);
    out.qd = cut(log.qd);
    out.qdd = cut(log.qdd);
    out.tau = cut(log.tau) - mean / double(baselines.size());
    out.t0 = log.t0 + double(common.from) * log.period;
    if (alignments)
        alignments->insert(alignments->end(), laid.begin(), laid.end());
    return out;
}

} // namespace learnid
