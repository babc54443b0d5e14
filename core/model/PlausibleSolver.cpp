// The Ceres problem of plausibleEstimate() (PlausibleSolver.h).
//
// Ceres (Debian's libceres-dev) is the solver: a nonlinear least-squares problem with bounds on
// the nonnegative joint terms and residuals that refuse infeasible points is exactly its job
// (Levenberg-Marquardt, dense QR, bound constraints by projection, automatic derivatives of the
// prior's residuals). docs/identify.md says why it replaced the hand-written solver.
//
// The variables are the standard parameters themselves: the data's residual is linear in them
// (its Gauss-Newton model exact) and the problem without the rule is convex. In log-Cholesky
// coordinates the same data residual is curved, and an optimum far from the prior needs the
// second-order term that Gauss-Newton leaves out (hundreds of steps on the KUKA LWR4+ logs).

#include "model/PlausibleSolver.h"

#include "model/GeometricPrior.h"

#include <ceres/ceres.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

namespace learnid::detail {

namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// r = A pi - b: linear in every parameter block, its Jacobian A's columns.
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
        for (int l = 0; l < m_links; ++l) {
            pi.segment<10>(10 * l) = Eigen::Map<const Vector10d>(parameters[l]);
            if (jacobians && jacobians[l])
                Eigen::Map<RowMajor>(jacobians[l], m_a.rows(), 10) = m_a.middleCols<10>(10 * l);
        }
        if (terms > 0) {
            pi.tail(terms) = Eigen::Map<const Eigen::VectorXd>(parameters[m_links], terms);
            if (jacobians && jacobians[m_links])
                Eigen::Map<RowMajor>(jacobians[m_links], m_a.rows(), terms) = m_a.rightCols(terms);
        }
        if (!pi.allFinite())
            return false;
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




// The rule's two inequalities per link (GeometricPrior.h, RuleBarrier) where the prior meets them.
void addRuleBarriers(ceres::Problem &problem, const PlausibilityRule &rule,
                     const std::vector<Vector10d> &prior0,
                     const std::vector<double> &weights, const std::vector<double *> &blocks)
{
    for (size_t l = 0; l < prior0.size(); ++l) {
        const Eigen::Matrix3d sigma = RuleBarrier::matrix(prior0[l].data(), true, 0.0);
        const Eigen::Vector3d eig =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(sigma, Eigen::EigenvaluesOnly)
                .eigenvalues();
        const double smallestMoment = eig[0] + eig[1];
        const double bounds[2] = {rule.minMomentShare * smallestMoment,
                                  rule.triangleMargin / (2.0 + rule.triangleMargin)};
        for (const bool shape : {false, true}) {
            const double bound = bounds[shape ? 1 : 0];
            const Eigen::Matrix3d m0 = RuleBarrier::matrix(prior0[l].data(), shape, bound);
            const Eigen::LLT<Eigen::Matrix3d> llt(m0);
            if (llt.info() != Eigen::Success || !(m0.determinant() > 0.0))
                continue; // the prior itself breaks this part of the rule
            problem.AddResidualBlock(
                new ceres::AutoDiffCostFunction<RuleBarrier, 1, 10>(new RuleBarrier{
                    shape, bound, std::log(m0.determinant()), std::sqrt(weights[l])}),
                nullptr, blocks[l]);
        }
    }
}

} // namespace

PlausibleStage solvePlausibleStage(const PlausibleProblem &pr, const std::vector<Vector10d> &prior0,
                                   const PlausibleWeights &weights, std::vector<Vector10d> &links,
                                   Eigen::VectorXd &termValues)
{
    const int n = pr.links;
    const Eigen::Index terms = pr.prior.size() - 10 * n;
    ceres::Problem::Options options;
    options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
    ceres::Problem problem(options);
    std::vector<double *> blocks;
    for (int l = 0; l < n; ++l)
        blocks.push_back(links[size_t(l)].data());
    if (terms > 0)
        blocks.push_back(termValues.data());
    if (pr.a.rows() > 0)
        problem.AddResidualBlock(new DataResidual(pr.a, pr.b, n), nullptr, blocks);
    for (int l = 0; l < n; ++l) {
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<LogDetDivergence, 10, 10>(
                                     new LogDetDivergence(prior0[size_t(l)], weights.links[size_t(l)])),
                                 nullptr, blocks[size_t(l)]);
        if (!pr.volumes.empty() && pr.volumes[size_t(l)]) {
            const BoundingEllipsoid &e = *pr.volumes[size_t(l)];
            const double t0 = e.fitShare(pr.prior.segment<10>(10 * l)) * pr.prior[10 * l];
            problem.AddResidualBlock(new ceres::AutoDiffCostFunction<VolumeDivergence, 1, 10>(
                                         new VolumeDivergence{e.constraintMatrix(), t0,
                                                              std::sqrt(weights.links[size_t(l)])}),
                                     nullptr, blocks[size_t(l)]);
        }
    }
    if (pr.rule)
        addRuleBarriers(problem, *pr.rule, prior0, weights.links, blocks);
    if (terms > 0) {
        problem.AddResidualBlock(new TermPrior(weights.terms, pr.prior.tail(terms)), nullptr,
                                 termValues.data());
        for (const int i : pr.nonnegative)
            if (!qEnvironmentVariableIsSet("LEARNID_NOBOUNDS")) problem.SetParameterLowerBound(termValues.data(), i - 10 * n, 0.0);
    }

    ceres::Solver::Options solver;
    solver.linear_solver_type = ceres::DENSE_QR;
    solver.logging_type = ceres::SILENT;
    solver.max_num_iterations = 500;
    solver.function_tolerance = 1e-12;
    solver.gradient_tolerance = 1e-14;
    solver.parameter_tolerance = 1e-12;
    if (qEnvironmentVariableIsSet("LEARNID_DEBUG_CERES")) { // TEMP
        solver.logging_type = ceres::PER_MINIMIZER_ITERATION;
        solver.minimizer_progress_to_stdout = true;
    }
    if (qEnvironmentVariableIsSet("LEARNID_CHECK_GRADIENTS")) { // TEMP
        solver.check_gradients = true;
        solver.gradient_check_relative_precision = 1e-5;
    }
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    if (qEnvironmentVariableIsSet("LEARNID_DEBUG_CERES")) { // TEMP
        std::vector<ceres::ResidualBlockId> ids;
        problem.GetResidualBlocks(&ids);
        for (auto id : ids) {
            double cost = 0;
            problem.EvaluateResidualBlock(id, false, &cost, nullptr, nullptr);
            std::vector<double *> ps;
            problem.GetParameterBlocksForResidualBlock(id, &ps);
            int which = -1;
            for (size_t l = 0; l < links.size(); ++l)
                if (ps.size() == 1 && ps[0] == links[l].data()) which = int(l);
            fprintf(stdout, "block link=%d nres=%d cost=%g\n", which, problem.GetCostFunctionForResidualBlock(id)->num_residuals(), cost);
        }
    }
    PlausibleStage stage;
    stage.iterations = int(summary.iterations.size());
    stage.converged = summary.termination_type == ceres::CONVERGENCE;
    stage.finalCost = 2.0 * summary.final_cost;
    stage.report = QString::fromStdString(summary.BriefReport());
    return stage;
}

} // namespace learnid::detail
