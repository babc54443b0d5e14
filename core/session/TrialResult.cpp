#include "session/TrialResult.h"

#include <cmath>

namespace learnid {

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

} // namespace learnid
