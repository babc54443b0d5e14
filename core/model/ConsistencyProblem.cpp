#include "model/ConsistencyProblem.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <array>
#include <cmath>
#include <limits>

namespace learnid::detail {

namespace {

QString translated(const char *text)
{
    return QCoreApplication::translate("PhysicalConsistency", text);
}

void requireEntries(const Eigen::VectorXd &v, const char *name, Eigen::Index expected,
                    const char *what)
{
    if (v.size() != expected)
        throw Error(translated("%1 has %2 entries; %3 %4.")
                        .arg(QLatin1String(name))
                        .arg(v.size())
                        .arg(QLatin1String(what))
                        .arg(expected));
}

void requireFinite(const Eigen::VectorXd &v, const char *name)
{
    for (Eigen::Index i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]))
            throw Error(translated("%1[%2] is not finite.").arg(QLatin1String(name)).arg(i));
}

// E_k = dJ / dpi_k: J is linear in pi.
const std::array<Eigen::Matrix4d, 10> &pseudoInertiaBasis()
{
    static const std::array<Eigen::Matrix4d, 10> basis = [] {
        std::array<Eigen::Matrix4d, 10> e;
        for (int k = 0; k < 10; ++k)
            e[size_t(k)] = pseudoInertia(Vector10d::Unit(k));
        return e;
    }();
    return basis;
}

// phi(pi) = -sum_l log det J_l - sum_i log pi_i; +inf where pi is not strictly consistent.
double barrier(const ConsistencyProblem &problem, const Eigen::VectorXd &pi)
{
    double phi = 0.0;
    for (int l = 0; l < problem.links; ++l) {
        const Eigen::LLT<Eigen::Matrix4d> llt(pseudoInertia(pi.segment<10>(10 * l)));
        if (llt.info() != Eigen::Success)
            return std::numeric_limits<double>::infinity();
        phi -= 2.0 * llt.matrixLLT().diagonal().array().log().sum();
    }
    for (Eigen::Index i = 10 * problem.links; i < pi.size(); ++i) {
        if (!problem.nonnegative[size_t(i)])
            continue;
        if (!(pi[i] > 0.0))
            return std::numeric_limits<double>::infinity();
        phi -= std::log(pi[i]);
    }
    return std::isnan(phi) ? std::numeric_limits<double>::infinity() : phi;
}

// mu grad phi into gradient and mu hess phi into hessian: d(-log det J)/dpi_k = -tr(J^-1 E_k),
// d2/dpi_a dpi_b = tr(J^-1 E_a J^-1 E_b).
void addBarrierDerivatives(const ConsistencyProblem &problem, const Eigen::VectorXd &pi, double mu,
                           Eigen::VectorXd &gradient, Eigen::MatrixXd &hessian)
{
    std::array<Eigen::Matrix4d, 10> b;
    for (int l = 0; l < problem.links; ++l) {
        const Eigen::Matrix4d jInverse =
            Eigen::LLT<Eigen::Matrix4d>(pseudoInertia(pi.segment<10>(10 * l)))
                .solve(Eigen::Matrix4d::Identity());
        for (int k = 0; k < 10; ++k) {
            b[size_t(k)] = jInverse * pseudoInertiaBasis()[size_t(k)];
            gradient[10 * l + k] -= mu * b[size_t(k)].trace();
        }
        for (int r = 0; r < 10; ++r)
            for (int c = 0; c < 10; ++c)
                hessian(10 * l + r, 10 * l + c) +=
                    mu * b[size_t(r)].cwiseProduct(b[size_t(c)].transpose()).sum();
    }
    for (Eigen::Index i = 10 * problem.links; i < pi.size(); ++i) {
        if (!problem.nonnegative[size_t(i)])
            continue;
        gradient[i] -= mu / pi[i];
        hessian(i, i) += mu / (pi[i] * pi[i]);
    }
}

} // namespace

int ConsistencyProblem::barrierTerms() const
{
    int terms = 4 * links;
    for (const char n : nonnegative)
        terms += n;
    return terms;
}

