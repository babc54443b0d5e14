#include "identify/PayloadEstimate.h"

#include "model/Error.h"
#include "model/PlausibleEstimate.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadEstimate)
};

using Vector10 = Eigen::Matrix<double, 10, 1>;

// m, c, I_c (xx, xy, yy, xz, yz, zz) of pi, without requiring a positive mass of an
// intermediate value (the derivative is taken around a positive one).
Vector10 bodyOf(const Vector10 &pi)
{
    const double m = pi[0];
    const Eigen::Vector3d h = pi.segment<3>(1);
    const Eigen::Matrix3d shift =
        (h.squaredNorm() * Eigen::Matrix3d::Identity() - h * h.transpose()) / m;
    const Eigen::Matrix3d ic = rotationalInertia(pi) - shift;
    Vector10 out;
    out << m, h / m, ic(0, 0), ic(0, 1), ic(1, 1), ic(0, 2), ic(1, 2), ic(2, 2);
    return out;
}

// Which parameters each body value depends on: c_a on m and m c_a; each entry of I_c on m, m c
// and that entry of I.
bool dependsOn(int value, int parameter)
{
    if (value == 0)
        return parameter == 0;
    if (value < 4)
        return parameter == 0 || parameter == value;
    return parameter < 4 || parameter == value;
}

} // namespace

QStringList PayloadEstimate::bodyNames()
{
    return {QStringLiteral("m"),     QStringLiteral("cx"),    QStringLiteral("cy"),
            QStringLiteral("cz"),    QStringLiteral("Ic xx"), QStringLiteral("Ic xy"),
            QStringLiteral("Ic yy"), QStringLiteral("Ic xz"), QStringLiteral("Ic yz"),
            QStringLiteral("Ic zz")};
}

