#include "identify/ObservableUpdate.h"

#include "identify/GramBlock.h"

#include "model/Error.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <cmath>
#include <functional>
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

// 1 / (joint j's torque level) for the observability decision: the RMS of the torque the rows
// explain (levelSquares: its sum of squares over the rows), no lower than 1e-3
// of the strongest joint's, so that a joint the model gives no torque does not weigh without
// bound. No torque at all leaves the rows as they are.
Eigen::VectorXd jointLevelWeights(const Eigen::VectorXd &levelSquares, Eigen::Index samples)
{
    const Eigen::VectorXd level =
        (levelSquares / double(std::max<Eigen::Index>(samples, 1))).cwiseMax(0.0).cwiseSqrt();
    const double strongest = level.size() > 0 ? level.maxCoeff() : 0.0;
    if (!(strongest > 0.0) || !std::isfinite(strongest))
        return Eigen::VectorXd::Ones(levelSquares.size());
    // Weights relative to the strongest joint (1 there) keep gramObs at gram's magnitude.
    return (level.cwiseMax(1e-3 * strongest) / strongest).cwiseInverse();
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
// A^T A, gramObs the same with each joint's rows divided by its torque level, gramW
// A^T W^2 A, rhs A^T W^2 (b - A phiPrev), gramH (H^T A)^T W^2 (H^T A) or null. Fills phi, rank,
// condition, observable and phiStd.
struct NormalEquations
{
    Eigen::MatrixXd gram, gramObs, gramW, gramH;
    Eigen::VectorXd rhs;
    bool shaped = false;
    Eigen::Index rows = 0;     ///< rows stacked (samples x joints)
    double varianceGain = 1.0; ///< NoiseShaping::varianceGain
    /// ||W (b - A phi)||^2 at any phi.
    std::function<double(const Eigen::VectorXd &)> weightedSquaresAt;
};

// Inside the subspace D V (columns: scaled directions), the weighted least-squares step x with
// phi = phiPrev + D V x, and the covariance of x for unit noise variance.
struct SubspaceStep
{
    Eigen::VectorXd x;
    Eigen::MatrixXd covX;
};

SubspaceStep solveIn(const NormalEquations &eq, const Eigen::MatrixXd &dv)
{
    const Eigen::Index k = dv.cols();
    SubspaceStep step{Eigen::VectorXd::Zero(k), Eigen::MatrixXd::Zero(k, k)};
    if (k == 0)
        return step;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(dv.transpose() * eq.gramW * dv);
    step.x = ldlt.solve(dv.transpose() * eq.rhs);
    step.covX = ldlt.solve(Eigen::MatrixXd::Identity(k, k)); // (B^T B)^-1
    if (eq.shaped)
        step.covX = step.covX * (dv.transpose() * eq.gramH * dv) * step.covX;
    return step;
}

// sigma_w^2: the weighted residual variance before the rows were filtered.
double noiseVariance(const NormalEquations &eq, const Eigen::VectorXd &phi, Eigen::Index rank)
{
    const double dofLeft = double(std::max<Eigen::Index>(1, eq.rows - rank));
    return eq.weightedSquaresAt(phi) / dofLeft / std::max(eq.varianceGain, 1e-300);
}

ParameterUpdate solveNormalEquations(const NormalEquations &eq, const Eigen::VectorXd &phiPrev,
                                     const Eigen::VectorXd &scaleFloor, double tolerance,
                                     double maxRelativeStd)
{
    const Eigen::Index m = eq.gram.cols();
    // Parameter scaling: a column times its parameter is the torque it explains. Columns are
    // scaled before any decision, which keeps the conditioning of the scaled Gram matrix near
    // that of the problem (cond(W^T W) ~ 10-100 on a line, docs/design.md §1.6);
    // rankTolerance >= 1e-6 keeps sigma^2 ratios far above rounding. The scale does not fall
    // below scaleFloor (a parameter moved near 0 stays as visible as it was).
    const Eigen::VectorXd colNorm = eq.gram.diagonal().cwiseSqrt();
    const Eigen::VectorXd obsNorm = eq.gramObs.diagonal().cwiseSqrt();
    Eigen::VectorXd scale = phiPrev.cwiseAbs();
    if (scaleFloor.size() == m)
        scale = scale.cwiseMax(scaleFloor.cwiseAbs());
    for (Eigen::Index i = 0; i < m; ++i)
        if (!(scale[i] > 0.0))
            scale[i] = obsNorm[i] > 0.0 ? 1.0 / obsNorm[i] : 1.0;

    // 1. Observability is a property of the trajectory: decided on the unweighted scaled
    // regressor, or with jointLevels on the one whose joints' rows are each divided by that
    // joint's torque level (jointLevelWeights): a wrist's parameters then count by the share of
    // the wrist's torque they explain, not by their share of the shoulder's gravity.
    const SortedEigen eig = sortedEigen(scale.asDiagonal() * eq.gramObs * scale.asDiagonal());
    const double lambdaMax = eig.values.size() > 0 ? eig.values[0] : 0.0;
    int rank = 0;
    while (rank < m && lambdaMax > 0.0 && eig.values[rank] > tolerance * tolerance * lambdaMax)
        ++rank;
    Eigen::MatrixXd vr = eig.vectors.leftCols(rank);
    Eigen::MatrixXd kept = eig.vectors.rightCols(m - rank);

    // 2. Weighted least squares inside the observable subspace: phi = phiPrev + D V_r x.
    ParameterUpdate out;
    SubspaceStep step = solveIn(eq, scale.asDiagonal() * vr);
    out.phi = phiPrev + scale.asDiagonal() * (vr * step.x);
    double s2 = noiseVariance(eq, out.phi, rank);

    // 3. Each direction at the weight its data deserve: a direction whose standard deviation is
    // above maxRelativeStd of the parameters' scale is not determined by these samples (a short
    // record, a badly fitting one) and keeps phiPrev's component too.
    if (rank > 0 && std::isfinite(maxRelativeStd)) {
        const SortedEigen spread = sortedEigen(s2 * step.covX); // largest variance first
        int drop = 0;
        while (drop < rank && spread.values[drop] > maxRelativeStd * maxRelativeStd)
            ++drop;
        if (drop > 0) {
            const Eigen::MatrixXd u = spread.vectors.rightCols(rank - drop);
            Eigen::MatrixXd moved(m, m - rank + drop);
            moved << kept, vr * spread.vectors.leftCols(drop);
            kept = moved;
            vr = vr * u;
            rank -= drop;
            step = solveIn(eq, scale.asDiagonal() * vr);
            out.phi = phiPrev + scale.asDiagonal() * (vr * step.x);
            s2 = noiseVariance(eq, out.phi, rank);
        }
    }
    out.rank = rank;

    // Var(phi) = sigma_w^2 D V_r covX V_r^T D.
    const Eigen::MatrixXd cov = vr * step.covX * vr.transpose();
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
    const Eigen::VectorXd ev = sortedEigen(unit.asDiagonal() * eq.gram * unit.asDiagonal()).values;
    out.condition = ev[m - 1] > 0.0 ? ev[0] / ev[m - 1] : std::numeric_limits<double>::infinity();
    return out;
}

} // namespace

