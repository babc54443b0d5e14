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

} // namespace

FilteredLog withBaselineSubtracted(const PayloadModel &model, const FilteredLog &log,
                                   const std::vector<FilteredLog> &baselines)
{
    FilteredLog out = log;
    if (baselines.empty())
        return out;
    Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(model.dof(), log.q.cols());
    for (const FilteredLog &b : baselines) {
        // The same timed path: same joints, same grid, same length. A different length means
        // another plan (or a run that ended early), whose samples would not line up in time.
        if (b.dof() != log.dof() || b.q.cols() != log.q.cols() ||
            std::abs(b.period - log.period) > 1e-9 * log.period) {
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
        for (Eigen::Index k = 0; k < b.q.cols(); ++k)
            mean.col(k) += b.tau.col(k) - model.armTorqueAt(b.q.col(k), b.qd.col(k), b.qdd.col(k));
    }
    out.tau -= mean / double(baselines.size());
    return out;
}

} // namespace learnid
