#include "identify/ObservableUpdate.h"

#include "model/Error.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

// Singular values and right singular vectors of a tall matrix, through the R of a QR.
Eigen::JacobiSVD<Eigen::MatrixXd> tallSvd(const Eigen::MatrixXd &a)
{
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
    const Eigen::MatrixXd r = qr.matrixQR().topRows(a.cols()).triangularView<Eigen::Upper>();
    return Eigen::JacobiSVD<Eigen::MatrixXd>(r, Eigen::ComputeFullV);
}

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

// cond(W^T W) with the columns of W scaled to unit norm.
double unitColumnCondition(const Eigen::MatrixXd &a, const Eigen::VectorXd &colNorm)
{
    Eigen::VectorXd unit = colNorm;
    for (Eigen::Index i = 0; i < unit.size(); ++i)
        unit[i] = colNorm[i] > 0.0 ? 1.0 / colNorm[i] : 1.0;
    const Eigen::VectorXd sv = tallSvd(a * unit.asDiagonal()).singularValues();
    const double minSv = sv[sv.size() - 1];
    return minSv > 0.0 ? (sv[0] / minSv) * (sv[0] / minSv) : std::numeric_limits<double>::infinity();
}

} // namespace

ParameterUpdate observableUpdate(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 const Eigen::VectorXd &rowWeightIn, const NoiseShaping &noise)
{
    checkSizes(a, b, n, phiPrev, rowWeightIn);
    const Eigen::Index rows = a.rows();
    const Eigen::Index m = a.cols();
    const Eigen::VectorXd rowWeight =
        rowWeightIn.size() == rows ? rowWeightIn : Eigen::VectorXd::Ones(rows);

    // Parameter scaling: a column times its parameter is the torque it explains.
    const Eigen::VectorXd colNorm = a.colwise().norm().transpose();
    Eigen::VectorXd scale = phiPrev.cwiseAbs();
    for (Eigen::Index i = 0; i < m; ++i)
        if (!(scale[i] > 0.0))
            scale[i] = colNorm[i] > 0.0 ? 1.0 / colNorm[i] : 1.0;
    const Eigen::MatrixXd scaled = a * scale.asDiagonal();

    // Observability is a property of the trajectory: decided on the unweighted scaled regressor.
    const auto svd = tallSvd(scaled);
    const Eigen::VectorXd sigma = svd.singularValues();
    const double sigmaMax = sigma.size() > 0 ? sigma[0] : 0.0;
    int rank = 0;
    while (rank < m && sigmaMax > 0.0 && sigma[rank] > tolerance * sigmaMax)
        ++rank;
    const Eigen::MatrixXd vr = svd.matrixV().leftCols(rank);
    const Eigen::MatrixXd kept = svd.matrixV().rightCols(m - rank);

    // Weighted least squares inside the observable subspace: phi = phiPrev + D V_r x.
    ParameterUpdate out;
    out.rank = rank;
    out.phi = phiPrev;
    Eigen::MatrixXd covX = Eigen::MatrixXd::Zero(rank, rank);
    if (rank > 0) {
        const Eigen::MatrixXd bw = rowWeight.asDiagonal() * (scaled * vr);
        const Eigen::VectorXd rw = rowWeight.cwiseProduct(b - a * phiPrev);
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(bw);
        const Eigen::MatrixXd r = qr.matrixQR().topRows(rank).triangularView<Eigen::Upper>();
        const Eigen::VectorXd qtr = (qr.householderQ().adjoint() * rw).head(rank);
        const Eigen::VectorXd x = r.triangularView<Eigen::Upper>().solve(qtr);
        out.phi += scale.cwiseProduct(vr * x);
        const Eigen::MatrixXd rInv =
            r.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(rank, rank));
        covX = rInv * rInv.transpose(); // (B^T B)^-1
        if (noise.transposedApplied.rows() == rows && noise.transposedApplied.cols() == m) {
            // Row weights are constant per joint signal, so they commute with H.
            const Eigen::MatrixXd hb =
                rowWeight.asDiagonal() * (noise.transposedApplied * scale.asDiagonal() * vr);
            covX = covX * (hb.transpose() * hb) * covX;
        }
    }

    const Eigen::VectorXd residual = b - a * out.phi;
    const Eigen::Index samples = rows / n;
    out.residualRms =
        Eigen::Map<const Eigen::MatrixXd>(residual.data(), n, samples).rowwise().squaredNorm();
    out.residualRms = (out.residualRms / double(samples)).cwiseSqrt();

    // Var(phi) = sigma_w^2 D V_r covX V_r^T D, with sigma_w^2 the weighted residual variance
    // before the rows were filtered.
    const double dofLeft = double(std::max<Eigen::Index>(1, rows - rank));
    const double s2 = rowWeight.cwiseProduct(residual).squaredNorm() / dofLeft
                      / std::max(noise.varianceGain, 1e-300);
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
    out.condition = unitColumnCondition(a, colNorm);
    return out;
}

} // namespace learnid
