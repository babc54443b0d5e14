#include "identify/ObservableUpdate.h"

#include "identify/GramBlock.h"

#include "model/Error.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

Error nonFiniteError()
{
    return Error(QCoreApplication::translate(
        "ObservableUpdate", "the regressor or the torque contains non-finite values"));
}

void checkSizes(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                const Eigen::VectorXd &phiPrev, const Eigen::VectorXd &rowWeight)
{
    const Eigen::Index rows = a.rows();
    if (n <= 0 || rows % n != 0 || b.size() != rows || phiPrev.size() != a.cols() ||
        (rowWeight.size() != 0 && rowWeight.size() != rows) || rows < a.cols())
        throw sizeError(rows, a.cols(), b.size(), n, phiPrev.size());
    if (!a.allFinite() || !b.allFinite() || !phiPrev.allFinite() ||
        (rowWeight.size() != 0 && !rowWeight.allFinite()))
        throw nonFiniteError();
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

// The update from the Gram matrices (common to the stacked rows and the Gram blocks): gram is
// A^T A, gramW A^T W^2 A, rhs A^T W^2 (b - A phiPrev), gramH (H^T A)^T W^2 (H^T A) or null.
// Fills phi, rank, condition and observable; cov (m x m, scaled parameters) is the covariance of
// the update for unit noise variance, set by finishStd().
struct Solved
{
    ParameterUpdate out;
    Eigen::VectorXd scale;
    Eigen::MatrixXd cov;
};

Solved solveNormalEquations(const Eigen::MatrixXd &gram, const Eigen::MatrixXd &gramW,
                            const Eigen::VectorXd &rhs, const Eigen::MatrixXd *gramH,
                            const Eigen::VectorXd &phiPrev, double tolerance)
{
    const Eigen::Index m = gram.cols();
    // Parameter scaling: a column times its parameter is the torque it explains. Columns are
    // scaled before any decision, which keeps the conditioning of the scaled Gram matrix near
    // that of the problem (cond(W^T W) ~ 10-100 on a line, docs/design.md §1.6);
    // rankTolerance >= 1e-6 keeps sigma^2 ratios far above rounding.
    const Eigen::VectorXd colNorm = gram.diagonal().cwiseSqrt();
    Solved s;
    s.scale = phiPrev.cwiseAbs();
    for (Eigen::Index i = 0; i < m; ++i)
        if (!(s.scale[i] > 0.0))
            s.scale[i] = colNorm[i] > 0.0 ? 1.0 / colNorm[i] : 1.0;
    const Eigen::VectorXd &scale = s.scale;

    // Observability is a property of the trajectory: decided on the unweighted scaled regressor.
    const SortedEigen eig = sortedEigen(scale.asDiagonal() * gram * scale.asDiagonal());
    const double lambdaMax = eig.values.size() > 0 ? eig.values[0] : 0.0;
    int rank = 0;
    while (rank < m && lambdaMax > 0.0 && eig.values[rank] > tolerance * tolerance * lambdaMax)
        ++rank;
    const Eigen::MatrixXd vr = eig.vectors.leftCols(rank);
    const Eigen::MatrixXd kept = eig.vectors.rightCols(m - rank);

    // Weighted least squares inside the observable subspace: phi = phiPrev + D V_r x.
    ParameterUpdate &out = s.out;
    out.rank = rank;
    out.phi = phiPrev;
    Eigen::MatrixXd covX = Eigen::MatrixXd::Zero(rank, rank);
    if (rank > 0) {
        const Eigen::MatrixXd dv = scale.asDiagonal() * vr;
        const Eigen::MatrixXd btb = dv.transpose() * gramW * dv;
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(btb);
        out.phi += dv * ldlt.solve(dv.transpose() * rhs);
        covX = ldlt.solve(Eigen::MatrixXd::Identity(rank, rank)); // (B^T B)^-1
        if (gramH)
            covX = covX * (dv.transpose() * *gramH * dv) * covX;
    }
    s.cov = vr * covX * vr.transpose();

    out.observable.assign(size_t(m), true);
    for (Eigen::Index i = 0; i < m; ++i) {
        // A parameter with a noticeable share in a kept direction is not determined by the data.
        if (kept.cols() > 0 && kept.row(i).squaredNorm() > 1e-2)
            out.observable[size_t(i)] = false;
    }

    // Conditioning as usually quoted: cond(W^T W) with unit-norm columns.
    Eigen::VectorXd unit = colNorm;
    for (Eigen::Index i = 0; i < m; ++i)
        unit[i] = colNorm[i] > 0.0 ? 1.0 / colNorm[i] : 1.0;
    const Eigen::VectorXd ev = sortedEigen(unit.asDiagonal() * gram * unit.asDiagonal()).values;
    out.condition = ev[m - 1] > 0.0 ? ev[0] / ev[m - 1] : std::numeric_limits<double>::infinity();
    return s;
}

// Var(phi) = sigma_w^2 D V_r covX V_r^T D, with sigma_w^2 the weighted residual variance before
// the rows were filtered: weightedSquares = ||W (b - A phi)||^2 over `rows` rows.
ParameterUpdate finishStd(Solved s, double weightedSquares, Eigen::Index rows, double varianceGain)
{
    ParameterUpdate &out = s.out;
    const double dofLeft = double(std::max<Eigen::Index>(1, rows - out.rank));
    const double s2 = weightedSquares / dofLeft / std::max(varianceGain, 1e-300);
    out.phiStd = (s2 * s.cov.diagonal()).cwiseMax(0.0).cwiseSqrt().cwiseProduct(s.scale);
    for (size_t i = 0; i < out.observable.size(); ++i)
        if (!out.observable[i])
            out.phiStd[Eigen::Index(i)] = std::numeric_limits<double>::infinity();
    return std::move(s.out);
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

    // Gram matrices in one pass each.
    const Eigen::MatrixXd gram = a.transpose() * a;
    const Eigen::MatrixXd gramW =
        weighted ? Eigen::MatrixXd(a.transpose() * w2.asDiagonal() * a) : gram;
    const Eigen::VectorXd residualPrev = b - a * phiPrev;
    const Eigen::VectorXd rhs = weighted
                                    ? Eigen::VectorXd(a.transpose() * w2.cwiseProduct(residualPrev))
                                    : Eigen::VectorXd(a.transpose() * residualPrev);
    Eigen::MatrixXd gramH;
    const bool shaped =
        noise.transposedApplied.rows() == rows && noise.transposedApplied.cols() == m;
    if (shaped) {
        // Row weights are constant per joint signal, so they commute with H.
        const Eigen::MatrixXd &h = noise.transposedApplied;
        gramH = weighted ? Eigen::MatrixXd(h.transpose() * w2.asDiagonal() * h)
                         : Eigen::MatrixXd(h.transpose() * h);
    }
    Solved s =
        solveNormalEquations(gram, gramW, rhs, shaped ? &gramH : nullptr, phiPrev, tolerance);

    const Eigen::VectorXd residual = b - a * s.out.phi;
    const Eigen::Index samples = rows / n;
    const Eigen::Map<const Eigen::MatrixXd> perJoint(residual.data(), n, samples);
    s.out.residualRms = (perJoint.rowwise().squaredNorm() / double(samples)).cwiseSqrt();
    const double weightedSquares = weighted ? residual.cwiseAbs2().dot(w2) : residual.squaredNorm();
    return finishStd(std::move(s), weightedSquares, rows, noise.varianceGain);
}

ParameterUpdate observableUpdate(const std::vector<const GramBlock *> &blocks,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 double varianceGain)
{
    const Eigen::Index m = phiPrev.size();
    const int n = blocks.empty() ? 0 : blocks.front()->joints();
    if (blocks.empty())
        throw sizeError(0, m, 0, n, m);
    Eigen::Index samples = 0;
    bool shaped = true;
    for (const GramBlock *block : blocks) {
        if (block->joints() != n || block->parameters() != m)
            throw sizeError(block->samples() * block->joints(), block->parameters(),
                            block->samples() * block->joints(), block->joints(), m);
        if (!block->allFinite() || !phiPrev.allFinite())
            throw nonFiniteError();
        samples += block->samples();
        shaped = shaped && block->shaped();
    }
    const Eigen::Index rows = samples * n;
    if (rows < m)
        throw sizeError(rows, m, rows, n, m);

    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(m, m), gramW = gram, gramH = gram;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
    for (const GramBlock *block : blocks) {
        for (int j = 0; j < n; ++j) {
            const double w2 = block->weight(j) * block->weight(j);
            gram += block->gram(j);
            gramW += w2 * block->gram(j);
            rhs += w2 * block->gradientAt(j, phiPrev);
            if (shaped)
                gramH += w2 * block->shapedGram(j);
        }
    }
    Solved s =
        solveNormalEquations(gram, gramW, rhs, shaped ? &gramH : nullptr, phiPrev, tolerance);

    Eigen::VectorXd squares = Eigen::VectorXd::Zero(n);
    double weightedSquares = 0.0;
    for (const GramBlock *block : blocks) {
        const Eigen::VectorXd r2 = block->residualSquaresAt(s.out.phi);
        squares += r2;
        for (int j = 0; j < n; ++j)
            weightedSquares += block->weight(j) * block->weight(j) * r2[j];
    }
    s.out.residualRms = (squares / double(samples)).cwiseSqrt();
    return finishStd(std::move(s), weightedSquares, rows, varianceGain);
}

} // namespace learnid
