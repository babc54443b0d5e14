// The primal barrier Newton method of plausibleEstimate() (PlausibleNewton.h).
//
// Written here, not taken from a library: the problem is a least-squares term, log-det terms of
// affine matrix functions and linear inequalities, and what converges on it in tens of steps is
// Newton's method with the exact Hessian (every term's is known in closed form). Ceres, which
// Debian packages, builds its model from residual Jacobians (Gauss-Newton): it leaves out the
// curvature of the barriers and of the log-det prior near the boundary and creeps there (500
// steps without converging on the KUKA LWR4+ logs; docs/identify.md has the figures). DSDP's
// SDP form has a linear objective and no log-det term.

#include "model/PlausibleNewton.h"

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <limits>

namespace learnid::detail {

namespace {

// dJ / dpi_k for a link's 10 standard parameters (J is linear in pi).
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

const Eigen::Matrix4d &thicknessMatrix()
{
    static const Eigen::Matrix4d d = Eigen::Vector4d(1.0, 1.0, 1.0, 0.0).asDiagonal();
    return d;
}

// -ln det M of a positive definite M and its derivatives in pi (M = J - constant):
// d = -tr(M^-1 E_k), H = tr(M^-1 E_a M^-1 E_b), times weight, added to gradient and hessian.
// False when M is not positive definite.
bool addLogDetBarrier(const Eigen::Matrix4d &m, double weight, double &value,
                      Eigen::Ref<Vector10d> gradient, Eigen::Ref<Matrix10d> hessian)
{
    const Eigen::LLT<Eigen::Matrix4d> llt(m);
    if (llt.info() != Eigen::Success)
        return false;
    const Eigen::Matrix4d l = llt.matrixL();
    if (!(l.diagonal().minCoeff() > 0.0))
        return false;
    value -= weight * 2.0 * l.diagonal().array().log().sum();
    const Eigen::Matrix4d inverse = llt.solve(Eigen::Matrix4d::Identity());
    const auto &e = pseudoInertiaBasis();
    std::array<Eigen::Matrix4d, 10> x;
    for (int k = 0; k < 10; ++k) {
        x[size_t(k)] = inverse * e[size_t(k)];
        gradient[k] -= weight * x[size_t(k)].trace();
    }
    for (int a = 0; a < 10; ++a)
        for (int b = a; b < 10; ++b) {
            const double h = weight * (x[size_t(a)].cwiseProduct(x[size_t(b)].transpose())).sum();
            hessian(a, b) += h;
            if (a != b)
                hessian(b, a) += h;
        }
    return true;
}

// f + mu phi at pi with its gradient and Hessian (when asked); +infinity outside the domain.
double evaluate(const PlausibleObjective &o, const Eigen::VectorXd &pi, double mu,
                Eigen::VectorXd *gradient, Eigen::MatrixXd *hessian)
{
    const Eigen::Index p = pi.size();
    const int n = int(o.links.size());
    const Eigen::VectorXd residual = o.a * pi - o.b;
    double value = residual.squaredNorm();
    if (gradient) {
        *gradient = 2.0 * o.a.transpose() * residual;
        *hessian = 2.0 * o.a.transpose() * o.a;
    }
    Vector10d g;
    Matrix10d h;
    for (int l = 0; l < n; ++l) {
        const LinkTerms &t = o.links[size_t(l)];
        const Vector10d x = pi.segment<10>(10 * l);
        const Eigen::Matrix4d j = pseudoInertia(x);
        g.setZero();
        h.setZero();
        // gamma (tr(J0^-1 J) - ln det J + ln det J0 - 4): its own barrier at J singular.
        double divergence = (t.priorInverse.cwiseProduct(j)).sum() + t.priorLogDet - 4.0;
        for (int k = 0; k < 10; ++k)
            g[k] += (t.priorInverse.cwiseProduct(pseudoInertiaBasis()[size_t(k)])).sum();
        if (!addLogDetBarrier(j, 1.0, divergence, g, h))
            return std::numeric_limits<double>::infinity();
        value += t.weight * divergence;
        g *= t.weight;
        h *= t.weight;
        // The barrier of J - s D, also where s = 0: with a weight gamma far below the data's the
        // divergence alone is a barrier Newton's method creeps along (not self-concordant:
        // gamma (-ln det J) / mu has a constant of 2 / sqrt(gamma / mu)); with the barrier's own
        // mu (-ln det J) the scaled objective is self-concordant and converges in tens of steps.
        if (!addLogDetBarrier(j - t.thickness * thicknessMatrix(), mu, value, g, h))
            return std::numeric_limits<double>::infinity();
        if (t.hasVolume) {
            Vector10d q;
            for (int k = 0; k < 10; ++k)
                q[k] = (t.volume.cwiseProduct(pseudoInertiaBasis()[size_t(k)])).sum();
            const double share = q.dot(x);
            if (!(share > 0.0))
                return std::numeric_limits<double>::infinity();
            value -= mu * std::log(share);
            g -= mu * q / share;
            h += mu * q * q.transpose() / (share * share);
        }
        if (gradient) {
            gradient->segment<10>(10 * l) += g;
            hessian->block<10, 10>(10 * l, 10 * l) += h;
        }
    }
    for (Eigen::Index i = 10 * n; i < p; ++i) {
        const double w = o.termWeights[i - 10 * n];
        const double d = pi[i] - o.prior[i];
        value += w * w * d * d;
        if (gradient) {
            (*gradient)[i] += 2.0 * w * w * d;
            (*hessian)(i, i) += 2.0 * w * w;
        }
        if (o.fixed[size_t(i)]) {
            if (gradient) { // held at 0: no step
                hessian->row(i).setZero();
                hessian->col(i).setZero();
                (*hessian)(i, i) = 1.0;
                (*gradient)[i] = 0.0;
            }
            continue;
        }
        if (o.nonnegative[size_t(i)]) {
            if (!(pi[i] > 0.0))
                return std::numeric_limits<double>::infinity();
            value -= mu * std::log(pi[i]);
            if (gradient) {
                (*gradient)[i] -= mu / pi[i];
                (*hessian)(i, i) += mu / (pi[i] * pi[i]);
            }
        }
    }
    return std::isfinite(value) ? value : std::numeric_limits<double>::infinity();
}

int barrierParameter(const PlausibleObjective &o)
{
    int nu = 0;
    for (const LinkTerms &t : o.links)
        nu += 4 + (t.hasVolume ? 1 : 0);
    for (size_t i = 0; i < o.nonnegative.size(); ++i)
        nu += o.nonnegative[i] && !o.fixed[i] ? 1 : 0;
    return nu;
}

} // namespace

double objectiveValue(const PlausibleObjective &objective, const Eigen::VectorXd &pi)
{
    return evaluate(objective, pi, 0.0, nullptr, nullptr);
}

NewtonResult minimiseWithBarriers(const PlausibleObjective &o, Eigen::VectorXd start,
                                  double relativeGap, int maxSteps)
{
    NewtonResult result;
    result.pi = std::move(start);
    const int nu = barrierParameter(o);
    double cost = objectiveValue(o, result.pi);
    double mu = 0.1 * std::max(cost, 1e-300) / std::max(nu, 1);
    Eigen::VectorXd gradient, step, trial;
    Eigen::MatrixXd hessian;
    Eigen::LDLT<Eigen::MatrixXd> ldlt;
    double value = evaluate(o, result.pi, mu, &gradient, &hessian);
    bool stalled = false; ///< the last step lowered the objective by no more than its rounding
    while (result.steps < maxSteps && std::isfinite(value)) {
        // Scaled to a unit diagonal first: a link whose prior is nearly degenerate (a published
        // massless link made a real body) has curvatures 1e12 times the others'.
        const Eigen::VectorXd scale =
            hessian.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
        ldlt.compute(scale.asDiagonal() * hessian * scale.asDiagonal());
        step = scale.asDiagonal() * ldlt.solve(-scale.cwiseProduct(gradient));
        const double decrement = -gradient.dot(step); // Newton decrement^2 of f + mu phi
        ++result.steps;
        if (!(decrement > 1e-9 * mu + 1e-13 * cost) || stalled) { // centred for this mu
            stalled = false;
            if (nu * mu <= relativeGap * cost || nu == 0) {
                result.converged = true;
                break;
            }
            mu *= 0.1;
            value = evaluate(o, result.pi, mu, &gradient, &hessian);
            continue;
        }
        const double before = value;
        bool accepted = false;
        for (double t = 1.0; t > 1e-20 && !accepted; t *= 0.5) {
            trial = result.pi + t * step;
            const double trialValue = evaluate(o, trial, mu, nullptr, nullptr);
            if (trialValue <= value - 0.25 * t * decrement) {
                result.pi.swap(trial);
                accepted = true;
            }
        }
        if (!accepted) { // rounding: nothing lowers the objective any more
            result.converged = nu * mu <= 1e3 * relativeGap * cost;
            break;
        }
        value = evaluate(o, result.pi, mu, &gradient, &hessian);
        cost = objectiveValue(o, result.pi);
        // A step that lowers the objective only by its rounding error (the sum of many terms;
        // the line search accepts it by chance) makes no progress: as centred as doubles tell.
        // Seen on the PUMA's log fit, on one CPU and not another (glibc's libm differs by an
        // ulp between them), stuck at one mu for the rest of maxSteps.
        stalled =
            before - value <= 256.0 * std::numeric_limits<double>::epsilon() * std::abs(before);
    }
    result.cost = objectiveValue(o, result.pi);
    return result;
}

} // namespace learnid::detail
