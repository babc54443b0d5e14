#include "identify/FilteringEstimator.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

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
    // Tustin maps rho / (s + rho) to k (1 + z^-1) / ((1 + k) - (1 - k) z^-1), k = rho Ts / 2;
    // F is its cube.
    const double k = 0.5 * rho * samplePeriod;
    m_sectionGain = k / (1.0 + k); // and the pole (1 - k) / (1 + k) = 1 - 2 g
}

namespace {

// One step of the section g (1 + z^-1) / (1 - p z^-1), p = 1 - 2 g, from output y, input u and
// previous input u0: p y + g (u + u0) written so that a section at rest (u = u0 = y) stays
// exactly at rest.
inline double lowPassSection(double y, double u, double u0, double g)
{
    return y + g * ((u - y) + (u0 - y));
}

// The same for g (1 - z^-1) / (1 - p z^-1): p y + g (u - u0), exactly 0 at rest.
inline double differenceSection(double y, double u, double u0, double g)
{
    return y + g * ((u - u0) - 2.0 * y);
}

using Packet = Eigen::internal::packet_traits<double>::type;
constexpr int packetSize = Eigen::internal::packet_traits<double>::size;

// lowPassSection() on the lanes of a SIMD packet: one signal per lane, each lane computing
// what lowPassSection() computes, operation for operation (IEEE arithmetic is the same in every
// lane).
// (A template, so that a build without SIMD, where Packet is double, has no second overload.)
template <typename P, std::enable_if_t<!std::is_same_v<P, double>, int> = 0>
inline P lowPassSection(P y, P u, P u0, P g)
{
    using namespace Eigen::internal;
    return padd(y, pmul(g, padd(psub(u, y), psub(u0, y))));
}

// F = S+ S+ S+ on one signal (T = double) or on the lanes of a packet, sample by sample,
// started at rest at `rest`: every section's input and output equal it (unit DC gain).
template <typename T> struct LowPassChainOf
{
    T u0, y1, y2, y3;

    explicit LowPassChainOf(T rest)
        : u0(rest)
        , y1(rest)
        , y2(rest)
        , y3(rest)
    {}

    T step(T u, T g)
    {
        const T y1New = lowPassSection(y1, u, u0, g);
        const T y2New = lowPassSection(y2, y1New, y1, g);
        y3 = lowPassSection(y3, y2New, y2, g);
        u0 = u;
        y1 = y1New;
        y2 = y2New;
        return y3;
    }
};
using LowPassChain = LowPassChainOf<double>;
using LowPassLanes = LowPassChainOf<Packet>;

// runLowPass() in place on the 2 packetSize columns at x (stride apart), n samples each:
// two packets, so that one's recursion runs in the other's latency.
template <bool reversed>
void runLowPassLanesInPlace(double *x, Eigen::Index stride, int n, double g)
{
    using Eigen::internal::pgather;
    using Eigen::internal::pscatter;
    if (n == 0)
        return;
    const int first = reversed ? n - 1 : 0;
    const int step = reversed ? -1 : 1;
    double *second = x + packetSize * stride;
    LowPassLanes f(pgather<double, Packet>(x + first, stride));
    LowPassLanes h(pgather<double, Packet>(second + first, stride));
    const Packet gain = Eigen::internal::pset1<Packet>(g);
    for (int i = 0, k = first; i < n; ++i, k += step) {
        pscatter<double, Packet>(x + k, f.step(pgather<double, Packet>(x + k, stride), gain),
                                 stride);
        pscatter<double, Packet>(second + k,
                                 h.step(pgather<double, Packet>(second + k, stride), gain), stride);
    }
}

} // namespace

template <bool reversed>
void FilteringEstimator::runLowPass(const double *x, int n, double *out) const
{
    if (n == 0)
        return;
    const int first = reversed ? n - 1 : 0;
    const int step = reversed ? -1 : 1;
    LowPassChain f(x[first]);
    for (int i = 0, k = first; i < n; ++i, k += step)
        out[k] = f.step(x[k], m_sectionGain);
}

template <bool reversed>
void FilteringEstimator::runLowPassPairInPlace(double *x, double *w, int n) const
{
    // runLowPass() on x and on w, in place, in one loop: two independent chains.
    if (n == 0)
        return;
    const int first = reversed ? n - 1 : 0;
    const int step = reversed ? -1 : 1;
    LowPassChain f(x[first]);
    LowPassChain h(w[first]);
    for (int i = 0, k = first; i < n; ++i, k += step) {
        x[k] = f.step(x[k], m_sectionGain);
        w[k] = h.step(w[k], m_sectionGain);
    }
}