ConsistencyProblem consistencyProblem(const Eigen::MatrixXd &a, const Eigen::VectorXd &b,
                                      const Eigen::VectorXd &prior,
                                      const Eigen::VectorXd &priorScale, double priorWeight,
                                      int links, const std::vector<int> &nonnegativeIndices)
{
    const Eigen::Index p = a.cols();
    if (links < 0 || p < 10 * Eigen::Index(links))
        throw Error(translated("A has %1 columns, too few for %2 links (10 parameters each).")
                        .arg(p)
                        .arg(links));
    requireEntries(b, "b", a.rows(), "the rows of A are");
    requireEntries(prior, "prior", p, "the columns of A are");
    requireEntries(priorScale, "priorScale", p, "the columns of A are");
    for (Eigen::Index c = 0; c < p; ++c)
        for (Eigen::Index r = 0; r < a.rows(); ++r)
            if (!std::isfinite(a(r, c)))
                throw Error(translated("A(%1, %2) is not finite.").arg(r).arg(c));
    requireFinite(b, "b");
    requireFinite(prior, "prior");
    requireFinite(priorScale, "priorScale");
    for (Eigen::Index i = 0; i < p; ++i)
        if (priorScale[i] < 0.0)
            throw Error(translated("priorScale[%1] is negative.").arg(i));
    if (!std::isfinite(priorWeight) || priorWeight < 0.0)
        throw Error(translated("priorWeight is %1; it must be finite and >= 0.").arg(priorWeight));
    for (int l = 0; l < links; ++l)
        if (!(prior[10 * l] > 0.0))
            throw Error(translated("prior[%1], the mass of link %2, is %3 kg; the prior must be "
                                   "physically consistent.")
                            .arg(10 * l)
                            .arg(l)
                            .arg(prior[10 * l]));

    ConsistencyProblem problem;
    problem.links = links;
    problem.nonnegative.assign(size_t(p), 0);
    for (const int i : nonnegativeIndices) {
        if (i < 10 * links || i >= p)
            throw Error(translated("nonnegativeIndices holds %1, which is not a joint term "
                                   "(%2 to %3).")
                            .arg(i)
                            .arg(10 * links)
                            .arg(p - 1));
        problem.nonnegative[size_t(i)] = 1;
    }
    const Eigen::VectorXd weightedScale = priorWeight * priorScale;
    problem.m.resize(a.rows() + p, p);
    problem.m.topRows(a.rows()) = a;
    problem.m.bottomRows(p) = weightedScale.asDiagonal();
    problem.y.resize(a.rows() + p);
    problem.y.head(a.rows()) = b;
    problem.y.tail(p) = weightedScale.cwiseProduct(prior);
    return problem;
}

Eigen::VectorXd strictlyConsistent(const ConsistencyProblem &problem, const Eigen::VectorXd &pi,
                                   const Eigen::VectorXd &fallback, double floorShare)
{
    Eigen::VectorXd consistent = pi;
    for (int l = 0; l < problem.links; ++l) {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(pseudoInertia(pi.segment<10>(10 * l)));
        if (!(eigen.eigenvalues()[3] > 0.0))
            eigen.compute(pseudoInertia(fallback.segment<10>(10 * l)));
        const Eigen::Vector4d floored =
            eigen.eigenvalues().cwiseMax(floorShare * eigen.eigenvalues()[3]);
        consistent.segment<10>(10 * l) = inertialFromPseudoInertia(
            eigen.eigenvectors() * floored.asDiagonal() * eigen.eigenvectors().transpose());
    }
    for (Eigen::Index i = 10 * problem.links; i < pi.size(); ++i) {
        if (!problem.nonnegative[size_t(i)])
            continue;
        double floor = floorShare * std::max(std::abs(pi[i]), std::abs(fallback[i]));
        if (floor == 0.0)
            floor = 1e-16; // prior and data both at 0: any tiny positive value will do
        consistent[i] = std::max(pi[i], floor);
    }
    return consistent;
}

Eigen::VectorXd interiorPointEstimate(const ConsistencyProblem &problem, Eigen::VectorXd pi,
                                      double relativeGap, int maxSteps, int &steps)
{
    steps = 0;
    const int nu = problem.barrierTerms();
    Eigen::VectorXd residual = problem.m * pi - problem.y;
    double cost = residual.squaredNorm();
    const double startCost = cost;
    if (nu == 0 || cost == 0.0)
        return pi;
    const Eigen::MatrixXd costHessian = 2.0 * problem.m.transpose() * problem.m;
    Eigen::MatrixXd hessian;
    Eigen::VectorXd gradient, step, trial, trialResidual;
    Eigen::LDLT<Eigen::MatrixXd> ldlt;
    double mu = 0.1 * cost / nu;
    double phi = barrier(problem, pi);
    while (steps < maxSteps) {
        gradient.noalias() = 2.0 * problem.m.transpose() * residual;
        hessian = costHessian;
        addBarrierDerivatives(problem, pi, mu, gradient, hessian);
        ldlt.compute(hessian); // LDLT: a direction nothing sees has a zero pivot, and no step
        step = ldlt.solve(-gradient);
        const double decrement = -gradient.dot(step); // Newton decrement^2 of f + mu phi
        ++steps;
        // Centred (to rounding, which the decrement of a cost c cannot beat by much below
        // 1e-12 c): the cost is then within nu mu of the optimum.
        if (!(decrement > 1e-6 * mu + 1e-12 * cost)) {
            if (nu * mu <= relativeGap * std::max(cost, 1e-6 * startCost))
                break;
            mu *= 0.02;
            continue;
        }
        const double objective = cost + mu * phi;
        bool accepted = false;
        for (double t = 1.0; t > 1e-18 && !accepted; t *= 0.5) {
            trial = pi + t * step;
            const double trialPhi = barrier(problem, trial);
            if (!std::isfinite(trialPhi))
                continue;
            trialResidual.noalias() = problem.m * trial;
            trialResidual -= problem.y;
            const double trialCost = trialResidual.squaredNorm();
            if (trialCost + mu * trialPhi <= objective - 0.25 * t * decrement) {
                pi.swap(trial);
                residual.swap(trialResidual);
                cost = trialCost;
                phi = trialPhi;
                accepted = true;
            }
        }
        if (!accepted)
            break; // rounding: no step lowers the objective any more
    }
    return pi;
}

} // namespace learnid::detail
