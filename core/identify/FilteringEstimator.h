#pragma once

#include "control/StateSpace.h"

#include <Eigen/Core>
#include <vector>

namespace learnid {

/// The filtering estimator of paper eq. (17)-(18): F(s) = rho^3/(s + rho)^3 in controllable
/// canonical form, so that one state vector gives F x, F s x and F s^2 x (x1, x2 = x1', x3 = x2').
/// Discretised with Tustin at the sample period. Signals are row vectors of samples.
class FilteringEstimator
{
public:
    FilteringEstimator(double rho, double samplePeriod);

    double rho() const { return m_rho; }
    const StateSpace &discrete() const { return m_discrete; }

    /// Causal filtering, as a controller could run it: rows F x, F s x, F s^2 x (3 x N).
    /// The filter starts at rest at x[0].
    Eigen::MatrixXd causal(const Eigen::Ref<const Eigen::RowVectorXd> &x) const;

    /// Causal F x alone (1 x N).
    Eigen::RowVectorXd lowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const;

    /// Zero-phase filtering of recorded data: F applied forward, then backward with its
    /// derivative outputs, i.e. F(s) F(-s) x and its first two time derivatives (3 x N).
    Eigen::MatrixXd zeroPhase(const Eigen::Ref<const Eigen::RowVectorXd> &x) const;

    /// F applied backward in time, F(-s) x (1 x N): the transpose of lowPass() as a matrix in
    /// the interior (both start at rest at their first sample, so the edges differ slightly).
    Eigen::RowVectorXd anticausalLowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const;

    /// F(s) F(-s) x alone (1 x N).
    Eigen::RowVectorXd zeroPhaseLowPass(const Eigen::Ref<const Eigen::RowVectorXd> &x) const;
    /// zeroPhaseLowPass() of the n samples at x, in place (no copies: for long records).
    void zeroPhaseLowPassInPlace(double *x, Eigen::Index n) const;
    /// The same on several signals of n samples each, two at a time in one pass: each filter
    /// recursion waits on its own previous output, so a second one runs in the first's latency.
    /// The results are those of one signal at a time, to the bit.
    void zeroPhaseLowPassInPlace(const std::vector<double *> &series, Eigen::Index n) const;
    /// The same on every column of x (N x c, each a signal of N samples), 2 p columns at a time
    /// in p-lane SIMD registers (p = 2 with SSE2, 4 with AVX): the latency of one recursion then
    /// carries several signals. The results are those of one column at a time, to the bit.
    void zeroPhaseLowPassColumnsInPlace(Eigen::Ref<Eigen::MatrixXd> x) const;
    /// causal() or zeroPhase() of the n samples at x into out (3 x n, column-major) without
    /// copies; zeroPhase overwrites x with its forward pass.
    void filterInto(double *x, Eigen::Index n, bool zeroPhase, double *out) const;

    /// Variance of white noise after lowPass() relative to before: the sum of the squared
    /// impulse response of F.
    double lowPassNoiseGain() const;
    /// The same for zeroPhaseLowPass(): the sum of the squared impulse response of F(s)F(-s).
    double zeroPhaseNoiseGain() const;

private:
    template <bool reversed> void runAllOutputs(const double *x, int n, double *out) const;
    template <bool reversed> void runLowPass(const double *x, int n, double *out) const;
    template <bool reversed> void runLowPassPairInPlace(double *x, double *w, int n) const;

    double m_rho;
    double m_ts;
    StateSpace m_discrete;
    // The filter runs as Tustin first-order sections g (1 +- z^-1) / (1 - p z^-1): the same
    // transfer functions as the discrete state space's outputs in fewer operations.
    double m_sectionGain = 0.0;
};

} // namespace learnid
