// nearestConsistentEstimate() of PhysicalConsistency.h: an interior-point solve in the standard
// parameters for the start, then Levenberg-Marquardt over the links' log-Cholesky parameters
// and the joint terms.

#include "model/ConsistencyProblem.h"
#include "model/LogCholesky.h"
#include "model/PhysicalConsistency.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>

namespace learnid {

using detail::ConsistencyProblem;

namespace {

// The variables x (p): theta per link, s with pi_i = s^2 for a nonnegative term, pi_i itself
// for a free one; the standard vector, residual M pi - y and cost at x, and d pi / d theta.
struct Point
{
    Eigen::VectorXd x, pi, residual;
    std::vector<Matrix10d> blocks;
    double cost = std::numeric_limits<double>::infinity();
};

void evaluate(const ConsistencyProblem &problem, Point &point)
{
    const Eigen::Index p = point.x.size();
    point.pi.resize(p);
    point.blocks.resize(size_t(problem.links));
    for (int l = 0; l < problem.links; ++l)
        point.pi.segment<10>(10 * l) =
            inertialFromLogCholesky(point.x.segment<10>(10 * l), point.blocks[size_t(l)]);
    for (Eigen::Index i = 10 * problem.links; i < p; ++i)
        point.pi[i] = problem.nonnegative[size_t(i)] ? point.x[i] * point.x[i] : point.x[i];
    point.residual.noalias() = problem.m * point.pi;
    point.residual -= problem.y;
    point.cost = point.residual.squaredNorm();
    if (!std::isfinite(point.cost))
        point.cost = std::numeric_limits<double>::infinity();
}

// The variables of a strictly consistent pi. A link so close to the boundary that rounding
// leaves its reversed Cholesky factor undefined is first floored at 1e-12 lambda_max.
Eigen::VectorXd variablesOf(const ConsistencyProblem &problem, const Eigen::VectorXd &pi,
                            const Eigen::VectorXd &fallback)
{
    Eigen::VectorXd x = pi;
    for (int l = 0; l < problem.links; ++l) {
        try {
            x.segment<10>(10 * l) = logCholeskyFromInertial(pi.segment<10>(10 * l));
        } catch (const Error &) {
            x.segment<10>(10 * l) = logCholeskyFromInertial(
                detail::strictlyConsistent(problem, pi, fallback, 1e-12).segment<10>(10 * l));
        }
    }
    for (Eigen::Index i = 10 * problem.links; i < pi.size(); ++i)
        if (problem.nonnegative[size_t(i)])
            x[i] = std::sqrt(pi[i]);
    return x;
}

// d residual / d x = M (d pi / d x), the latter block diagonal.
void residualJacobian(const ConsistencyProblem &problem, const Point &point,
                      Eigen::MatrixXd &jacobian)
{
    jacobian.resize(problem.m.rows(), problem.m.cols());
    for (int l = 0; l < problem.links; ++l)
        jacobian.middleCols<10>(10 * l).noalias() =
            problem.m.middleCols<10>(10 * l) * point.blocks[size_t(l)];
    for (Eigen::Index i = 10 * problem.links; i < point.x.size(); ++i)
        jacobian.col(i) =
            problem.m.col(i) * (problem.nonnegative[size_t(i)] ? 2.0 * point.x[i] : 1.0);
}

// The second-order term of the least-squares Hessian, sum_i r_i d2 r_i / dx dx^T, into
// hessian, block diagonal: per link the curvature of q . pi(theta), q = M^T r, and 2 q_i for
// pi_i = s_i^2; each block's negative eigenvalues dropped so the Hessian stays positive
// semidefinite. Near the boundary the residual does not vanish, and Gauss-Newton alone sees
// the boundary as a plane it could cross: it creeps, or stops short.
void addSecondOrderTerm(const ConsistencyProblem &problem, const Point &point,
                        const Eigen::VectorXd &q, Eigen::MatrixXd &hessian)
{
    for (int l = 0; l < problem.links; ++l) {
        const Eigen::SelfAdjointEigenSolver<Matrix10d> curvature(
            logCholeskyCurvature(point.x.segment<10>(10 * l), q.segment<10>(10 * l)));
        hessian.block<10, 10>(10 * l, 10 * l) +=
            curvature.eigenvectors() * curvature.eigenvalues().cwiseMax(0.0).asDiagonal() *
            curvature.eigenvectors().transpose();
    }
    for (Eigen::Index i = 10 * problem.links; i < point.x.size(); ++i)
        if (problem.nonnegative[size_t(i)])
            hessian(i, i) += std::max(0.0, 2.0 * q[i]);
}

} // namespace

ConsistentEstimate nearestConsistentEstimate(const Eigen::MatrixXd &a, const Eigen::VectorXd &b,
                                             const Eigen::VectorXd &prior,
                                             const Eigen::VectorXd &priorScale, double priorWeight,
                                             int links, const std::vector<int> &nonnegativeIndices)
{
    const ConsistencyProblem problem =
        detail::consistencyProblem(a, b, prior, priorScale, priorWeight, links, nonnegativeIndices);
    ConsistentEstimate result;
    if (problem.m.cols() == 0) { // nothing to estimate
        result.cost = b.squaredNorm();
        result.converged = true;
        return result;
    }

    // The cheaper of two strictly consistent points: the prior, and the unconstrained fit
    // about it (minimum-norm step where the rows do not see a direction), floored.
    constexpr double startFloor = 1e-2;
    const Eigen::VectorXd fromPrior = detail::strictlyConsistent(problem, prior, prior, startFloor);
    const Eigen::VectorXd fromFit = detail::strictlyConsistent(
        problem,
        prior + problem.m.completeOrthogonalDecomposition().solve(problem.y - problem.m * prior),
        prior, startFloor);
    const bool fitCheaper = (problem.m * fromFit - problem.y).squaredNorm() <
                            (problem.m * fromPrior - problem.y).squaredNorm();
    // From there to within 1e-9 of the optimal cost, in pi where the problem is convex: the
    // log-Cholesky coordinates run off to infinity towards a boundary optimum, and LM alone
    // needs thousands of steps there when the prior weight is small.
    const Eigen::VectorXd interior = detail::interiorPointEstimate(
        problem, fitCheaper ? fromFit : fromPrior, 1e-9, 200, result.newtonSteps);

    constexpr int maxIterations = 200;
    constexpr double relativeDecrease = 1e-12;
    constexpr double relativeStep = 1e-12;
    Point current, candidate;
    current.x = variablesOf(problem, interior, prior);
    evaluate(problem, current);
    Eigen::MatrixXd jacobian, hessian, damped;
    Eigen::VectorXd gradient, piGradient, damping, step;
    Eigen::LLT<Eigen::MatrixXd> llt;
    double mu = 1e-3, nu = 2.0;
    bool linearise = true;
    result.converged = current.cost == 0.0;
    while (!result.converged && result.iterations < maxIterations && mu < 1e100) {
        if (linearise) {
            residualJacobian(problem, current, jacobian);
            hessian.noalias() = jacobian.transpose() * jacobian;
            gradient.noalias() = jacobian.transpose() * current.residual;
            // Marquardt's scaling diag(J^T J), floored so that a variable the cost does not
            // see is still damped.
            const double largest = hessian.diagonal().maxCoeff();
            damping = hessian.diagonal().cwiseMax(largest > 0.0 ? 1e-12 * largest : 1.0);
            piGradient.noalias() = problem.m.transpose() * current.residual;
            addSecondOrderTerm(problem, current, piGradient, hessian);
            linearise = false;
        }
        ++result.iterations;
        damped = hessian;
        damped.diagonal() += mu * damping;
        llt.compute(damped);
        if (llt.info() != Eigen::Success) {
            mu *= nu;
            nu *= 2.0;
            continue;
        }
        step = llt.solve(-gradient);
        const bool tinyStep = step.norm() <= relativeStep * (current.x.norm() + relativeStep);
        // The decrease the quadratic model predicts: -(2 g^T step + step^T H step).
        const double predicted = -(2.0 * step.dot(gradient) + step.dot(hessian * step));
        candidate.x = current.x + step;
        if (candidate.x.allFinite())
            evaluate(problem, candidate);
        else
            candidate.cost = std::numeric_limits<double>::infinity();
        if (candidate.cost < current.cost && predicted > 0.0) {
            const double decrease = current.cost - candidate.cost;
            const double gain = decrease / predicted;
            std::swap(current, candidate);
            linearise = true;
            mu *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gain - 1.0, 3)); // Nielsen
            nu = 2.0;
            result.converged = decrease <= relativeDecrease * candidate.cost || current.cost == 0.0;
        } else {
            mu *= nu;
            nu *= 2.0;
        }
        result.converged = result.converged || tinyStep;
    }
    result.standard = current.pi;
    result.cost = current.cost;
    return result;
}

} // namespace learnid
