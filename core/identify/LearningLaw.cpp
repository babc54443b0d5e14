#include "identify/LearningLaw.h"

#include "identify/FilteringEstimator.h"
#include "identify/ImprovedLaw.h"
#include "identify/PaperLaw.h"
#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

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

JointStateEstimate estimateJointStates(const FilteringEstimator &filter, const TrialPlan &plan,
                                       const TrialRecord &record, bool zeroPhase)
{
    const Eigen::Index n = record.q.rows();
    const Eigen::Index samples = record.samples();
    JointStateEstimate out{Eigen::MatrixXd(n, samples), Eigen::MatrixXd(n, samples),
                           Eigen::MatrixXd(n, samples)};
    for (Eigen::Index j = 0; j < n; ++j) {
        const Eigen::RowVectorXd e = plan.desired.q.row(j).head(samples) - record.q.row(j);
        const Eigen::MatrixXd fe = zeroPhase ? filter.zeroPhase(e) : filter.causal(e);
        out.q.row(j) = plan.desired.q.row(j).head(samples) - fe.row(0);
        out.qd.row(j) = plan.desired.qd.row(j).head(samples) - fe.row(1);
        out.qdd.row(j) = plan.desired.qdd.row(j).head(samples) - fe.row(2);
    }
    return out;
}

Eigen::MatrixXd filterJointSignals(
    const Eigen::MatrixXd &a, int n,
    const std::function<Eigen::RowVectorXd(const Eigen::RowVectorXd &)> &filter)
{
    const Eigen::Index samples = a.rows() / n;
    Eigen::MatrixXd out(a.rows(), a.cols());
    for (Eigen::Index i = 0; i < a.cols(); ++i) {
        for (int j = 0; j < n; ++j) {
            const Eigen::Map<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>> signal(
                a.col(i).data() + j, samples, Eigen::InnerStride<>(n));
            const Eigen::RowVectorXd filtered = filter(signal);
            Eigen::Map<Eigen::RowVectorXd, 0, Eigen::InnerStride<>>(out.col(i).data() + j, samples,
                                                                   Eigen::InnerStride<>(n)) =
                filtered;
        }
    }
    return out;
}

void validateRecord(const RobotModel &model, const TrialPlan &plan, const TrialRecord &record)
{
    const auto tr = [](const char *s) { return QCoreApplication::translate("LearningLaw", s); };
    const int n = model.dof();
    if (record.q.rows() != n || record.tau.rows() != n || record.tau.cols() != record.q.cols()
        || plan.desired.dof() != n || plan.feedforward.rows() != n
        || plan.feedforward.cols() != plan.samples() || record.samples() != plan.samples()) {
        throw Error(tr("trial record does not match its plan: %1 of %2 samples, %3 joints "
                       "recorded for a %4-joint model")
                        .arg(record.samples())
                        .arg(plan.samples())
                        .arg(record.q.rows())
                        .arg(n));
    }
    if (record.samples() < 16)
        throw Error(tr("trial record has only %1 samples").arg(record.samples()));
    for (int k = 0; k < record.samples(); ++k) {
        for (int j = 0; j < n; ++j) {
            if (!std::isfinite(record.q(j, k)) || !std::isfinite(record.tau(j, k))) {
                throw Error(tr("trial record has a non-finite %1 at sample %2, joint %3")
                                .arg(std::isfinite(record.q(j, k)) ? tr("torque") : tr("angle"))
                                .arg(k)
                                .arg(j + 1));
            }
        }
    }
}

} // namespace learnid
