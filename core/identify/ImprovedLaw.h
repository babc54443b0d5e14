#pragma once

#include "identify/LearningLaw.h"

namespace learnid {

/// The improved estimator for recorded data (docs/method.md §2.2):
///  1. e = q_d - q filtered zero-phase, F(s)F(-s): q_hat = q_d - e_f, qd_hat = qd_d - e_f',
///     qdd_hat = qdd_d - e_f'' (no phase lag, so no path-dependent bias);
///  2. each torque sample, held over [t_k, t_k + Ts), is paired with the mid-point of its
///     interval: W_k+1/2 = (W_k + W_k+1) / 2;
///  3. both sides filtered zero-phase by F(s)F(-s): F[W] phi = F[tau] (linear in phi, so exact
///     for the true phi), which removes torque noise above rho;
///  4. ordinary least squares per trial, then rows weighted by 1/(residual RMS of their joint
///     in their trial) and, with EstimatorSettings::accumulate, all completed trials solved
///     together (WLS): the estimate is consistent whatever feedforward a trial ran with, so
///     every trial adds information;
///  5. the update keeps directions the trajectories do not observe (observableUpdate).
/// The estimate does not depend on phi_{k-1} except in unobservable directions.
class ImprovedLaw final : public LearningLaw
{
public:
    QString id() const override { return QStringLiteral("improved"); }
    ParameterUpdate update(const RobotModel &model, const std::vector<TrialData> &trials,
                           const Eigen::VectorXd &phiPrev,
                           const EstimatorSettings &settings) const override;
};

} // namespace learnid
