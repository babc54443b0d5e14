#include "session/ConvergenceFigures.h"

#include "model/ChainModel.h"
#include "session/EstimateConsistency.h"

#include <cmath>
#include <limits>

namespace learnid {

double largestRelativeDifferencePercent(const Eigen::VectorXd &x, const Eigen::VectorXd &ref)
{
    double worst = 0.0;
    for (Eigen::Index i = 0; i < std::min(x.size(), ref.size()); ++i) {
        if (ref[i] == 0.0)
            continue;
        const double r = (x[i] - ref[i]) / std::abs(ref[i]) * 100.0;
        if (std::abs(r) > std::abs(worst))
            worst = r;
    }
    return worst;
}

double pathTorqueErrorPercent(const RobotModel &model, const JointTrajectory &path,
                              const Eigen::VectorXd &phiHat, const Eigen::VectorXd &phi)
{
    return pathTorqueErrorsPercent(model, path, {phiHat}, phi).front();
}

QVector<double> pathTorqueErrorsPercent(const RobotModel &model, const JointTrajectory &path,
                                        const QVector<Eigen::VectorXd> &estimates,
                                        const Eigen::VectorXd &reference)
{
    const int n = model.dof(), m = model.parameterCount(), e = int(estimates.size());
    const Eigen::Index samples = path.samples();
    // Every estimate minus the reference, and the reference itself, as columns.
    Eigen::MatrixXd phi(m, e + 1);
    for (int k = 0; k < e; ++k)
        phi.col(k) = estimates[k] - reference;
    phi.col(e) = reference;
    Eigen::ArrayXd squares = Eigen::ArrayXd::Zero(e + 1);
    Eigen::MatrixXd w(n, m), torque(n, e + 1);
    for (Eigen::Index k = 0; k < samples; ++k) {
        model.regressor(path.q.col(k), path.qd.col(k), path.qdd.col(k), w);
        torque.noalias() = w * phi;
        squares += torque.colwise().squaredNorm().transpose().array();
    }
    QVector<double> percent(e, std::numeric_limits<double>::quiet_NaN());
    if (squares[e] > 0.0)
        for (int k = 0; k < e; ++k)
            percent[k] = 100.0 * std::sqrt(squares[k] / squares[e]);
    return percent;
}

EstimateFigures estimateFigures(const RobotModel &model, const JointTrajectory &path,
                                const QVector<Eigen::VectorXd> &estimates,
                                const std::optional<Eigen::VectorXd> &truth)
{
    EstimateFigures f;
    if (estimates.isEmpty() || path.samples() == 0)
        return f;
    if (truth)
        f.vsTruth = pathTorqueErrorsPercent(model, path, estimates, *truth);
    f.vsNewest = pathTorqueErrorsPercent(model, path, estimates, estimates.constLast());
    // The verdict only (no path: no nearest estimate, which the export computes when asked).
    const EstimateConsistency verdict =
        checkEstimateConsistency(model, estimates.constLast(), JointTrajectory());
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!verdict.applicable || !chain)
        return f;
    f.consistencyChecked = true;
    f.consistencyLines = verdict.describe(model);
    const QList<ParameterInfo> standard = chain->standardParameters();
    for (const LinkConsistency &l : verdict.links)
        if (!l.consistent)
            f.inconsistentGroups << standard.value(10 * l.link).group;
    for (const LinkPlausibility &l : verdict.plausibility)
        if (!l.plausible && verdict.links.at(size_t(l.link)).consistent)
            f.implausibleGroups << standard.value(10 * l.link).group;
    for (const int i : verdict.negativeTerms)
        if (!f.inconsistentGroups.contains(standard.value(i).group))
            f.inconsistentGroups << standard.value(i).group;
    return f;
}

} // namespace learnid
