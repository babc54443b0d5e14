#include "identify/ImprovedLaw.h"

#include "identify/FilteringEstimator.h"
#include "identify/GramBlock.h"
#include "model/Error.h"
#include "model/VectorState.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

/// One trial's rows F[W_k+1/2] phi = F[tau_k] (steps 1-3 of the class comment) reduced to their
/// Gram quantities per joint about the trial's own least-squares fit, with the weight of each
/// joint's rows (step 4) and H^T A's Gram matrices for the covariance. Kept in the trial's cache:
/// O(n m^2) numbers, whatever the trial's length.
struct TrialGram final : LawCache
{
    double rho = 0.0;
    GramBlock block;
};

std::shared_ptr<TrialGram> trialGram(const RobotModel &model, const TrialPlan &plan,
                                     const TrialRecord &record, const EstimatorSettings &settings,
                                     const Eigen::VectorXd &phiPrev)
{
    validateRecord(model, plan, record);
    const int n = model.dof();
    const int m = model.parameterCount();
    const int samples = record.samples();
    const FilteringEstimator filter(settings.rho, record.samplePeriod);

    // 1. Joint states from the zero-phase filtered tracking error.
    const JointStateEstimate hat = estimateJointStates(filter, plan, record, true);

    // Regressor entries as signals: row i*n + j of w is W(j, i) over the samples.
    Eigen::MatrixXd w(n * m, samples);
    model.regressorSeries(hat.q, hat.qd, hat.qdd, w);

    // 2. Mid-sample pairing, 3. zero-phase filtering of both sides. Joint j's rows A_j: column i
    // is the filtered signal of W(j, i); entries that are identically zero stay zero.
    const int rows = samples - 1;
    std::vector<Eigen::MatrixXd> a(size_t(n), Eigen::MatrixXd(rows, m));
    std::vector<double *> nonzero;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < m; ++i) {
            const int r = i * n + j;
            auto column = a[size_t(j)].col(i);
            if (w.row(r).isZero(0.0)) {
                column.setZero();
                continue;
            }
            column = 0.5 * (w.row(r).head(rows) + w.row(r).tail(rows)).transpose();
            nonzero.push_back(column.data());
        }
    }
    Eigen::MatrixXd tauf(rows, n);
    std::vector<double *> series = nonzero; // and the torques: all filtered in pairs
    for (int j = 0; j < n; ++j) {
        tauf.col(j) = record.tau.row(j).head(rows).transpose();
        series.push_back(tauf.col(j).data());
    }
    filter.zeroPhaseLowPassInPlace(series, rows);

    // 4. OLS gives each joint's residual level in this trial; its rows get the inverse weight.
    // The block is then taken about the OLS estimate, so that its residuals are computed from
    // the rows (exactly) and any later fit's residual follows without cancellation.
    auto out = std::make_shared<TrialGram>();
    out->rho = settings.rho;
    out->block = selfFittedBlock(a, tauf, phiPrev, settings.rankTolerance);
    const double floor = 1e-9 * (tauf.cwiseAbs().maxCoeff() + 1.0);
    for (int j = 0; j < n; ++j) {
        const double rms = std::sqrt(out->block.residualSquares(j) / double(rows));
        out->block.setJointWeight(j, 1.0 / std::max(rms, floor));
    }

    // Torque noise reaches b through F(s)F(-s), a symmetric operator (H^T = H).
    filter.zeroPhaseLowPassInPlace(nonzero, rows);
    for (int j = 0; j < n; ++j)
        out->block.setJointShapedRows(j, a[size_t(j)]);
    return out;
}

// The trial's Gram block from its cache, computed and cached on first use.
std::shared_ptr<const TrialGram> trialGramOf(const RobotModel &model, const TrialData &trial,
                                             const EstimatorSettings &settings,
                                             const Eigen::VectorXd &phiPrev)
{
    if (trial.cache) {
        if (auto cached = std::dynamic_pointer_cast<const TrialGram>(*trial.cache);
            cached && cached->rho == settings.rho)
            return cached;
    }
    auto r = trialGram(model, *trial.plan, *trial.record, settings, phiPrev);
    if (trial.cache)
        *trial.cache = r;
    return r;
}

} // namespace

ParameterUpdate ImprovedLaw::update(const RobotModel &model, const std::vector<TrialData> &trials,
                                    const Eigen::VectorXd &phiPrev,
                                    const EstimatorSettings &settings) const
{
    clearUpperVectorState();
    if (trials.empty())
        throw Error(QCoreApplication::translate("LearningLaw", "no completed trial to learn from"));
    const size_t first = settings.accumulate ? 0 : trials.size() - 1;

    // 4. All trials solved together, each row weighted by its joint's noise in its trial: the
    // estimate is consistent whatever feedforward a trial ran with, so every trial adds.
    std::vector<std::shared_ptr<const TrialGram>> parts;
    std::vector<const GramBlock *> blocks;
    for (size_t i = first; i < trials.size(); ++i) {
        parts.push_back(trialGramOf(model, trials[i], settings, phiPrev));
        blocks.push_back(&parts.back()->block);
    }
    const double gain =
        FilteringEstimator(settings.rho, trials.back().record->samplePeriod).zeroPhaseNoiseGain();
    return observableUpdate(blocks, phiPrev, settings.rankTolerance, gain);
}

} // namespace learnid