template <bool reversed>
void FilteringEstimator::runAllOutputs(const double *x, int n, double *out) const
{
    if (n == 0)
        return;
    // Output i of the Tustin state space is D^i F, D = (2/Ts)(1 - z^-1)/(1 + z^-1) the Tustin
    // derivative: with sections S+ = g (1 + z^-1)/(1 - p z^-1) and S- = g (1 - z^-1)/(1 - p z^-1),
    // F = S+ S+ S+, D F = (2/Ts) S- S+ S+, D^2 F = (2/Ts)^2 S- S- S+.
    const int first = reversed ? n - 1 : 0;
    const int step = reversed ? -1 : 1;
    const double g = m_sectionGain;
    const double derivative = 2.0 / m_ts;
    // At rest at x[first]: S+ passes a constant, S- gives 0.
    double u0 = x[first];
    double a = u0, b = u0, y0 = u0, y1 = 0.0, c = 0.0, y2 = 0.0;
    for (int i = 0, k = first; i < n; ++i, k += step) {
        const double u = x[k];
        const double aNew = lowPassSection(a, u, u0, g);
        const double bNew = lowPassSection(b, aNew, a, g);
        const double cNew = differenceSection(c, aNew, a, g);
        y0 = lowPassSection(y0, bNew, b, g);
        y1 = differenceSection(y1, bNew, b, g);
        y2 = differenceSection(y2, cNew, c, g);
        out[3 * k] = y0;
        out[3 * k + 1] = derivative * y1;
        out[3 * k + 2] = derivative * derivative * y2;
        u0 = u;
        a = aNew;
        b = bNew;
        c = cNew;
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
    runAllOutputs<false>(in.data(), int(in.size()), out.data());
    return out;
}

Eigen::RowVectorXd FilteringEstimator::lowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    const Eigen::RowVectorXd in = x;
    Eigen::RowVectorXd out(in.size());
    runLowPass<false>(in.data(), int(in.size()), out.data());
    return out;
}

Eigen::MatrixXd FilteringEstimator::zeroPhase(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    const Eigen::RowVectorXd forward = lowPass(x);
    Eigen::MatrixXd out(3, forward.size());
    runAllOutputs<true>(forward.data(), int(forward.size()), out.data());
    // The backward pass differentiates with respect to reversed time: d/dt = -d/d(-t).
    out.row(1) *= -1.0;
    return out;
}

Eigen::RowVectorXd
FilteringEstimator::anticausalLowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    const Eigen::RowVectorXd in = x;
    Eigen::RowVectorXd out(in.size());
    runLowPass<true>(in.data(), int(in.size()), out.data());
    return out;
}

void FilteringEstimator::zeroPhaseLowPassInPlace(double *x, Eigen::Index n) const
{
    // Each step reads its input sample before it writes the output over it.
    runLowPass<false>(x, int(n), x);
    runLowPass<true>(x, int(n), x);
}

void FilteringEstimator::zeroPhaseLowPassInPlace(const std::vector<double *> &series,
                                                 Eigen::Index n) const
{
    size_t i = 0;
    for (; i + 1 < series.size(); i += 2) {
        runLowPassPairInPlace<false>(series[i], series[i + 1], int(n));
        runLowPassPairInPlace<true>(series[i], series[i + 1], int(n));
    }
    if (i < series.size())
        zeroPhaseLowPassInPlace(series[i], n);
}

void FilteringEstimator::zeroPhaseLowPassColumnsInPlace(Eigen::Ref<Eigen::MatrixXd> x) const
{
    const Eigen::Index lanes = 2 * packetSize;
    const Eigen::Index stride = x.outerStride();
    const int n = int(x.rows());
    Eigen::Index c = 0;
    for (; c + lanes <= x.cols(); c += lanes) {
        runLowPassLanesInPlace<false>(x.col(c).data(), stride, n, m_sectionGain);
        runLowPassLanesInPlace<true>(x.col(c).data(), stride, n, m_sectionGain);
    }
    std::vector<double *> rest;
    for (; c < x.cols(); ++c)
        rest.push_back(x.col(c).data());
    zeroPhaseLowPassInPlace(rest, x.rows());
}

void FilteringEstimator::filterInto(double *x, Eigen::Index n, bool zeroPhase, double *out) const
{
    if (!zeroPhase) {
        runAllOutputs<false>(x, int(n), out);
        return;
    }
    runLowPass<false>(x, int(n), x);
    runAllOutputs<true>(x, int(n), out);
    // The backward pass differentiates with respect to reversed time: d/dt = -d/d(-t).
    for (Eigen::Index k = 0; k < n; ++k)
        out[3 * k + 1] = -out[3 * k + 1];
}

Eigen::RowVectorXd
FilteringEstimator::zeroPhaseLowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const
{
    return anticausalLowPass(lowPass(x));
}

} // namespace learnid
