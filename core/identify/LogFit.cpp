#include "identify/LogFit.h"

#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/Plausibility.h"
#include "model/PlausibleEstimate.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(LogFit)
};

// Per joint j, the triangular factor of [Y_j | tau_j] over every sample of every log
// ((p + 1) x (p + 1)): ||Y_j pi - tau_j|| = ||R_j [pi; -1]|| for every pi, in p + 1 rows
// instead of all samples. Householder QR of the rows themselves, not their Gram matrix: poorly
// excited data are ill-conditioned, and squaring the condition would lose what they hold.
std::vector<Eigen::MatrixXd> jointFactors(const ChainModel &model,
                                          const std::vector<FilteredLog> &logs, Eigen::Index total)
{
    const int n = model.dof();
    const int p = model.standardCount();
    std::vector<Eigen::MatrixXd> rows(size_t(n), Eigen::MatrixXd(total, p + 1));
    Eigen::MatrixXd y(n, p);
    Eigen::Index at = 0;
    for (const FilteredLog &log : logs) {
        // Y and tau of this log, one matrix per joint, filtered alike (FilteredLog::rows).
        std::vector<Eigen::MatrixXd> raw(size_t(n), Eigen::MatrixXd(log.q.cols(), p + 1));
        for (Eigen::Index k = 0; k < log.q.cols(); ++k) {
            model.standardRegressor(log.q.col(k), log.qd.col(k), log.qdd.col(k), y);
            for (int j = 0; j < n; ++j) {
                raw[size_t(j)].row(k).head(p) = y.row(j);
                raw[size_t(j)](k, p) = log.tau(j, k);
            }
        }
        const Eigen::Index kept = log.keptSamples();
        for (int j = 0; j < n; ++j) {
            rows[size_t(j)].middleRows(at, kept) = log.rows(std::move(raw[size_t(j)]));
            raw[size_t(j)].resize(0, 0);
        }
        at += kept;
    }
    std::vector<Eigen::MatrixXd> factors;
    for (Eigen::MatrixXd &m : rows) {
        Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(m);
        const Eigen::Index r = std::min<Eigen::Index>(m.rows(), p + 1);
        Eigen::MatrixXd f = Eigen::MatrixXd::Zero(p + 1, p + 1);
        f.topRows(r) = qr.matrixQR().topRows(r).triangularView<Eigen::Upper>();
        factors.push_back(std::move(f));
        m.resize(0, 0);
    }
    return factors;
}

// The factor of the joints' factors stacked, joint j weighted by weights[j].
Eigen::MatrixXd stackedFactor(const std::vector<Eigen::MatrixXd> &factors,
                              const Eigen::VectorXd &weights)
{
    const Eigen::Index c = factors.front().cols();
    Eigen::MatrixXd stacked(c * Eigen::Index(factors.size()), c);
    for (size_t j = 0; j < factors.size(); ++j)
        stacked.middleRows(Eigen::Index(j) * c, c) = weights[Eigen::Index(j)] * factors[j];
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(stacked);
    return qr.matrixQR().topRows(c).triangularView<Eigen::Upper>();
}

// RMS per joint of the residual of pi: ||R_j [pi; -1]|| / sqrt(samples).
Eigen::VectorXd residualRms(const std::vector<Eigen::MatrixXd> &factors, const Eigen::VectorXd &pi,
                            Eigen::Index samples)
{
    Eigen::VectorXd x(pi.size() + 1);
    x << pi, -1.0;
    Eigen::VectorXd rms(Eigen::Index(factors.size()));
    for (size_t j = 0; j < factors.size(); ++j)
        rms[Eigen::Index(j)] = (factors[j] * x).norm() / std::sqrt(double(samples));
    return rms;
}