PayloadEstimate estimatePayload(const Eigen::MatrixXd &rows, const Eigen::VectorXd &targets,
                                const PayloadPrior &prior, const PayloadEstimateSettings &settings)
{
    if (rows.cols() != 10 || rows.rows() != targets.size())
        throw Error(Text::tr("the payload's rows (%1 x %2) and targets (%3) do not match")
                        .arg(rows.rows())
                        .arg(rows.cols())
                        .arg(targets.size()));
    if (!rows.allFinite() || !targets.allFinite())
        throw Error(Text::tr("the payload's rows or targets are not finite"));
    if (!(settings.varianceFactor > 0.0) || !std::isfinite(settings.varianceFactor))
        throw Error(Text::tr("the variance factor must be positive"));
    validatePayloadPrior(prior);
    PayloadEstimate e;
    e.rows = rows.rows();
    e.prior = prior.parameters();

    // [A | b] = Q R: R's 11 rows hold all the rows say.
    Eigen::MatrixXd ab(rows.rows(), 11);
    ab << rows, targets;
    Eigen::Matrix<double, 11, 11> r = Eigen::Matrix<double, 11, 11>::Zero();
    if (ab.rows() > 0) {
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(ab);
        const Eigen::Index k = std::min<Eigen::Index>(11, ab.rows());
        r.topRows(k) = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
    }
    const Eigen::Matrix<double, 10, 10> a = r.topLeftCorner<10, 10>();
    const Vector10 b = r.col(10).head<10>();
    e.observability = payloadObservability(a, settings.priorShare);
    const PayloadObservability &o = e.observability;

    // The anchor of what the data do not see: the prior body moved to what they do see, its
    // mass and the components of its centre of mass the data identify (a first fit about the
    // prior), its inertia about the centre of mass the prior's (scaled with the mass). Kept in
    // the body's own terms, an unseen direction keeps the prior's geometry: with the centre of
    // mass moved sideways, the prior's Iyy about the flange would no longer be a real body.
    const InertialParameters first =
        e.prior + o.truncatedInverse * a.transpose() * (b - a * e.prior);
    const PayloadBody priorBody = payloadBody(e.prior);
    InertialParameters anchor = e.prior;
    if (o.massIdentified() && first[0] > 0.0) {
        const double m = first[0];
        Eigen::Vector3d c = priorBody.com;
        for (int axis = 0; axis < 3; ++axis)
            if (o.identified(1 + axis))
                c[axis] = first[1 + axis] / m;
        anchor = inertialParameters(m, c, priorBody.inertiaAtCom * (m / priorBody.mass));
        if (!(prior.bound.ellipsoid().fitShare(anchor) > 0.0))
            anchor = e.prior * (m / priorBody.mass); // moved outside the bound: only the mass
    }
    e.anchor = anchor;
    // The truncated least squares about it: pi = prior + (A^T A)^+ A^T (b - A prior).
    e.leastSquares = anchor + o.truncatedInverse * a.transpose() * (b - a * anchor);

    // The plausible estimate's data: A = U S V^T D (D the column scales); the determined
    // directions as the rows have them, the unseen ones held at the anchor with the strongest
    // direction's weight, each scaled by the largest column norm (an unseen parameter's own
    // column is about 0, and would hold it by nothing).
    Eigen::Matrix<double, 10, 1> d = a.colwise().norm().transpose();
    d = d.cwiseMax(1e-3 * d.maxCoeff() + 1e-300);
    const Eigen::JacobiSVD<Eigen::Matrix<double, 10, 10>> svd(
        a * d.cwiseInverse().asDiagonal(), Eigen::ComputeFullU | Eigen::ComputeFullV);
    const int k = o.rank;
    const Eigen::Matrix<double, 10, 10> vt = svd.matrixV().transpose();
    const double strongest = svd.singularValues()[0];
    PlausibleProblem problem;
    problem.a.resize(10, 10);
    problem.a << svd.singularValues().head(k).asDiagonal() * vt.topRows(k) * d.asDiagonal(),
        strongest * d.maxCoeff() * vt.bottomRows(10 - k);
    problem.b = problem.a * anchor;
    problem.b.head(k) = svd.matrixU().leftCols(k).transpose() * b;
    problem.prior = anchor;
    problem.links = 1;
    problem.volumes = {prior.bound.ellipsoid()};
    problem.priorShare = settings.geometricShare;
    if (!settings.plausible) {
        e.parameters = e.leastSquares;
        e.converged = true;
    } else if (k == 0) { // nothing seen: the prior as it is
        e.parameters = e.prior;
        e.converged = true;
        e.solverReport = Text::tr("no direction determined: the prior");
    } else {
        const PlausibleEstimate plausible = plausibleEstimate(problem);
        e.parameters = plausible.standard.head<10>();
        e.converged = plausible.converged;
        e.solverReport = plausible.report;
    }
    if (e.parameters[0] > 0.0) {
        e.body = payloadBody(e.parameters);
        e.comInsideBound = prior.bound.contains(e.body.com);
    }

    // Residual per row of the least-squares fit: ||R [pi; -1]||^2 = ||A pi - b||^2.
    Eigen::Matrix<double, 11, 1> x;
    x << e.leastSquares, -1.0;
    const double dof = std::max<double>(1.0, double(e.rows - k));
    const double variance = (r * x).squaredNorm() / dof;
    e.residualRms = std::sqrt((r * x).squaredNorm() / std::max<double>(1.0, double(e.rows)));
    e.covariance = settings.varianceFactor * variance * o.truncatedInverse;

    // The body's standard errors to first order: J cov J^T, J by central differences.
    const Vector10 at = e.parameters;
    const Vector10 value = bodyOf(at);
    Eigen::Matrix<double, 10, 10> jacobian;
    for (int j = 0; j < 10; ++j) {
        const double step = 1e-6 * std::max(std::abs(at[j]), 1e-3 * std::abs(at[0]) + 1e-12);
        Vector10 up = at, down = at;
        up[j] += step;
        down[j] -= step;
        jacobian.col(j) = (bodyOf(up) - bodyOf(down)) / (2.0 * step);
    }
    const Eigen::Matrix<double, 10, 10> bodyCovariance =
        jacobian * e.covariance * jacobian.transpose();
    for (int i = 0; i < 10; ++i) {
        e.bodyValue[size_t(i)] = value[i];
        e.bodyStandardError[size_t(i)] = std::sqrt(std::max(0.0, bodyCovariance(i, i)));
        bool identified = true;
        for (int j = 0; j < 10; ++j)
            identified = identified && (!dependsOn(i, j) || o.identified(j));
        e.bodyIdentified[size_t(i)] = identified;
    }
    return e;
}

} // namespace learnid
