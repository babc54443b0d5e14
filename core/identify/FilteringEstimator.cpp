#include "identify/FilteringEstimator.h"

#include <algorithm>
#include <cmath>

namespace learnid {

FilteringEstimator::FilteringEstimator(double rho, double samplePeriod)
    : m_rho(rho)
    , m_ts(samplePeriod)
{
    // eq. (19): x1' = x2, x2' = x3, x3' = -k3 x1 - k2 x2 - k1 x3 + k3 u,
    // k1 = 3 rho, k2 = 3 rho^2, k3 = rho^3.
    StateSpace c;
    c.a = Eigen::MatrixXd::Zero(3, 3);
    c.a(0, 1) = 1.0;
    c.a(1, 2) = 1.0;
    c.a(2, 0) = -rho * rho * rho;
    c.a(2, 1) = -3.0 * rho * rho;
    c.a(2, 2) = -3.0 * rho;
    c.b = Eigen::MatrixXd::Zero(3, 1);
    c.b(2, 0) = rho * rho * rho;
    c.c = Eigen::MatrixXd::Identity(3, 3);
    c.d = Eigen::MatrixXd::Zero(3, 1);
    m_discrete = tustin(c, samplePeriod);
    m_a = m_discrete.a;
    m_b = m_discrete.b;
    m_d = m_discrete.d;
    m_rest = steadyState(m_discrete, Eigen::VectorXd::Ones(1));
}

template <bool allOutputs, bool reversed>
void FilteringEstimator::run(const double *x, int n, double *out, int outStride) const
{
    if (n == 0)
        return;
    const int first = reversed ? n - 1 : 0;
    const int step = reversed ? -1 : 1;
    Eigen::Vector3d s = m_rest * x[first];
    for (int i = 0, k = first; i < n; ++i, k += step) {
        const double u = x[k];
        if constexpr (allOutputs) {
            const Eigen::Vector3d y = s + m_d * u;
            out[k * outStride] = y[0];
            out[k * outStride + 1] = y[1];
            out[k * outStride + 2] = y[2];
        } else {
            out[k * outStride] = s[0] + m_d[0] * u;
        }
        s = m_a * s + m_b * u;
    }
}

namespace {
// Samples over which the impulse response of F, decaying like t^2 exp(-rho t), is negligible.
int impulseLength(double rho, double ts)
{
    return std::clamp(int(std::ceil(60.0 / (rho * ts))), 64, 1 << 22);
}
} // namespace

double FilteringEstimator::lowPassNoiseGain() const
{
    // lowPass() starts at rest at its first sample: that sample must be 0 for the output to be
    // the impulse response (an impulse at sample 0 would give 1 - step response).
    Eigen::RowVectorXd impulse = Eigen::RowVectorXd::Zero(impulseLength(m_rho, m_ts) + 1);
    impulse[1] = 1.0;
    return lowPass(impulse).squaredNorm();
}

double FilteringEstimator::zeroPhaseNoiseGain() const
{
    const int half = impulseLength(m_rho, m_ts);
    Eigen::RowVectorXd impulse = Eigen::RowVectorXd::Zero(2 * half + 1);
    impulse[half] = 1.0;
    return zeroPhaseLowPass(impulse).squaredNorm();
}

Eigen::MatrixXd FilteringEstimator::causal(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    const Eigen::RowVectorXd in = x; // contiguous copy
    Eigen::MatrixXd out(3, in.size());
    run<true, false>(in.data(), int(in.size()), out.data(), 3);
    return out;
}

Eigen::RowVectorXd FilteringEstimator::lowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    const Eigen::RowVectorXd in = x;
    Eigen::RowVectorXd out(in.size());
    run<false, false>(in.data(), int(in.size()), out.data(), 1);
    return out;
}

Eigen::MatrixXd FilteringEstimator::zeroPhase(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    const Eigen::RowVectorXd forward = lowPass(x);
    Eigen::MatrixXd out(3, forward.size());
    run<true, true>(forward.data(), int(forward.size()), out.data(), 3);
    // The backward pass differentiates with respect to reversed time: d/dt = -d/d(-t).
    out.row(1) *= -1.0;
    return out;
}

Eigen::RowVectorXd
FilteringEstimator::anticausalLowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    const Eigen::RowVectorXd in = x;
    Eigen::RowVectorXd out(in.size());
    run<false, true>(in.data(), int(in.size()), out.data(), 1);
    return out;
}

Eigen::RowVectorXd
FilteringEstimator::zeroPhaseLowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    return anticausalLowPass(lowPass(x));
}

} // namespace learnid
