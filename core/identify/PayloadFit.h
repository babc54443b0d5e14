#pragma once

#include "identify/LogSignals.h"
#include "identify/PayloadEstimate.h"
#include "model/Payload.h"

#include <Eigen/Core>
#include <vector>

namespace learnid {

/// How the payload is fitted to filtered logs (docs/payload.md).
struct PayloadFitSettings
{
    PayloadEstimateSettings estimate;
    /// Weigh each joint's rows by the inverse RMS of its residual after a first, unweighted fit
    /// (as LogFitSettings::weighted).
    bool weighted = true;
    /// Directions (10 x k, the parameters' units) the fit must not learn, e.g. those the
    /// planned paths do not observe (PayloadObservability::unseen): the rows are projected off
    /// them, so they keep the prior and are reported as not identified however the measured
    /// motion strayed from the plan. Empty: the rows alone decide.
    Eigen::MatrixXd unseen;
};

/// The payload fitted to logs on top of the fixed arm.
struct PayloadFit
{
    PayloadEstimate estimate;
    Eigen::VectorXd jointNoise;  ///< n: RMS residual per joint of the unweighted fit [N m]
    Eigen::VectorXd trainingRms; ///< n: RMS residual per joint with the estimate [N m]
    Eigen::Index samples = 0;    ///< samples used, all logs
    double filterGain = 0.0;     ///< sum of the squared impulse response of F(s)F(-s)
};

/// The noise gain of the logs' zero-phase filter F(s)F(-s) (bandwidth rho [rad/s], sample
/// period [s]): the sum of its squared impulse response. White noise of variance s^2 leaves it
/// with variance g s^2, correlated over about 1 / (g) samples.
double zeroPhaseNoiseGain(double rho, double period);

/// The payload's 10 parameters fitted to the logs' torques with the arm held fixed: per sample
/// the payload's regressor Y_k and tau - tau_arm (PayloadModel::evaluate), both sides filtered
/// alike (FilteredLog::rows), each joint's rows weighted by its residual's RMS, then
/// estimatePayload() with the standard errors of filtered rows (varianceFactor 1 / (g stride)).
/// Throws Error when a log's joint count differs from the model's, no log has samples, a
/// value is not finite, or the prior is refused (validatePayloadPrior).
PayloadFit fitPayload(const PayloadModel &model, const std::vector<FilteredLog> &logs,
                      const PayloadPrior &prior, const PayloadFitSettings &settings = {});

/// The torque the arm with the payload pi predicts along log, filtered as the fit filters it
/// (n x log.keptSamples()); pi = 0: the arm alone.
Eigen::MatrixXd payloadPredictedTorque(const PayloadModel &model, const InertialParameters &pi,
                                       const FilteredLog &log);

} // namespace learnid
