// plausibleEstimate() of PlausibleEstimate.h: the problem checked, its weights, and Ceres.
//
// Ceres (Debian's libceres-dev) is the solver: a nonlinear least-squares problem in the links'
// log-Cholesky parameters with bounds on the nonnegative joint terms is exactly its job
// (Levenberg-Marquardt, dense QR, bound constraints by projection, automatic derivatives of the
// prior's residuals). docs/identify.md says why it replaced the hand-written solver.

#include "model/PlausibleEstimate.h"

#include "model/Error.h"
#include "model/GeometricPrior.h"
#include "model/LogCholesky.h"

#include <ceres/ceres.h>

#include <Eigen/SVD>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <memory>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PlausibleEstimate)
};

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// r = A pi(theta_1..theta_n, terms) - b, with its Jacobian per parameter block:
// A_l (d pi_l / d theta_l) for link l (LogCholesky.h), A_terms for the joint terms.
class DataResidual final : public ceres::CostFunction
{
public:
    DataResidual(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int links)
        : m_a(a)
        , m_b(b)
        , m_links(links)
    {
        set_num_residuals(int(a.rows()));
        for (int l = 0; l < links; ++l)
            mutable_parameter_block_sizes()->push_back(10);
        if (a.cols() > 10 * links)
            mutable_parameter_block_sizes()->push_back(int(a.cols()) - 10 * links);
    }

    bool Evaluate(double const *const *parameters, double *residuals,
                  double **jacobians) const override
    {
        const Eigen::Index p = m_a.cols(), terms = p - 10 * m_links;
        Eigen::VectorXd pi(p);
        Matrix10d jacobian;
        for (int l = 0; l < m_links; ++l) {
            const Eigen::Map<const Eigen::Matrix<double, 10, 1>> theta(parameters[l]);
            if (!theta.allFinite())
                return false;
            pi.segment<10>(10 * l) = inertialFromLogCholesky(theta, jacobian);
            if (jacobians && jacobians[l]) {
                Eigen::Map<RowMajor>(jacobians[l], m_a.rows(), 10) =
                    m_a.middleCols<10>(10 * l) * jacobian;
            }
        }
        if (terms > 0) {
            pi.tail(terms) = Eigen::Map<const Eigen::VectorXd>(parameters[m_links], terms);
            if (jacobians && jacobians[m_links])
                Eigen::Map<RowMajor>(jacobians[m_links], m_a.rows(), terms) = m_a.rightCols(terms);
        }
        Eigen::Map<Eigen::VectorXd>(residuals, m_a.rows()) = m_a * pi - m_b;
        return true;
    }

private:
    const Eigen::MatrixXd &m_a;
    const Eigen::VectorXd &m_b;
    int m_links;
};

// w c_i (pi_i - prior_i) for the joint terms.
class TermPrior final : public ceres::CostFunction
{
public:
    TermPrior(Eigen::VectorXd scale, Eigen::VectorXd prior)
        : m_scale(std::move(scale))
        , m_prior(std::move(prior))
    {
        set_num_residuals(int(m_scale.size()));
        mutable_parameter_block_sizes()->push_back(int(m_scale.size()));
    }

    bool Evaluate(double const *const *parameters, double *residuals,
                  double **jacobians) const override
    {
        const Eigen::Index n = m_scale.size();
        Eigen::Map<Eigen::VectorXd>(residuals, n) =
            m_scale.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(parameters[0], n) - m_prior);
        if (jacobians && jacobians[0])
            Eigen::Map<RowMajor>(jacobians[0], n, n) = m_scale.asDiagonal();
        return true;
    }

private:
    Eigen::VectorXd m_scale, m_prior;
};

void checkProblem(const PlausibleProblem &pr)
{
    const Eigen::Index p = pr.prior.size();
    if (pr.links < 0 || p < 10 * Eigen::Index(pr.links) || pr.a.cols() != p ||
        pr.b.size() != pr.a.rows())
        throw Error(Text::tr("The estimation problem's sizes do not match: A is %1 x %2, b has "
                             "%3 entries, the prior %4 for %5 links.")
                        .arg(pr.a.rows())
                        .arg(pr.a.cols())
                        .arg(pr.b.size())
                        .arg(p)
                        .arg(pr.links));
    if (!pr.a.allFinite() || !pr.b.allFinite() || !pr.prior.allFinite())
        throw Error(Text::tr("The estimation problem has entries that are not finite."));
    if (!(pr.priorShare > 0.0 && pr.priorShare < 1.0))
        throw Error(
            Text::tr("The prior share must lie between 0 and 1, not %1.").arg(pr.priorShare));
    if (!pr.volumes.empty() && pr.volumes.size() != size_t(pr.links))
        throw Error(
            Text::tr("%1 bounding volumes for %2 links.").arg(pr.volumes.size()).arg(pr.links));
    for (const int i : pr.nonnegative) {
        if (i < 10 * pr.links || i >= p)
            throw Error(Text::tr("Index %1 is not a joint term.").arg(i));
        if (pr.prior[i] < 0.0)
            throw Error(
                Text::tr("The prior's joint term %1 is negative (%2).").arg(i).arg(pr.prior[i]));
    }
    for (int l = 0; l < pr.links; ++l) {
        if (!pr.volumes.empty() && pr.volumes[size_t(l)] &&
            !(pr.volumes[size_t(l)]->fitShare(pr.prior.segment<10>(10 * l)) > 0.0))
            throw Error(Text::tr("The prior's link %1 does not lie inside its bounding volume.")
                            .arg(l + 1));
    }
}

