#include "session/EstimateConsistency.h"

#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelCheck.h"
#include "model/PlausibleEstimate.h"
#include "session/PathIdentifiability.h"

#include <Eigen/SVD>
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
/// The CAD prior's weight against the path rows (PlausibleProblem::priorShare). What is
/// accepted and exported counts it at 1e-6 of what the path determines best, so that the path's
/// torques follow the estimate. The pre-trial check's stand-in counts it at 0.03^2, the share
/// below which identification from logs calls a direction undetermined (LogFitSettings): the
/// check linearises the whole mass matrix and gravity, and what the path determines only weakly
/// is better taken from the CAD model than from an estimate that is not a real body. (At 1e-6 the
/// double pendulum's published model and a KUKA LWR4+ after one learning were refused as
/// unstable, their trials running stably at 0.03.)
constexpr double exportShare = 1e-3;
constexpr double checkShare = 0.03;

// Per standard parameter, the share of its direction (scaled by its column of a) inside the
// directions of a whose singular value is above share times the largest.
std::vector<double> determinedShares(const Eigen::MatrixXd &a, double share)
{
    Eigen::VectorXd d = a.colwise().norm().transpose();
    d = d.cwiseMax(1e-12 * d.maxCoeff() + 1e-300);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a * d.cwiseInverse().asDiagonal(),
                                                Eigen::ComputeThinV);
    const Eigen::VectorXd &s = svd.singularValues();
    Eigen::Index rank = 0;
    while (rank < s.size() && s[rank] > share * s[0] && s[rank] > 0.0)
        ++rank;
    std::vector<double> out;
    for (Eigen::Index i = 0; i < a.cols(); ++i)
        out.push_back(std::min(1.0, svd.matrixV().row(i).head(rank).norm()));
    return out;
}

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
    const Eigen::VectorXd prior = realBodyPrior(model.cadStandard(), model.dof());
    out.volumes = linkVolumes(model.chain(), prior);
    out.plausibility = checkPlausibility(standard, prior, model.dof(), out.volumes);
    out.tinyTerms = tinyJointTerms(standard, model.nonnegativeStandard());
    out.plausible = out.consistent &&
                    std::all_of(out.plausibility.begin(), out.plausibility.end(),
                                [](const LinkPlausibility &l) { return l.plausible; }) &&
                    out.tinyTerms.empty();
    out.standard = standard;
    return out;
}

EstimateConsistency checkEstimateConsistency(const RobotModel &model, const Eigen::VectorXd &phi,
                                             const JointTrajectory &path, NearestEstimate when)
{
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain || phi.size() != model.parameterCount() || !phi.allFinite())
        return {};
    const int n = chain->dof();
    const Eigen::VectorXd prior =
        realBodyPrior(chain->cadStandard(), n, chain->nonnegativeStandard());
    EstimateConsistency out =
        checkStandardConsistency(*chain, chain->base().standardFromBase(phi, prior));
    out.nearest = phi;
    if ((out.consistent && when == NearestEstimate::WhenInconsistent) || path.samples() == 0)
        return out;
    try {
        const Eigen::MatrixXd r = pathRegressorFactor(model, path, maxPathSamples);
        PlausibleProblem problem;
        problem.a = r * chain->base().baseMatrix();
        problem.b = r * phi;
        problem.prior = prior;
        problem.links = n;
        problem.nonnegative = chain->nonnegativeStandard();
        // What is accepted, applied and exported is a plausible body; the pre-trial check's
        // stand-in only needs real bodies with the estimate's torques on the path, as close
        // as the divergence lets it come.
        if (when == NearestEstimate::Always) {
            problem.volumes = linkVolumes(chain->chain(), prior);
            problem.rule = PlausibilityRule();
        }
        problem.priorShare = when == NearestEstimate::Always ? exportShare : checkShare;
        const PlausibleEstimate fit = plausibleEstimate(problem);
        out.nearest = chain->baseFromStandard(fit.standard);
        out.nearestStandard = fit.standard;
        out.standardDetermined = determinedShares(problem.a, exportShare);
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
    if (!applicable)
        return {};
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    QStringList problems;
    if (chain && plausibility.size() == links.size() && volumes.size() == links.size()) {
        const SerialChain &joints = chain->chain();
        for (size_t l = 0; l < links.size(); ++l)
            problems +=
                linkProblems(linkLabel(joints, int(l)), links[l], plausibility[l], volumes[l]);
        // A joint term's index past the 10 n inertia entries: its joint, JointTerms' order.
        const QList<ParameterInfo> names = chain->standardParameters();
        const int perJoint = std::max(1, chain->jointTerms().count());
        std::vector<int> terms = negativeTerms;
        terms.insert(terms.end(), tinyTerms.begin(), tinyTerms.end());
        for (const int i : terms) {
            const int j = (i - 10 * chain->dof()) / perJoint;
            if (j < 0 || j >= chain->dof() || i >= standard.size())
                continue;
            problems << jointTermProblem(jointLabel(joints, j), names.value(i).name, standard[i]);
        }
    }
    QStringList lines;
    if (!consistent)
        lines << Text::tr("not physically consistent");
    else if (!plausible)
        lines << Text::tr("physically consistent (every link a real body) but not plausible");
    else
        lines << Text::tr("physically consistent and plausible: every link a real body that a "
                          "robot's link could be");
    return lines + problems;
}

} // namespace learnid
