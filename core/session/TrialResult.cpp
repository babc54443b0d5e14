#include "session/TrialResult.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(TrialResult)
};

} // namespace

void trackingErrorFigures(const TrialPlan &plan, const TrialRecord &record, Eigen::VectorXd &maxDeg,
                          Eigen::VectorXd &rmsDeg)
{
    const int n = int(record.q.rows());
    const int samples = std::min(record.samples(), plan.samples());
    maxDeg = Eigen::VectorXd::Zero(n);
    rmsDeg = Eigen::VectorXd::Zero(n);
    if (samples == 0)
        return;
    const Eigen::MatrixXd e =
        (plan.desired.q.leftCols(samples) - record.q.leftCols(samples)) * (180.0 / M_PI);
    maxDeg = e.cwiseAbs().rowwise().maxCoeff();
    rmsDeg = (e.array().square().rowwise().sum() / double(samples)).sqrt().matrix();
}

QString lateSetpointsNote(const TrialRecord &record)
{
    if (record.lateSetpoints <= 0)
        return {};
    return Text::tr("%n set-point(s) reached the drives after their SYNC (statusword bit 12): "
                    "the drives held the previous one, so this trial's motion is not quite the "
                    "plan's and neither is what it teaches; close other programs on this computer",
                    nullptr, record.lateSetpoints);
}

} // namespace learnid
