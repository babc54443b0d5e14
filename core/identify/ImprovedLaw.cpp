#include "identify/ImprovedLaw.h"

#include "identify/FilteringEstimator.h"
#include "identify/GramBlock.h"
#include "identify/JointRows.h"
#include "identify/ObservableUpdate.h"
#include "identify/RotorTorque.h"
#include "identify/SensorLag.h"
#include "identify/TaskThreads.h"
#include "model/Error.h"
#include "model/VectorState.h"

#include <QCoreApplication>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>

namespace learnid {

namespace {

/// One trial's rows F[W_k+1/2] phi = F[tau_k] (steps 1-3 of the class comment) reduced to their
/// Gram quantities per joint about the trial's own least-squares fit, with the weight of each
/// joint's rows (step 4) and H^T A's Gram matrices for the covariance. Kept in the trial's cache:
/// O(n m^2) numbers, whatever the trial's length.
struct TrialGram final : LawCache
{
    double rho = 0.0;
    bool jointTorqueSensor = false; ///< the settings the rows were formed with
    double torqueSensorLag = 0.0;
    GramBlock block;
};

// task(j) for every joint, on all the threads, the largest joints first: each joint's numbers
// are its own, whichever thread computes them.
void forEachJoint(TaskThreads &threads, const std::vector<JointRows> &a,
                  const std::function<void(int)> &task)
{
    const std::vector<int> order = jointsLargestFirst(a);
    std::atomic<size_t> next{0};
    threads.run([&](int) {
        for (size_t i = next++; i < order.size(); i = next++)
            task(order[i]);
    });
}

std::shared_ptr<TrialGram> trialGram(const RobotModel &model, const TrialData &trial,
                                     const EstimatorSettings &settings,
                                     const Eigen::VectorXd &phiPrev)
{
    const TrialPlan &plan = *trial.plan;
    const TrialRecord &record = *trial.record;
    validateRecord(model, plan, record);
    const int n = model.dof();
    const int samples = record.samples();
    // The rows learned from: all, or those before the filter's settling at the end of a trial
    // stopped early (TrialData::rows); every sample is filtered.
    const Eigen::Index used = std::max(trial.usedSamples() - 1, 0);
    if (used + 1 < 16)
        throw Error(QCoreApplication::translate("LearningLaw",
                                                "trial record has only %1 samples to learn from")
                        .arg(used + 1));
    const FilteringEstimator filter(settings.rho, record.samplePeriod);

    // 1. Joint states from the zero-phase filtered tracking error.
    const JointStateEstimate hat = estimateJointStates(filter, plan, record, true);

    // The joints' rows are formed, filtered and reduced on two threads where the machine has
    // them (the numbers do not depend on it); a short record is not worth waking a second one.
    TaskThreads threads(samples >= 10000 ? TaskThreads::available() : 1);

    // 2. Mid-sample pairing, 3. zero-phase filtering of both sides. Joint j's rows A_j: column i
    // is the filtered signal of W(j, i); only the columns not identically zero are kept (and
    // filtered), the others stay exactly zero.
    std::vector<JointRows> a = midSampleJointRows(model, hat.q, hat.qd, hat.qdd, threads);
    const Eigen::Index rows = std::max(samples - 1, 0);
    // The torques the sensors were given (their lag undone), then the rotors they do not see.
    const Eigen::MatrixXd measured =
        withoutSensorLag(record.tau, record.samplePeriod, settings.torqueSensorLag);
    Eigen::MatrixXd tauf = measured.leftCols(rows).transpose();
    if (settings.jointTorqueSensor)
        tauf += rotorTorque(filter, plan, record, measured, hat.qdd, used);
    auto out = std::make_shared<TrialGram>();
    out->rho = settings.rho;
    out->jointTorqueSensor = settings.jointTorqueSensor;
    out->torqueSensorLag = settings.torqueSensorLag;
    GramBlock &block = out->block;
    block = GramBlock(n, model.parameterCount(), used, phiPrev);
    // Per joint: both sides filtered, then the normal equations of the OLS fit of step 4.
    forEachJoint(threads, a, [&](int j) {
        filter.zeroPhaseLowPassColumnsInPlace(a[size_t(j)].a);
        filter.zeroPhaseLowPassInPlace(tauf.col(j).data(), rows);
        if (used < rows)
            a[size_t(j)].a.conservativeResize(used, Eigen::NoChange);
        block.setJointNormalEquations(j, a[size_t(j)], tauf.col(j).head(used));
    });

    // 4. OLS gives each joint's residual level in this trial; its rows get the inverse weight.
    // The block is then taken about the OLS estimate, so that its residuals are computed from
    // the rows (exactly) and any later fit's residual follows without cancellation.
    block.setReference(observableUpdate({&block}, phiPrev, settings.rankTolerance).phi);
    forEachJoint(threads, a, [&](int j) {
        block.setJointResidual(j, a[size_t(j)], tauf.col(j).head(used));
        // Torque noise reaches b through F(s)F(-s), a symmetric operator (H^T = H).
        filter.zeroPhaseLowPassColumnsInPlace(a[size_t(j)].a);
        block.setJointShapedRows(j, a[size_t(j)]);
    });
    const double floor = 1e-9 * (tauf.topRows(used).cwiseAbs().maxCoeff() + 1.0);
    for (int j = 0; j < n; ++j) {
        const double rms = std::sqrt(block.residualSquares(j) / double(used));
        block.setJointWeight(j, 1.0 / std::max(rms, floor));
    }
    return out;
}

// The trial's Gram block from its cache, computed and cached on first use.
std::shared_ptr<const TrialGram> trialGramOf(const RobotModel &model, const TrialData &trial,
                                             const EstimatorSettings &settings,
                                             const Eigen::VectorXd &phiPrev)
{
    if (trial.cache) {
        if (auto cached = std::dynamic_pointer_cast<const TrialGram>(*trial.cache);
            cached && cached->rho == settings.rho &&
            cached->jointTorqueSensor == settings.jointTorqueSensor &&
            cached->torqueSensorLag == settings.torqueSensorLag &&
            cached->block.samples() == std::max(trial.usedSamples() - 1, 0))
            return cached;
    }
    auto r = trialGram(model, trial, settings, phiPrev);
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
    // A parameter's scale does not vanish with its estimate: a direction once moved near 0 stays
    // as observable as it was with the estimate the first trial ran with (docs/method.md §2.3).
    const Eigen::VectorXd &anchor = trials.front().plan->feedforwardParameters;
    return observableUpdate(blocks, phiPrev, settings.rankTolerance, gain,
                            anchor.size() == phiPrev.size() ? anchor : Eigen::VectorXd(),
                            partialTrialStdLimit(trials.back(), settings),
                            settings.jointLevelObservability);
}

} // namespace learnid
