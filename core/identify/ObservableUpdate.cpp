#include "identify/ObservableUpdate.h"

#include "model/Error.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

void checkSizes(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                const Eigen::VectorXd &phiPrev, const Eigen::VectorXd &rowWeight)
{
    const Eigen::Index rows = a.rows();
    if (n <= 0 || rows % n != 0 || b.size() != rows || phiPrev.size() != a.cols()
        || (rowWeight.size() != 0 && rowWeight.size() != rows) || rows < a.cols()) {
        throw Error(QCoreApplication::translate(
                        "ObservableUpdate",
                        "least squares sizes do not match: %1 x %2 regressor, %3 targets, "
                        "%4 joints, %5 parameters")
                        .arg(rows)
                        .arg(a.cols())
                        .arg(b.size())
                        .arg(n)
                        .arg(phiPrev.size()));
    }
    if (!a.allFinite() || !b.allFinite() || !phiPrev.allFinite()
        || (rowWeight.size() != 0 && !rowWeight.allFinite())) {
        throw Error(QCoreApplication::translate(
            "ObservableUpdate", "the regressor or the torque contains non-finite values"));
    }
}

// Eigen-decomposition of a symmetric Gram matrix, largest eigenvalue first.
struct SortedEigen
{
    Eigen::VectorXd values;
    Eigen::MatrixXd vectors;
};

SortedEigen sortedEigen(const Eigen::MatrixXd &gram)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(gram);
    return {es.eigenvalues().reverse().cwiseMax(0.0), es.eigenvectors().rowwise().reverse()};
}

} // namespace

ParameterUpdate observableUpdate(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 const Eigen::VectorXd &rowWeightIn, const NoiseShaping &noise)
{
    checkSizes(a, b, n, phiPrev, rowWeightIn);
    const Eigen::Index rows = a.rows();
    const Eigen::Index m = a.cols();
    const bool weighted = rowWeightIn.size() == rows;
    const Eigen::VectorXd w2 = weighted ? rowWeightIn.cwiseAbs2() : Eigen::VectorXd();

    // Gram matrices in one pass each. Columns are scaled before any decision, which keeps the
    // conditioning of the scaled Gram matrix near that of the problem (cond(W^T W) ~ 10-100 on
    // a line, DESIGN.md §1.6); rankTolerance >= 1e-6 keeps sigma^2 ratios far above rounding.
    const Eigen::MatrixXd gram = a.transpose() * a;
    const Eigen::MatrixXd gramW = weighted ? Eigen::MatrixXd(a.transpose() * w2.asDiagonal() * a)
                                           : gram;
    const Eigen::VectorXd residualPrev = b - a * phiPrev;
    const Eigen::VectorXd rhs = weighted ? Eigen::VectorXd(a.transpose() * w2.cwiseProduct(residualPrev))
                                         : Eigen::VectorXd(a.transpose() * residualPrev);

    // Parameter scaling: a column times its parameter is the torque it explains.
    const Eigen::VectorXd colNorm = gram.diagonal().cwiseSqrt();
    Eigen::VectorXd scale = phiPrev.cwiseAbs();
    for (Eigen::Index i = 0; i < m; ++i)
        if (!(scale[i] > 0.0))
            scale[i] = colNorm[i] > 0.0 ? 1.0 / colNorm[i] : 1.0;

    // Observability is a property of the trajectory: decided on the unweighted scaled regressor.
    const SortedEigen eig = sortedEigen(scale.asDiagonal() * gram * scale.asDiagonal());
    const double lambdaMax = eig.values.size() > 0 ? eig.values[0] : 0.0;
    int rank = 0;
    while (rank < m && lambdaMax > 0.0 && eig.values[rank] > tolerance * tolerance * lambdaMax)
        ++rank;
    const Eigen::MatrixXd vr = eig.vectors.leftCols(rank);
    const Eigen::MatrixXd kept = eig.vectors.rightCols(m - rank);

    // Weighted least squares inside the observable subspace: phi = phiPrev + D V_r x.
    ParameterUpdate out;
    out.rank = rank;
    out.phi = phiPrev;
    Eigen::MatrixXd covX = Eigen::MatrixXd::Zero(rank, rank);
    if (rank > 0) {
        const Eigen::MatrixXd dv = scale.asDiagonal() * vr;
        const Eigen::MatrixXd btb = dv.transpose() * gramW * dv;
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(btb);
        out.phi += dv * ldlt.solve(dv.transpose() * rhs);
        covX = ldlt.solve(Eigen::MatrixXd::Identity(rank, rank)); // (B^T B)^-1
        if (noise.transposedApplied.rows() == rows && noise.transposedApplied.cols() == m) {
            // Row weights are constant per joint signal, so they commute with H.
            const Eigen::MatrixXd &h = noise.transposedApplied;
            const Eigen::MatrixXd gramH = weighted
                                              ? Eigen::MatrixXd(h.transpose() * w2.asDiagonal() * h)
                                              : Eigen::MatrixXd(h.transpose() * h);
            covX = covX * (dv.transpose() * gramH * dv) * covX;
        }
    }

    const Eigen::VectorXd residual = b - a * out.phi;
    const Eigen::Index samples = rows / n;
    const Eigen::Map<const Eigen::MatrixXd> perJoint(residual.data(), n, samples);
    out.residualRms = (perJoint.rowwise().squaredNorm() / double(samples)).cwiseSqrt();

    // Var(phi) = sigma_w^2 D V_r covX V_r^T D, with sigma_w^2 the weighted residual variance
    // before the rows were filtered.
    const double dofLeft = double(std::max<Eigen::Index>(1, rows - rank));
    const double weightedSquares = weighted ? residual.cwiseAbs2().dot(w2) : residual.squaredNorm();
    const double s2 = weightedSquares / dofLeft / std::max(noise.varianceGain, 1e-300);
    const Eigen::MatrixXd cov = vr * covX * vr.transpose();
    out.phiStd = (s2 * cov.diagonal()).cwiseMax(0.0).cwiseSqrt().cwiseProduct(scale);
    out.observable.assign(size_t(m), true);
    for (Eigen::Index i = 0; i < m; ++i) {
        // A parameter with a noticeable share in a kept direction is not determined by the data.
        if (kept.cols() > 0 && kept.row(i).squaredNorm() > 1e-2) {
            out.observable[size_t(i)] = false;
            out.phiStd[i] = std::numeric_limits<double>::infinity();
        }
    }

    // Conditioning as usually quoted: cond(W^T W) with unit-norm columns.
    Eigen::VectorXd unit = colNorm;
    for (Eigen::Index i = 0; i < m; ++i)
        unit[i] = colNorm[i] > 0.0 ? 1.0 / colNorm[i] : 1.0;
    const Eigen::VectorXd ev = sortedEigen(unit.asDiagonal() * gram * unit.asDiagonal()).values;
    out.condition = ev[m - 1] > 0.0 ? ev[0] / ev[m - 1] : std::numeric_limits<double>::infinity();
    return out;
}

} // namespace learnid