ParameterUpdate observableUpdate(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 const Eigen::VectorXd &rowWeightIn, const NoiseShaping &noise,
                                 const Eigen::VectorXd &scaleFloor, double maxRelativeStd,
                                 bool jointLevels)
{
    checkSizes(a, b, n, phiPrev, rowWeightIn);
    const Eigen::Index rows = a.rows();
    const Eigen::Index m = a.cols();
    const Eigen::Index samples = rows / n;
    const bool weighted = rowWeightIn.size() == rows;
    const Eigen::VectorXd w2 =
        weighted ? Eigen::VectorXd(rowWeightIn.cwiseAbs2()) : Eigen::VectorXd::Ones(rows);

    // Gram matrices in one pass each.
    NormalEquations eq;
    eq.rows = rows;
    eq.varianceGain = noise.varianceGain;
    eq.gram = a.transpose() * a;
    const Eigen::VectorXd predicted = a * phiPrev;
    const Eigen::Map<const Eigen::MatrixXd> measuredPerJoint(b.data(), n, samples);
    const Eigen::VectorXd jointWeight =
        jointLevels ? jointLevelWeights(measuredPerJoint.rowwise().squaredNorm(), samples)
                    : Eigen::VectorXd::Ones(n);
    Eigen::VectorXd obsRowWeight2(rows);
    for (Eigen::Index r = 0; r < rows; ++r)
        obsRowWeight2[r] = jointWeight[r % n] * jointWeight[r % n];
    eq.gramObs = a.transpose() * obsRowWeight2.asDiagonal() * a;
    eq.gramW = weighted ? Eigen::MatrixXd(a.transpose() * w2.asDiagonal() * a) : eq.gram;
    eq.rhs = a.transpose() * w2.cwiseProduct(b - predicted);
    eq.shaped = noise.transposedApplied.rows() == rows && noise.transposedApplied.cols() == m;
    if (eq.shaped) {
        // Row weights are constant per joint signal, so they commute with H.
        const Eigen::MatrixXd &h = noise.transposedApplied;
        eq.gramH = h.transpose() * w2.asDiagonal() * h;
    }
    eq.weightedSquaresAt = [&](const Eigen::VectorXd &phi) {
        return (b - a * phi).cwiseAbs2().dot(w2);
    };
    ParameterUpdate out = solveNormalEquations(eq, phiPrev, scaleFloor, tolerance, maxRelativeStd);

    const Eigen::VectorXd residual = b - a * out.phi;
    const Eigen::Map<const Eigen::MatrixXd> perJoint(residual.data(), n, samples);
    out.residualRms = (perJoint.rowwise().squaredNorm() / double(samples)).cwiseSqrt();
    return out;
}

