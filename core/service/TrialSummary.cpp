#include "service/TrialSummary.h"

namespace learnid {

namespace {

// Same columns, no rows: the storage is freed, samples() is unchanged.
void dropRows(Eigen::MatrixXd &m)
{
    m = Eigen::MatrixXd(0, m.cols());
}

} // namespace

TrialResult trialSummary(const TrialResult &trial)
{
    TrialResult s = trial;
    for (Eigen::MatrixXd *m :
         {&s.check.plan.desired.q, &s.check.plan.desired.qd, &s.check.plan.desired.qdd,
          &s.check.plan.feedforward, &s.record.q, &s.record.tau})
        dropRows(*m);
    return s;
}

} // namespace learnid
