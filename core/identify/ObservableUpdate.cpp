#include "identify/ObservableUpdate.h"

#include "model/Error.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <QCoreApplication>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

// Singular values and right vectors of a (rows x m), through R of a QR when a is tall.
// Also returns Q^T y truncated to m rows, so that U^T y = Uq^T (Q^T y).
struct ReducedSvd
{
    Eigen::VectorXd sigma;
    Eigen::MatrixXd u; // m x m, left vectors of R
    Eigen::MatrixXd v;
    Eigen::VectorXd qty;
};

ReducedSvd reducedSvd(const Eigen::MatrixXd &a, const Eigen::VectorXd &y)
{
    const Eigen::Index m = a.cols();
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
    const Eigen::MatrixXd r = qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
    const Eigen::VectorXd qty = (qr.householderQ().adjoint() * y).head(m);
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
    return {svd.singularValues(), svd.matrixU(), svd.matrixV(), qty};
}

} // namespace

ParameterUpdate observableUpdate(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                                 const Eigen::VectorXd &phiPrev, double tolerance,
                                 const Eigen::VectorXd &rowWeightIn)
{
    const Eigen::Index rows = a.rows();
    const Eigen::Index m = a.cols();
    if (n <= 0 || rows % n != 0 || b.size() != rows || phiPrev.size() != m
        || (rowWeightIn.size() != 0 && rowWeightIn.size() != rows) || rows < m) {
        throw Error(QCoreApplication::translate(
                        "ObservableUpdate",
                        "least squares sizes do not match: %1 x %2 regressor, %3 targets, "
                        "%4 joints, %5 parameters")
                        .arg(rows)
                        .arg(m)
                        .arg(b.size())
                        .arg(n)
                        .arg(phiPrev.size()));
    }
    if (!a.allFinite() || !b.allFinite() || !phiPrev.allFinite()) {
        throw Error(QCoreApplication::translate(
            "ObservableUpdate", "the regressor or the torque contains non-finite values"));
    }

    const Eigen::VectorXd rowWeight =
        rowWeightIn.size() == rows ? rowWeightIn : Eigen::VectorXd::Ones(rows);

    // Parameter scaling: a column times its parameter is the torque it explains.
    Eigen::VectorXd scale = phiPrev.cwiseAbs();
    const Eigen::VectorXd colNorm = a.colwise().norm().transpose();
    for (Eigen::Index i = 0; i < m; ++i)
        if (!(scale[i] > 0.0))
            scale[i] = colNorm[i] > 0.0 ? 1.0 / colNorm[i] : 1.0;

    const Eigen::VectorXd residualPrev = b - a * phiPrev;
    const Eigen::MatrixXd weighted = rowWeight.asDiagonal() * a * scale.asDiagonal();
    const ReducedSvd svd = reducedSvd(weighted, rowWeight.cwiseProduct(residualPrev));

    ParameterUpdate out;
    const double sigmaMax = svd.sigma.size() > 0 ? svd.sigma[0] : 0.0;
    Eigen::VectorXd step = Eigen::VectorXd::Zero(m);
    Eigen::MatrixXd covScaled = Eigen::MatrixXd::Zero(m, m);
    Eigen::MatrixXd kept = Eigen::MatrixXd::Zero(m, 0);
    for (Eigen::Index i = 0; i < m; ++i) {
        const double s = svd.sigma[i];
        if (sigmaMax > 0.0 && s > tolerance * sigmaMax) {
            step += svd.v.col(i) * (svd.u.col(i).dot(svd.qty) / s);
            covScaled += svd.v.col(i) * svd.v.col(i).transpose() / (s * s);
            ++out.rank;
        } else {
            kept.conservativeResize(m, kept.cols() + 1);
            kept.col(kept.cols() - 1) = svd.v.col(i);
        }
    }
    out.phi = phiPrev + scale.cwiseProduct(step);

    const Eigen::VectorXd residual = b - a * out.phi;
    out.residualRms.resize(n);
    const Eigen::Index samples = rows / n;
    for (int j = 0; j < n; ++j) {
        double sum = 0.0;
        for (Eigen::Index k = 0; k < samples; ++k)
            sum += residual[k * n + j] * residual[k * n + j];
        out.residualRms[j] = std::sqrt(sum / double(samples));
    }

    // Var(phi) = s^2 D (V_r S_r^-2 V_r^T) D, s^2 the weighted residual variance.
    const double dofLeft = double(std::max<Eigen::Index>(1, rows - out.rank));
    const double s2 = rowWeight.cwiseProduct(residual).squaredNorm() / dofLeft;
    out.phiStd = (s2 * covScaled.diagonal()).cwiseSqrt().cwiseProduct(scale);
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
    const Eigen::JacobiSVD<Eigen::MatrixXd> plain(
        Eigen::HouseholderQR<Eigen::MatrixXd>(a * unit.asDiagonal())
            .matrixQR()
            .topRows(m)
            .triangularView<Eigen::Upper>());
    const Eigen::VectorXd sv = plain.singularValues();
    const double minSv = sv[m - 1];
    out.condition = minSv > 0.0 ? (sv[0] / minSv) * (sv[0] / minSv)
                                : std::numeric_limits<double>::infinity();
    return out;
}

} // namespace learnid
