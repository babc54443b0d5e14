#include "session/EstimateConsistency.h"

#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "session/PathIdentifiability.h"

#include <QCoreApplication>
#include <algorithm>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(EstimateConsistency)
};

constexpr double eigenvalueTolerance =
    1e-12;                           ///< relative to a link's largest (PhysicalConsistency.h)
constexpr int maxPathSamples = 2000; ///< path rows used to weight the projection
constexpr double priorShare = 1e-6; ///< the CAD prior's weight against the path rows, per parameter

} // namespace

EstimateConsistency checkStandardConsistency(const ChainModel &model,
                                             const Eigen::VectorXd &standard)
{
    EstimateConsistency out;
    out.applicable = true;
    out.links = checkConsistency(standard, model.dof(), eigenvalueTolerance);
    out.negativeTerms = negativeJointTerms(standard, model.nonnegativeStandard());
    out.consistent = out.negativeTerms.empty() &&
                     std::all_of(out.links.begin(), out.links.end(),
                                 [](const LinkConsistency &l) { return l.consistent; });
    return out;
}

EstimateConsistency checkEstimateConsistency(const RobotModel &model, const Eigen::VectorXd &phi,
                                             const JointTrajectory &path)
{
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain || phi.size() != model.parameterCount() || !phi.allFinite())
        return {};
    const int n = chain->dof();
    const Eigen::VectorXd prior = realBodyPrior(chain->cadStandard(), n);
    EstimateConsistency out =
        checkStandardConsistency(*chain, chain->base().standardFromBase(phi, prior));
    out.nearest = phi;
    if (out.consistent || path.samples() == 0)
        return out;
    try {
        const Eigen::MatrixXd r = pathRegressorFactor(model, path, maxPathSamples);
        const Eigen::MatrixXd k = chain->base().baseMatrix();
        const Eigen::MatrixXd a = r * k;
        const Eigen::VectorXd b = r * phi;
        // The prior weighs 1e-6 of the path rows per parameter: what the path sees follows the
        // path, the rest stays at the CAD model.
        const Eigen::VectorXd scale = priorScale(prior, n);
        const double weight = std::sqrt(priorShare * a.squaredNorm() / double(prior.size()));
        const ConsistentEstimate fit =
            nearestConsistentEstimate(a, b, prior, scale, weight, n, chain->nonnegativeStandard());
        out.nearest = chain->baseFromStandard(fit.standard);
        out.nearestStandard = fit.standard;
        const double size = (r * phi).norm();
        out.pathTorqueChangePercent =
            size > 0.0 ? 100.0 * (r * (out.nearest - phi)).norm() / size : 0.0;
    } catch (const Error &e) {
        out.nearest = phi;
        out.nearestError = e.message();
    }
    return out;
}

QStringList EstimateConsistency::describe(const RobotModel &model) const
{
    QStringList lines;
    if (!applicable)
        return lines;
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    for (const LinkConsistency &l : links) {
        if (l.consistent)
            continue;
        const QString link = chain ? chain->chain().joints[size_t(l.link)].link : QString();
        lines << (l.mass <= 0.0 ? Text::tr("link %1 (%2): mass %3 kg: not a real body")
                                      .arg(l.link + 1)
                                      .arg(link)
                                      .arg(l.mass, 0, 'g', 4)
                                : Text::tr("link %1 (%2): its inertia cannot belong to a real body "
                                           "(pseudo-inertia eigenvalue %3)")
                                      .arg(l.link + 1)
                                      .arg(link)
                                      .arg(l.minEigenvalue, 0, 'g', 3));
    }
    if (chain) {
        const QList<ParameterInfo> names = chain->standardParameters();
        for (const int i : negativeTerms)
            lines << Text::tr("%1 is negative: friction and rotor inertia cannot be")
                         .arg(names.value(i).name);
    }
    if (lines.isEmpty())
        lines << Text::tr("physically consistent: every link a real body");
    return lines;
}

} // namespace learnid
