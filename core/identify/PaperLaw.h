#pragma once

#include "identify/LearningLaw.h"

namespace learnid {

/// The paper's learning law made consistent (docs/method.md §2.1), causal as a robot controller
/// could run it online:
///   e = q_d - q,  qd_hat = qd_d - F s e,  qdd_hat = qdd_d - F s^2 e          (eq. 16-17)
///   tau_hat = tau_f + F (tau - tau_f)     (torque filtered like velocity; the printed F tau
///                                          delays tau by ~3/rho but not the regressor)
///   phi_k = phi_{k-1} + W_hat^+ (tau_hat - W_hat phi_{k-1}),  W_hat = W(q, qd_hat, qdd_hat)
/// which is eq. (11)-(13) with eta = tau_hat - tau_f + (W_d - W_hat) phi_{k-1}.
/// Each torque sample is paired with the regressor at the mid-point of the interval it is held
/// over (one sample of delay online).
class PaperLaw final : public LearningLaw
{
public:
    QString id() const override { return QStringLiteral("paper"); }
    ParameterUpdate update(const RobotModel &model, const std::vector<TrialData> &trials,
                           const Eigen::VectorXd &phiPrev,
                           const EstimatorSettings &settings) const override;
};

} // namespace learnid
