#include "identify/PaperLaw.h"

#include "identify/FilteringEstimator.h"
#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

ParameterUpdate PaperLaw::update(const RobotModel &model, const std::vector<TrialData> &trials,
                                 const Eigen::VectorXd &phiPrev,
                                 const EstimatorSettings &settings) const
{
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
        tauHat.row(j) = plan.feedforward.row(j)
                        + filter.lowPass(record.tau.row(j) - plan.feedforward.row(j));

    // Torque sample k is held over [t_k, t_k + Ts): pair it with the regressor at the interval's
    // mid-point, (W_k + W_k+1) / 2. Online this costs one sample of delay. Pairing it with W_k
    // instead leaves a converged bias of about -0.5 % in b on the paper scenario.
    const int rows = samples - 1;
    Eigen::MatrixXd a(Eigen::Index(rows) * n, m);
    Eigen::MatrixXd w0(n, m), w1(n, m);
    model.regressor(record.q.col(0), qdHat.col(0), qddHat.col(0), w0);
    for (int k = 0; k < rows; ++k) {
        model.regressor(record.q.col(k + 1), qdHat.col(k + 1), qddHat.col(k + 1), w1);
        a.middleRows(Eigen::Index(k) * n, n) = 0.5 * (w0 + w1);
        w0.swap(w1);
    }
    const Eigen::VectorXd b =
        Eigen::Map<const Eigen::VectorXd>(tauHat.data(), Eigen::Index(rows) * n);
    // Torque noise reaches tau_hat through the causal F, whose transpose runs backward in time.
    NoiseShaping noise;
    noise.varianceGain = filter.lowPassNoiseGain();
    noise.transposedApplied = filterJointSignals(
        a, n, [&filter](const Eigen::RowVectorXd &x) { return filter.anticausalLowPass(x); });
    return observableUpdate(a, b, n, phiPrev, settings.rankTolerance, {}, noise);
}

} // namespace learnid