// The least-squares fit min ||A pi - b|| about the prior: the correction pi - prior in the
// directions whose singular value (columns scaled by d) is at least share times the largest;
// the rest stays at the prior.
struct TruncatedFit
{
    Eigen::VectorXd pi;
    Eigen::MatrixXd directions; ///< the determined directions in scaled units (p x rank)
    double largest = 0.0;       ///< largest singular value of A diag(1 / d)
    double condition = 0.0;
};

TruncatedFit truncatedFit(const Eigen::MatrixXd &a, const Eigen::VectorXd &b,
                          const Eigen::VectorXd &prior, const Eigen::VectorXd &d, double share)
{
    const Eigen::MatrixXd scaled = a * d.cwiseInverse().asDiagonal();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd &s = svd.singularValues();
    TruncatedFit fit;
    fit.largest = s.size() > 0 ? s[0] : 0.0;
    Eigen::Index rank = 0;
    while (rank < s.size() && s[rank] > share * fit.largest && s[rank] > 0.0)
        ++rank;
    const Eigen::VectorXd r0 = b - a * prior;
    const Eigen::VectorXd coefficients =
        (svd.matrixU().leftCols(rank).transpose() * r0).cwiseQuotient(s.head(rank));
    fit.pi = prior + d.cwiseInverse().asDiagonal() * (svd.matrixV().leftCols(rank) * coefficients);
    fit.directions = svd.matrixV().leftCols(rank);
    fit.condition = rank > 0 ? fit.largest / s[rank - 1] : 0.0;
    return fit;
}

} // namespace

std::vector<int> LogFit::undetermined() const
{
    std::vector<int> out;
    for (size_t i = 0; i < observedShare.size(); ++i) {
        if (observedShare[i] < 0.5)
            out.push_back(int(i));
    }
    return out;
}

LogFit fitLogs(const ChainModel &model, const std::vector<FilteredLog> &logs,
               const LogFitSettings &settings)
{
    const int n = model.dof();
    const int p = model.standardCount();
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
        throw Error(Text::tr("no samples to fit"));
    if (!(settings.priorShare > 0.0 && settings.priorShare < 1.0) ||
        !(settings.geometricShare > 0.0 && settings.geometricShare < 1.0))
        throw Error(Text::tr("the prior share must lie between 0 and 1"));

    LogFit fit;
    fit.samples = total;
    fit.baseCount = model.parameterCount();
    fit.prior = realBodyPrior(model.cadStandard(), n, model.nonnegativeStandard());
    const std::vector<Eigen::MatrixXd> factors = jointFactors(model, logs, total);

    // First pass unweighted: each joint's residual sets its weight.
    Eigen::MatrixXd r = stackedFactor(factors, Eigen::VectorXd::Ones(n));
    const auto columnScale = [p](const Eigen::MatrixXd &a) {
        Eigen::VectorXd d = a.colwise().norm().transpose();
        const double floor = 1e-3 * d.maxCoeff() + 1e-300;
        return Eigen::VectorXd(d.cwiseMax(floor));
    };
    TruncatedFit ls = truncatedFit(r.topLeftCorner(p, p), r.col(p).head(p), fit.prior,
                                   columnScale(r.topLeftCorner(p, p)), settings.priorShare);
    fit.jointNoise = residualRms(factors, ls.pi, total);
    if (settings.weighted) {
        const double floor = 1e-6 * fit.jointNoise.maxCoeff() + 1e-300;
        r = stackedFactor(factors, fit.jointNoise.cwiseMax(floor).cwiseInverse());
    }
    const Eigen::MatrixXd a = r.topLeftCorner(p, p);
    const Eigen::VectorXd b = r.col(p).head(p);
    const Eigen::VectorXd d = columnScale(a);
    ls = truncatedFit(a, b, fit.prior, d, settings.priorShare);
    fit.leastSquares = ls.pi;
    fit.rank = int(ls.directions.cols());
    fit.condition = ls.condition;

    // How much of each base parameter's direction the data determine: the base parameters are
    // K pi; in scaled units the determined subspace is spanned by the directions.
    const Eigen::MatrixXd k = model.base().baseMatrix() * d.cwiseInverse().asDiagonal();
    for (Eigen::Index i = 0; i < k.rows(); ++i) {
        const Eigen::RowVectorXd row = k.row(i);
        const double size = row.norm();
        fit.observedShare.push_back(size > 0.0 ? (row * ls.directions).norm() / size : 0.0);
    }
    // A standard parameter alone is the unit vector e_i in scaled units: its determined share
    // is the norm of row i of the orthonormal directions.
    for (Eigen::Index i = 0; i < p; ++i)
        fit.standardDetermined.push_back(std::min(1.0, ls.directions.row(i).norm()));

    fit.standard = fit.leastSquares;
    if (settings.consistent) {
        PlausibleProblem problem;
        problem.a = a;
        problem.b = b;
        problem.prior = fit.prior;
        problem.links = n;
        problem.nonnegative = model.nonnegativeStandard();
        // A joint term the data do not determine (a joint that never moves) keeps the CAD value.
        for (Eigen::Index i = 10 * n; i < p; ++i)
            if (fit.standardDetermined[size_t(i)] < 0.5)
                problem.heldAtPrior.push_back(int(i));
        if (settings.volumes)
            problem.volumes = linkVolumes(model.chain(), fit.prior);
        problem.priorShare = settings.geometricShare;
        if (settings.plausible)
            problem.rule = PlausibilityRule();
        const PlausibleEstimate c = plausibleEstimate(problem);
        fit.standard = c.standard;
        fit.converged = c.converged;
        fit.solverReport = c.report;
    }
    fit.base = model.baseFromStandard(fit.standard);
    fit.trainingRms = residualRms(factors, fit.standard, total);
    return fit;
}

