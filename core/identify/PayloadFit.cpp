#include "identify/PayloadFit.h"

#include "identify/FilteringEstimator.h"
#include "model/Error.h"

#include <Eigen/QR>
#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadFit)
};

// Per joint, the filtered rows [Y_k | tau - tau_arm] of every log stacked (samples x 11).
std::vector<Eigen::MatrixXd> jointRows(const PayloadModel &model,
                                       const std::vector<FilteredLog> &logs, Eigen::Index total)
{
    const int n = model.dof();
    std::vector<Eigen::MatrixXd> rows(size_t(n), Eigen::MatrixXd(total, 11));
    Eigen::MatrixXd y(n, 10);
    Eigen::VectorXd arm(n);
    Eigen::Index at = 0;
    for (const FilteredLog &log : logs) {
        std::vector<Eigen::MatrixXd> raw(size_t(n), Eigen::MatrixXd(log.q.cols(), 11));
        for (Eigen::Index k = 0; k < log.q.cols(); ++k) {
            model.evaluate(log.q.col(k), log.qd.col(k), log.qdd.col(k), y, arm);
            for (int j = 0; j < n; ++j) {
                raw[size_t(j)].row(k).head<10>() = y.row(j);
                raw[size_t(j)](k, 10) = log.tau(j, k) - arm[j];
            }
        }
        const Eigen::Index kept = log.keptSamples();
        for (int j = 0; j < n; ++j)
            rows[size_t(j)].middleRows(at, kept) = log.rows(std::move(raw[size_t(j)]));
        at += kept;
    }
    return rows;
}

// The rows of all joints stacked, joint j's multiplied by weights[j], then projected off the
// unseen directions U: A (E - U U^+), so that A U = 0. What the unseen directions still put into
// the torque is taken as `held`'s (the value they keep): b - A U U^+ held. Left in b, the truth's
// share of them would be fitted into the seen directions (a payload whose inertia about the
// flange is unseen would move its centre of mass instead).
void stack(const std::vector<Eigen::MatrixXd> &rows, const Eigen::VectorXd &weights,
           const Eigen::MatrixXd &unseen, const InertialParameters &held, Eigen::MatrixXd &a,
           Eigen::VectorXd &b)
{
    const Eigen::Index per = rows.front().rows();
    a.resize(per * Eigen::Index(rows.size()), 10);
    b.resize(a.rows());
    for (size_t j = 0; j < rows.size(); ++j) {
        a.middleRows(Eigen::Index(j) * per, per) = weights[Eigen::Index(j)] * rows[j].leftCols(10);
        b.segment(Eigen::Index(j) * per, per) = weights[Eigen::Index(j)] * rows[j].col(10);
    }
    if (unseen.cols() > 0) {
        const Eigen::MatrixXd pinv = unseen.completeOrthogonalDecomposition().pseudoInverse();
        const Eigen::MatrixXd along = a * unseen;
        b -= along * (pinv * held);
        a -= along * pinv;
    }
}

Eigen::VectorXd residualRms(const std::vector<Eigen::MatrixXd> &rows, const InertialParameters &pi)
{
    Eigen::VectorXd rms(Eigen::Index(rows.size()));
    for (size_t j = 0; j < rows.size(); ++j) {
        const Eigen::VectorXd e = rows[j].leftCols(10) * pi - rows[j].col(10);
        rms[Eigen::Index(j)] =
            std::sqrt(e.squaredNorm() / double(std::max<Eigen::Index>(1, e.size())));
    }
    return rms;
}

} // namespace

double zeroPhaseNoiseGain(double rho, double period)
{
    const auto half = Eigen::Index(std::ceil(filterSettlingTime(rho) / period)) + 1;
    Eigen::VectorXd impulse = Eigen::VectorXd::Zero(2 * half + 1);
    impulse[half] = 1.0;
    FilteringEstimator(rho, period).zeroPhaseLowPassInPlace(impulse.data(), impulse.size());
    return impulse.squaredNorm();
}

PayloadFit fitPayload(const PayloadModel &model, const std::vector<FilteredLog> &logs,
                      const PayloadPrior &prior, const PayloadFitSettings &settings)
{
    const int n = model.dof();
    Eigen::Index total = 0;
    for (const FilteredLog &log : logs) {
        if (log.dof() != n) {
            throw Error(
                Text::tr("%1 has %2 joints, the robot %3").arg(log.source).arg(log.dof()).arg(n));
        }
        if (!log.q.allFinite() || !log.qd.allFinite() || !log.qdd.allFinite() ||
            !log.tau.allFinite())
            throw Error(Text::tr("%1: the filtered signals are not finite").arg(log.source));
        total += log.keptSamples();
    }
    if (total == 0)
        throw Error(Text::tr("no samples to fit the payload to"));
    validatePayloadPrior(prior);

    PayloadFit fit;
    fit.samples = total;
    const std::vector<Eigen::MatrixXd> rows = jointRows(model, logs, total);
    // Filtered residuals are correlated: the estimate's variance is that of the unfiltered
    // noise (the residual's / g) over all samples, of which the rows keep every stride-th.
    fit.filterGain = zeroPhaseNoiseGain(logs.front().rho, logs.front().period);
    PayloadEstimateSettings estimateSettings = settings.estimate;
    estimateSettings.varianceFactor = 1.0 / (fit.filterGain * logs.front().stride);

    Eigen::MatrixXd a;
    Eigen::VectorXd b;
    stack(rows, Eigen::VectorXd::Ones(n), settings.unseen, prior.parameters(), a, b);
    PayloadEstimateSettings firstPass = estimateSettings;
    firstPass.plausible = !settings.weighted;
    fit.estimate = estimatePayload(a, b, prior, firstPass);
    fit.jointNoise = residualRms(rows, fit.estimate.leastSquares);
    if (settings.weighted) {
        const double floor = 1e-6 * fit.jointNoise.maxCoeff() + 1e-300;
        stack(rows, fit.jointNoise.cwiseMax(floor).cwiseInverse(), settings.unseen,
              fit.estimate.anchor, a, b);
        fit.estimate = estimatePayload(a, b, prior, estimateSettings);
    }
    fit.trainingRms = residualRms(rows, fit.estimate.parameters);
    return fit;
}

Eigen::MatrixXd payloadPredictedTorque(const PayloadModel &model, const InertialParameters &pi,
                                       const FilteredLog &log)
{
    const int n = model.dof();
    Eigen::MatrixXd y(n, 10);
    Eigen::VectorXd arm(n);
    Eigen::MatrixXd tau(log.q.cols(), n);
    for (Eigen::Index k = 0; k < log.q.cols(); ++k) {
        model.evaluate(log.q.col(k), log.qd.col(k), log.qdd.col(k), y, arm);
        tau.row(k) = (arm + y * pi).transpose();
    }
    return log.rows(std::move(tau)).transpose();
}

} // namespace learnid
