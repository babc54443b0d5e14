#include "identify/LearningLaw.h"

#include "identify/FilteringEstimator.h"
#include "identify/ImprovedLaw.h"
#include "identify/PaperLaw.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(LearningLaw)
};

} // namespace

QStringList knownLearningLaws()
{
    return {QStringLiteral("paper"), QStringLiteral("improved")};
}

std::unique_ptr<LearningLaw> makeLearningLaw(const QString &id)
{
    if (id == QLatin1String("paper"))
        return std::make_unique<PaperLaw>();
    if (id == QLatin1String("improved"))
        return std::make_unique<ImprovedLaw>();
    return nullptr;
}

int TrialData::usedSamples() const
{
    const int recorded = record ? record->samples() : 0;
    return rows > 0 ? std::min(rows, recorded) : recorded;
}

bool TrialData::partial() const
{
    return record && (!record->completed() || (plan && record->samples() < plan->samples()));
}

double partialTrialStdLimit(const TrialData &newest, const EstimatorSettings &settings)
{
    return newest.partial() ? settings.partialMaxRelativeStd
                            : std::numeric_limits<double>::infinity();
}

int partialSettlingSamples(double rho, double samplePeriod)
{
    if (!(rho > 0.0) || !(samplePeriod > 0.0))
        return 0;
    return int(std::ceil(partialSettlingRhoTimes / (rho * samplePeriod)));
}

JointStateEstimate estimateJointStates(const FilteringEstimator &filter, const TrialPlan &plan,
                                       const TrialRecord &record, bool zeroPhase)
{
    const Eigen::Index n = record.q.rows();
    const Eigen::Index samples = record.samples();
    JointStateEstimate out{Eigen::MatrixXd(n, samples), Eigen::MatrixXd(n, samples),
                           Eigen::MatrixXd(n, samples)};
    Eigen::RowVectorXd e(samples);
    Eigen::MatrixXd fe(3, samples); // F e, F s e, F s^2 e
    for (Eigen::Index j = 0; j < n; ++j) {
        e = plan.desired.q.row(j).head(samples) - record.q.row(j);
        filter.filterInto(e.data(), samples, zeroPhase, fe.data());
        out.q.row(j) = plan.desired.q.row(j).head(samples) - fe.row(0);
        out.qd.row(j) = plan.desired.qd.row(j).head(samples) - fe.row(1);
        out.qdd.row(j) = plan.desired.qdd.row(j).head(samples) - fe.row(2);
    }
    return out;
}

void validateRecord(const RobotModel &model, const TrialPlan &plan, const TrialRecord &record)
{
    const int n = model.dof();
    if (record.q.rows() != n || record.tau.rows() != n || record.tau.cols() != record.q.cols() ||
        plan.desired.dof() != n || plan.feedforward.rows() != n ||
        plan.feedforward.cols() != plan.samples() || record.samples() != plan.samples()) {
        throw Error(Text::tr("trial record does not match its plan: %1 of %2 samples, %3 joints "
                             "recorded for a %4-joint model")
                        .arg(record.samples())
                        .arg(plan.samples())
                        .arg(record.q.rows())
                        .arg(n));
    }
    if (record.samples() < 16)
        throw Error(Text::tr("trial record has only %1 samples").arg(record.samples()));
    // A sum is finite when every term is (one vectorised pass); otherwise, or on overflow, the
    // loop below names the first bad value, if any.
    if (std::isfinite(record.q.sum() + record.tau.sum()))
        return;
    for (int k = 0; k < record.samples(); ++k) {
        for (int j = 0; j < n; ++j) {
            if (!std::isfinite(record.q(j, k)) || !std::isfinite(record.tau(j, k))) {
                throw Error(
                    Text::tr("trial record has a non-finite %1 at sample %2, joint %3")
                        .arg(std::isfinite(record.q(j, k)) ? Text::tr("torque") : Text::tr("angle"))
                        .arg(k)
                        .arg(j + 1));
            }
        }
    }
}

} // namespace learnid