// Per link the 10 directions of the divergence's own metric: pi of U0 B_k U0^T for an orthonormal
// basis B_k of symmetric 4 x 4 matrices, so that D(J0 + dJ, J0) ~ |v|^2 / 2 for dJ = sum v_k ...
Matrix10d divergenceDirections(const Eigen::Matrix4d &u0)
{
    Matrix10d out;
    int k = 0;
    for (int i = 0; i < 4; ++i) {
        for (int j = i; j < 4; ++j, ++k) {
            Eigen::Matrix4d b = Eigen::Matrix4d::Zero();
            b(i, j) = b(j, i) = i == j ? 1.0 : std::sqrt(0.5);
            out.col(k) = inertialFromPseudoInertia(u0 * b * u0.transpose());
        }
    }
    return out;
}

} // namespace

PlausibleEstimate plausibleEstimate(const PlausibleProblem &pr)
{
    checkProblem(pr);
    const int n = pr.links;
    const Eigen::Index p = pr.prior.size(), terms = p - 10 * n;

    // The prior's own metric: per link the divergence's directions, per joint term its column.
    std::vector<Eigen::Matrix<double, 10, 1>> theta0(static_cast<size_t>(n));
    Eigen::MatrixXd scaled(pr.a.rows(), p);
    for (int l = 0; l < n; ++l) {
        try {
            theta0[size_t(l)] = logCholeskyFromInertial(pr.prior.segment<10>(10 * l));
        } catch (const Error &e) {
            throw Error(Text::tr("The prior's link %1: %2").arg(l + 1).arg(e.message()));
        }
        const Eigen::Matrix4d u0 = detail::logCholeskyFactor(theta0[size_t(l)].data());
        scaled.middleCols<10>(10 * l) = pr.a.middleCols<10>(10 * l) * divergenceDirections(u0);
    }
    Eigen::VectorXd columns = pr.a.rightCols(terms).colwise().norm().transpose();
    if (terms > 0)
        columns = columns.cwiseMax(1e-3 * columns.maxCoeff() + 1e-300);
    scaled.rightCols(terms) = pr.a.rightCols(terms) * columns.cwiseInverse().asDiagonal();
    const double largest =
        pr.a.rows() > 0 ? Eigen::JacobiSVD<Eigen::MatrixXd>(scaled).singularValues()[0] : 0.0;
    // The prior counts share^2 of the best-determined direction: w^2 per scaled coordinate, and
    // gamma / 2 per unit of |v|^2 (D ~ |v|^2 / 2). Without data the prior alone decides.
    const double w = largest > 0.0 ? pr.priorShare * largest : 1.0;

    PlausibleEstimate result;
    result.linkWeight = 2.0 * w * w;
    ceres::Problem::Options options;
    options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
    ceres::Problem problem(options);
    std::vector<double *> blocks;
    std::vector<Eigen::Matrix<double, 10, 1>> theta = theta0;
    Eigen::VectorXd termValues = pr.prior.tail(terms);
    for (int l = 0; l < n; ++l)
        blocks.push_back(theta[size_t(l)].data());
    if (terms > 0)
        blocks.push_back(termValues.data());
    if (pr.a.rows() > 0)
        problem.AddResidualBlock(new DataResidual(pr.a, pr.b, n), nullptr, blocks);
    for (int l = 0; l < n; ++l) {
        problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<detail::LogDetDivergence, 10, 10>(
                new detail::LogDetDivergence(theta0[size_t(l)], result.linkWeight)),
            nullptr, blocks[size_t(l)]);
        if (!pr.volumes.empty() && pr.volumes[size_t(l)]) {
            const BoundingEllipsoid &e = *pr.volumes[size_t(l)];
            const double t0 = e.fitShare(pr.prior.segment<10>(10 * l)) * pr.prior[10 * l];
            problem.AddResidualBlock(
                new ceres::AutoDiffCostFunction<detail::VolumeDivergence, 1, 10>(
                    new detail::VolumeDivergence{e.constraintMatrix(), t0,
                                                 std::sqrt(result.linkWeight)}),
                nullptr, blocks[size_t(l)]);
        }
    }
    if (terms > 0) {
        problem.AddResidualBlock(new TermPrior(w * columns, pr.prior.tail(terms)), nullptr,
                                 termValues.data());
        for (const int i : pr.nonnegative)
            problem.SetParameterLowerBound(termValues.data(), i - 10 * n, 0.0);
    }

    ceres::Solver::Options solver;
    solver.linear_solver_type = ceres::DENSE_QR;
    solver.logging_type = ceres::SILENT;
    solver.max_num_iterations = 500;
    solver.function_tolerance = 1e-12;
    solver.gradient_tolerance = 1e-14;
    solver.parameter_tolerance = 1e-12;
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);

    result.standard.resize(p);
    for (int l = 0; l < n; ++l)
        result.standard.segment<10>(10 * l) = inertialFromLogCholesky(theta[size_t(l)]);
    result.standard.tail(terms) = termValues;
    result.dataCost = (pr.a * result.standard - pr.b).squaredNorm();
    result.priorCost = std::max(0.0, 2.0 * summary.final_cost - result.dataCost);
    result.iterations = int(summary.iterations.size());
    result.converged = summary.termination_type == ceres::CONVERGENCE;
    result.report = QString::fromStdString(summary.BriefReport());
    return result;
}

} // namespace learnid