double TorqueFigures::ratio(int joint) const
{
    const double m = rmsMeasured[joint];
    return m > 0.0 ? rmsError[joint] / m : 0.0;
}

Eigen::MatrixXd predictedTorque(const ChainModel &model, const Eigen::VectorXd &pi,
                                const FilteredLog &log)
{
    const int n = model.dof();
    Eigen::MatrixXd y(n, model.standardCount());
    Eigen::MatrixXd tau(log.q.cols(), n);
    for (Eigen::Index k = 0; k < log.q.cols(); ++k) {
        model.standardRegressor(log.q.col(k), log.qd.col(k), log.qdd.col(k), y);
        tau.row(k) = (y * pi).transpose();
    }
    return log.rows(std::move(tau)).transpose();
}

Eigen::MatrixXd measuredTorque(const FilteredLog &log)
{
    return log.rows(log.tau.transpose()).transpose();
}

TorqueFigures torqueFigures(const ChainModel &model, const Eigen::VectorXd &pi,
                            const FilteredLog &log)
{
    if (log.dof() != model.dof() || pi.size() != model.standardCount())
        throw Error(Text::tr("%1 does not fit the robot's joints or parameters").arg(log.source));
    return torqueFigures(measuredTorque(log), predictedTorque(model, pi, log));
}

TorqueFigures torqueFigures(const Eigen::MatrixXd &measured, const Eigen::MatrixXd &predicted)
{
    const Eigen::MatrixXd e = predicted - measured;
    const double samples = double(std::max<Eigen::Index>(measured.cols(), 1));
    TorqueFigures f;
    f.rmsError = (e.rowwise().squaredNorm() / samples).cwiseSqrt();
    f.rmsMeasured = (measured.rowwise().squaredNorm() / samples).cwiseSqrt();
    const double size = measured.squaredNorm();
    f.overall = size > 0.0 ? std::sqrt(e.squaredNorm() / size) : 0.0;
    const int n = int(measured.rows());
    for (int j = 0; j < n; ++j)
        f.meanRatio += f.ratio(j) / double(n);
    return f;
}

} // namespace learnid
