#include "identify/ImprovedLaw.h"

#include "identify/FilteringEstimator.h"
#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

namespace {

/// Stacked rows F[W_k+1/2] phi = F[tau_k] of one trial (steps 1-3 of the class comment).
struct Regression
{
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
};

Regression filteredRegression(const RobotModel &model, const TrialPlan &plan,
                              const TrialRecord &record, const EstimatorSettings &settings)
{
    validateRecord(model, plan, record);
    const int n = model.dof();
    const int m = model.parameterCount();
    const int samples = record.samples();
    const FilteringEstimator filter(settings.rho, record.samplePeriod);

    // 1. Joint states from the zero-phase filtered tracking error.
    Eigen::MatrixXd qHat(n, samples);
    Eigen::MatrixXd qdHat(n, samples);
    Eigen::MatrixXd qddHat(n, samples);
    for (int j = 0; j < n; ++j) {
        const Eigen::MatrixXd fe = filter.zeroPhase(plan.desired.q.row(j) - record.q.row(j));
        qHat.row(j) = plan.desired.q.row(j) - fe.row(0);
        qdHat.row(j) = plan.desired.qd.row(j) - fe.row(1);
        qddHat.row(j) = plan.desired.qdd.row(j) - fe.row(2);
    }

    // Regressor entries as signals: row i*n + j of w is W(j, i) over the samples.
    Eigen::MatrixXd w(n * m, samples);
    for (int k = 0; k < samples; ++k) {
        Eigen::Map<Eigen::MatrixXd> wk(w.col(k).data(), n, m);
        model.regressor(qHat.col(k), qdHat.col(k), qddHat.col(k), wk);
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
    out.a.resize(Eigen::Index(rows) * n, m);
    for (int k = 0; k < rows; ++k)
        out.a.middleRows(Eigen::Index(k) * n, n) =
            Eigen::Map<const Eigen::MatrixXd>(wf.col(k).data(), n, m);
    out.b = Eigen::Map<const Eigen::VectorXd>(tauf.data(), tauf.size());
    return out;
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

    // 4. Per trial, OLS gives each joint's residual level; rows are weighted by its inverse so
    // that joints and trials count by their noise, then all trials are solved together.
    std::vector<Regression> parts;
    std::vector<Eigen::VectorXd> weights;
    Eigen::Index rows = 0;
    for (size_t i = first; i < trials.size(); ++i) {
        parts.push_back(filteredRegression(model, *trials[i].plan, *trials[i].record, settings));
        const Regression &r = parts.back();
        const ParameterUpdate ols = observableUpdate(r.a, r.b, n, phiPrev, settings.rankTolerance);
        const double floor = 1e-9 * (r.b.cwiseAbs().maxCoeff() + 1.0);
        const Eigen::VectorXd jointWeight = ols.residualRms.cwiseMax(floor).cwiseInverse();
        weights.push_back(jointWeight.replicate(r.a.rows() / n, 1));
        rows += r.a.rows();
    }
    // Torque noise reaches b through F(s)F(-s), a symmetric operator (H^T = H).
    const FilteringEstimator filter(settings.rho, trials.back().record->samplePeriod);
    NoiseShaping noise;
    noise.varianceGain = filter.zeroPhaseNoiseGain();
    const auto shape = [&filter](const Eigen::RowVectorXd &x) { return filter.zeroPhaseLowPass(x); };
    if (parts.size() == 1) {
        noise.transposedApplied = filterJointSignals(parts[0].a, n, shape);
        return observableUpdate(parts[0].a, parts[0].b, n, phiPrev, settings.rankTolerance,
                                weights[0], noise);
    }

    Eigen::MatrixXd a(rows, model.parameterCount());
    Eigen::VectorXd b(rows), weight(rows);
    noise.transposedApplied.resize(rows, model.parameterCount());
    Eigen::Index at = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
        const Eigen::Index r = parts[i].a.rows();
        a.middleRows(at, r) = parts[i].a;
        b.segment(at, r) = parts[i].b;
        weight.segment(at, r) = weights[i];
        noise.transposedApplied.middleRows(at, r) = filterJointSignals(parts[i].a, n, shape);
        at += r;
    }
    return observableUpdate(a, b, n, phiPrev, settings.rankTolerance, weight, noise);
}

} // namespace learnid
