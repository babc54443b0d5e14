#include "identify/ImprovedLaw.h"

#include "identify/FilteringEstimator.h"
#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

namespace {

/// Stacked rows F[W_k+1/2] phi = F[tau_k] of one trial (steps 1-3 of the class comment), the
/// weight of each row (step 4) and H^T A for the covariance. Kept in the trial's cache.
struct Regression final : LawCache
{
    double rho = 0.0;
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
    Eigen::VectorXd weight;
    Eigen::MatrixXd shaped;
};

Regression filteredRegression(const RobotModel &model, const TrialPlan &plan,
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
    for (int k = 0; k < samples; ++k) {
        Eigen::Map<Eigen::MatrixXd> wk(w.col(k).data(), n, m);
        model.regressor(hat.q.col(k), hat.qd.col(k), hat.qdd.col(k), wk);
    }

    // 2. Mid-sample pairing, 3. zero-phase filtering of both sides.
    const int rows = samples - 1;
    Eigen::MatrixXd wf(n * m, rows);
    for (int r = 0; r < n * m; ++r) {
        if (w.row(r).isZero(0.0)) {
            wf.row(r).setZero();
            continue;
        }
        const Eigen::RowVectorXd mid = 0.5 * (w.row(r).head(rows) + w.row(r).tail(rows));
        wf.row(r) = filter.zeroPhaseLowPass(mid);
    }
    Eigen::MatrixXd tauf(n, rows);
    for (int j = 0; j < n; ++j)
        tauf.row(j) = filter.zeroPhaseLowPass(record.tau.row(j).head(rows));

    Regression out;
    out.rho = settings.rho;
    out.a.resize(Eigen::Index(rows) * n, m);
    for (int k = 0; k < rows; ++k)
        out.a.middleRows(Eigen::Index(k) * n, n) =
            Eigen::Map<const Eigen::MatrixXd>(wf.col(k).data(), n, m);
    out.b = Eigen::Map<const Eigen::VectorXd>(tauf.data(), tauf.size());

    // 4. OLS gives each joint's residual level in this trial; its rows get the inverse weight.
    const ParameterUpdate ols = observableUpdate(out.a, out.b, n, phiPrev, settings.rankTolerance);
    const double floor = 1e-9 * (out.b.cwiseAbs().maxCoeff() + 1.0);
    out.weight = ols.residualRms.cwiseMax(floor).cwiseInverse().replicate(rows, 1);
    // Torque noise reaches b through F(s)F(-s), a symmetric operator (H^T = H).
    out.shaped = filterJointSignals(out.a, n, [&filter](const Eigen::RowVectorXd &x) {
        return filter.zeroPhaseLowPass(x);
    });
    return out;
}

// The trial's regression from its cache, computed and cached on first use.
std::shared_ptr<const Regression> regressionOf(const RobotModel &model, const TrialData &trial,
                                               const EstimatorSettings &settings,
                                               const Eigen::VectorXd &phiPrev)
{
    if (trial.cache) {
        if (auto cached = std::dynamic_pointer_cast<const Regression>(*trial.cache);
            cached && cached->rho == settings.rho)
            return cached;
    }
    auto r = std::make_shared<Regression>(
        filteredRegression(model, *trial.plan, *trial.record, settings, phiPrev));
    if (trial.cache)
        *trial.cache = r;
    return r;
}

} // namespace

ParameterUpdate ImprovedLaw::update(const RobotModel &model, const std::vector<TrialData> &trials,
                                    const Eigen::VectorXd &phiPrev,
                                    const EstimatorSettings &settings) const
{
    if (trials.empty())
        throw Error(QCoreApplication::translate("LearningLaw", "no completed trial to learn from"));
    const int n = model.dof();
    const size_t first = settings.accumulate ? 0 : trials.size() - 1;

    // 4. All trials solved together, each row weighted by its joint's noise in its trial: the
    // estimate is consistent whatever feedforward a trial ran with, so every trial adds.
    std::vector<std::shared_ptr<const Regression>> parts;
    Eigen::Index rows = 0;
    for (size_t i = first; i < trials.size(); ++i) {
        parts.push_back(regressionOf(model, trials[i], settings, phiPrev));
        rows += parts.back()->a.rows();
    }
    NoiseShaping noise;
    noise.varianceGain =
        FilteringEstimator(settings.rho, trials.back().record->samplePeriod).zeroPhaseNoiseGain();
    if (parts.size() == 1) {
        noise.transposedApplied = parts[0]->shaped;
        return observableUpdate(parts[0]->a, parts[0]->b, n, phiPrev, settings.rankTolerance,
                                parts[0]->weight, noise);
    }

    Eigen::MatrixXd a(rows, model.parameterCount());
    Eigen::VectorXd b(rows), weight(rows);
    noise.transposedApplied.resize(rows, model.parameterCount());
    Eigen::Index at = 0;
    for (const auto &part : parts) {
        const Eigen::Index r = part->a.rows();
        a.middleRows(at, r) = part->a;
        b.segment(at, r) = part->b;
        weight.segment(at, r) = part->weight;
        noise.transposedApplied.middleRows(at, r) = part->shaped;
        at += r;
    }
    return observableUpdate(a, b, n, phiPrev, settings.rankTolerance, weight, noise);
}

} // namespace learnid