ParameterUpdate observableUpdate(const std::vector<const GramBlock *> &blocks,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 double varianceGain, const Eigen::VectorXd &scaleFloor,
                                 double maxRelativeStd, bool jointLevels)
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

    // Each joint's torque level: what it measured (the rows' targets, noise included, so that a
    // joint whose torque is mostly noise does not count as strong), else what phiPrev predicts.
    Eigen::VectorXd levelSquares = Eigen::VectorXd::Zero(n);
    for (const GramBlock *block : blocks)
        for (int j = 0; j < n; ++j)
            levelSquares[j] += block->targetSquares(j) > 0.0
                                   ? block->targetSquares(j)
                                   : phiPrev.dot(block->gram(j) * phiPrev);
    const Eigen::VectorXd jointWeight =
        jointLevels ? jointLevelWeights(levelSquares, samples) : Eigen::VectorXd::Ones(n);

    NormalEquations eq;
    eq.rows = rows;
    eq.varianceGain = varianceGain;
    eq.shaped = shaped;
    eq.gram = Eigen::MatrixXd::Zero(m, m);
    eq.gramObs = eq.gramW = eq.gramH = eq.gram;
    eq.rhs = Eigen::VectorXd::Zero(m);
    for (const GramBlock *block : blocks) {
        for (int j = 0; j < n; ++j) {
            const double w2 = block->weight(j) * block->weight(j);
            eq.gram += block->gram(j);
            eq.gramObs += jointWeight[j] * jointWeight[j] * block->gram(j);
            eq.gramW += w2 * block->gram(j);
            eq.rhs += w2 * block->gradientAt(j, phiPrev);
            if (shaped)
                eq.gramH += w2 * block->shapedGram(j);
        }
    }
    eq.weightedSquaresAt = [&](const Eigen::VectorXd &phi) {
        double sum = 0.0;
        for (const GramBlock *block : blocks) {
            const Eigen::VectorXd r2 = block->residualSquaresAt(phi);
            for (int j = 0; j < n; ++j)
                sum += block->weight(j) * block->weight(j) * r2[j];
        }
        return sum;
    };
    ParameterUpdate out = solveNormalEquations(eq, phiPrev, scaleFloor, tolerance, maxRelativeStd);

    Eigen::VectorXd squares = Eigen::VectorXd::Zero(n);
    for (const GramBlock *block : blocks)
        squares += block->residualSquaresAt(out.phi);
    out.residualRms = (squares / double(samples)).cwiseSqrt();
    return out;
}

} // namespace learnid
