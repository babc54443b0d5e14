#include "identify/PaperLaw.h"

#include "identify/FilteringEstimator.h"
#include "identify/GramBlock.h"
#include "model/Error.h"
#include "model/VectorState.h"

#include <QCoreApplication>

namespace learnid {

ParameterUpdate PaperLaw::update(const RobotModel &model, const std::vector<TrialData> &trials,
                                 const Eigen::VectorXd &phiPrev,
                                 const EstimatorSettings &settings) const
{
    clearUpperVectorState();
    if (trials.empty())
        throw Error(QCoreApplication::translate("LearningLaw", "no completed trial to learn from"));
    const TrialPlan &plan = *trials.back().plan;
    const TrialRecord &record = *trials.back().record;
    validateRecord(model, plan, record);
    const int n = model.dof();
    const int m = model.parameterCount();
    const int samples = record.samples();
    const FilteringEstimator filter(settings.rho, record.samplePeriod);

    // The regressor uses the measured angles; velocities and accelerations come through F.
    const JointStateEstimate hat = estimateJointStates(filter, plan, record, false);
    const Eigen::MatrixXd &qdHat = hat.qd;
    const Eigen::MatrixXd &qddHat = hat.qdd;
    Eigen::MatrixXd tauHat(n, samples);
    for (int j = 0; j < n; ++j)
        tauHat.row(j) =
            plan.feedforward.row(j) + filter.lowPass(record.tau.row(j) - plan.feedforward.row(j));

    // Torque sample k is held over [t_k, t_k + Ts): pair it with the regressor at the interval's
    // mid-point, (W_k + W_k+1) / 2. Online this costs one sample of delay. Pairing it with W_k
    // instead leaves a converged bias of about -0.5 % in b on the paper scenario.
    // Joint j's rows A_j (rows x m) and targets b_j, one row per sample.
    // The rows learned from: all, or those before the filter's settling at the end of a trial
    // stopped early (TrialData::rows; the causal filter has none, the rule is the laws').
    const int rows = trials.back().usedSamples() - 1;
    if (rows + 1 < 16)
        throw Error(QCoreApplication::translate("LearningLaw",
                                                "trial record has only %1 samples to learn from")
                        .arg(rows + 1));
    Eigen::MatrixXd w(n * m, samples); // row i * n + j: W(j, i) over the samples
    model.regressorSeries(record.q, qdHat, qddHat, w);
    std::vector<Eigen::MatrixXd> a(size_t(n), Eigen::MatrixXd(rows, m));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < m; ++i)
            a[size_t(j)].col(i) =
                0.5 * (w.row(i * n + j).head(rows) + w.row(i * n + j).segment(1, rows)).transpose();
    // Solved, then taken about its own fit: the residual is the rows' own.
    GramBlock block =
        selfFittedBlock(a, tauHat.leftCols(rows).transpose(), phiPrev, settings.rankTolerance);
    for (int j = 0; j < n; ++j) {
        // Torque noise reaches tau_hat through the causal F, whose transpose runs backward in
        // time; identically zero regressor entries stay zero.
        Eigen::MatrixXd &h = a[size_t(j)];
        for (int i = 0; i < m; ++i)
            if (!h.col(i).isZero(0.0))
                h.col(i) = filter.anticausalLowPass(h.col(i).transpose()).transpose();
        block.setJointShapedRows(j, h);
    }
    return observableUpdate({&block}, phiPrev, settings.rankTolerance, filter.lowPassNoiseGain(),
                            {}, partialTrialStdLimit(trials.back(), settings),
                            settings.jointLevelObservability);
}

} // namespace learnid
