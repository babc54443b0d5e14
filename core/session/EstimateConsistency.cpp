#include "session/EstimateConsistency.h"

#include "model/ChainModel.h"
#include "model/Error.h"
#include "session/PathIdentifiability.h"

#include <Eigen/Eigenvalues>
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

// The CAD model as the prior, each link made a real body where it is not (published data are
// not always: a link whose mass never acts has none): its pseudo-inertia's eigenvalues floored
// at 1e-6 of its largest (and that at 1e-6 kg m^2). The prior only holds what the path does
// not see, so the floor decides nothing the data decide.
Eigen::VectorXd consistentPrior(const Eigen::VectorXd &cad, int links)
{
    Eigen::VectorXd prior = cad;
    for (const LinkConsistency &l : checkConsistency(cad, links, eigenvalueTolerance)) {
        if (l.consistent && !l.degenerate)
            continue;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(
            pseudoInertia(cad.segment<10>(10 * l.link)));
        const double floor = 1e-6 * std::max(eig.eigenvalues().maxCoeff(), 1.0);
        const Eigen::Vector4d values = eig.eigenvalues().cwiseMax(floor);
        prior.segment<10>(10 * l.link) = inertialFromPseudoInertia(
            eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose());
    }
    return prior;
}

} // namespace

EstimateConsistency checkEstimateConsistency(const RobotModel &model, const Eigen::VectorXd &phi,
                                             const JointTrajectory &path)
{
    EstimateConsistency out;
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain || phi.size() != model.parameterCount() || !phi.allFinite())
        return out;
    out.applicable = true;
    out.nearest = phi;
    const int n = chain->dof();
    const Eigen::VectorXd prior = consistentPrior(chain->cadStandard(), n);
    const Eigen::VectorXd pi = chain->base().standardFromBase(phi, prior);
    out.links = checkConsistency(pi, n, eigenvalueTolerance);
    out.negativeTerms = negativeJointTerms(pi, chain->nonnegativeStandard());
    out.consistent = out.negativeTerms.empty() &&
                     std::all_of(out.links.begin(), out.links.end(),
                                 [](const LinkConsistency &l) { return l.consistent; });
    if (out.consistent || path.samples() == 0)
        return out;
    try {
        const Eigen::MatrixXd r = pathRegressorFactor(model, path, maxPathSamples);
        const Eigen::MatrixXd k = chain->base().baseMatrix();
        const Eigen::MatrixXd a = r * k;
        const Eigen::VectorXd b = r * phi;
        // D: each standard parameter relative to its CAD size (floored at 1e-3 of its link's
        // largest, so a zero CAD entry does not pin it); the prior weighs 1e-6 of the path
        // rows per parameter: what the path sees follows the path, the rest stays at the CAD.
        Eigen::VectorXd scale(prior.size());
        for (Eigen::Index i = 0; i < prior.size(); ++i) {
            const Eigen::Index block = i < 10 * n ? (i / 10) * 10 : i;
            const Eigen::Index size = i < 10 * n ? 10 : 1;
            const double floor = 1e-3 * prior.segment(block, size).cwiseAbs().maxCoeff() + 1e-9;
            scale[i] = 1.0 / std::max(std::abs(prior[i]), floor);
        }
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
