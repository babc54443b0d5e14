#pragma once

#include "identify/JointRows.h"
#include "model/Error.h"

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace learnid {

/// One block of least-squares rows (e.g. one trial's), reduced per joint j to its Gram
/// quantities about a reference estimate phiRef (m):
///   G_j = A_j^T A_j,  g_j = A_j^T r_j,  rr_j = r_j^T r_j,  r_j = b_j - A_j phiRef,
/// and for the covariance S_j = (H^T A_j)^T (H^T A_j) (see NoiseShaping). A_j (N x m) and b_j
/// (N) are joint j's rows: A_j phi = b_j [N m]. The block keeps O(n m^2) numbers whatever N.
///
/// The residual at any phi follows exactly (d = phi - phiRef):
///   ||b_j - A_j phi||^2 = rr_j - 2 d^T g_j + d^T G_j d,
/// which is b^T b - 2 phi^T A^T b + phi^T A^T A phi expanded about phiRef instead of 0: the
/// terms are then of the size of the residual itself (phiRef is the block's own fit), not of
/// b^T b, so rounding does not swamp a residual 1e-6 of the torque.
///
/// A joint's setters touch only that joint's numbers: different joints may be set concurrently.
class GramBlock
{
public:
    GramBlock() = default;
    /// n joints, m parameters, `samples` rows per joint, reference phiRef (m).
    GramBlock(int n, int m, Eigen::Index samples, const Eigen::VectorXd &reference);

    int joints() const { return int(m_gram.size()); }
    int parameters() const { return int(m_reference.size()); }
    Eigen::Index samples() const { return m_samples; }
    const Eigen::VectorXd &reference() const { return m_reference; }

    /// Joint j's rows a (N x m) and targets b (N), in one pass (any Eigen expression, e.g. a
    /// strided map of sample-major stacked rows).
    template <typename A, typename B> void setJointRows(int j, const A &a, const B &b)
    {
        m_gram[size_t(j)] = gramOf(a);
        setJointResidual(j, a, b);
    }
    /// Joint j's G_j and g_j = A_j^T b_j - G_j phiRef only (no residual pass): enough to solve;
    /// rr_j stays NaN until setJointResidual() sets it at the solution.
    template <typename A, typename B> void setJointNormalEquations(int j, const A &a, const B &b)
    {
        m_gram[size_t(j)] = gramOf(a);
        m_gradient[size_t(j)] = a.transpose() * b - m_gram[size_t(j)] * m_reference;
        m_residualSquares[j] = std::numeric_limits<double>::quiet_NaN();
        m_targetSquares[j] = b.squaredNorm();
    }
    /// Moves the reference to phiRef (m); every joint's residual must then be set again with
    /// setJointResidual() (the Gram matrices stay).
    void setReference(const Eigen::VectorXd &reference) { m_reference = reference; }
    /// Joint j's residual terms g_j, rr_j about the reference, from its rows (as setJointRows()
    /// without the Gram matrix).
    template <typename A, typename B> void setJointResidual(int j, const A &a, const B &b)
    {
        const Eigen::VectorXd r = b - a * m_reference;
        m_gradient[size_t(j)] = a.transpose() * r;
        m_residualSquares[j] = r.squaredNorm();
        m_targetSquares[j] = b.squaredNorm();
    }
    /// Joint j's rows filtered by H^T (N x m), for the covariance.
    template <typename H> void setJointShapedRows(int j, const H &h)
    {
        m_shapedGram[size_t(j)] = gramOf(h);
    }
    /// The same three from joint j's rows by their nonzero columns (JointRows): rows.a (N x c)
    /// holds the parameters rows.columns, every other column of the rows is identically 0. The
    /// products then skip the zero columns; the results are those of the full rows.
    template <typename B> void setJointNormalEquations(int j, const JointRows &rows, const B &b)
    {
        checkColumns(rows);
        m_gram[size_t(j)] = scattered(gramOf(rows.a), rows.columns);
        m_gradient[size_t(j)] = scattered(Eigen::VectorXd(rows.a.transpose() * b), rows.columns) -
                                m_gram[size_t(j)] * m_reference;
        m_residualSquares[j] = std::numeric_limits<double>::quiet_NaN();
        m_targetSquares[j] = b.squaredNorm();
    }
    template <typename B> void setJointResidual(int j, const JointRows &rows, const B &b)
    {
        checkColumns(rows);
        const Eigen::VectorXd reference = m_reference(rows.columns);
        const Eigen::VectorXd r = b - rows.a * reference;
        m_gradient[size_t(j)] = scattered(Eigen::VectorXd(rows.a.transpose() * r), rows.columns);
        m_residualSquares[j] = r.squaredNorm();
        m_targetSquares[j] = b.squaredNorm();
    }
    void setJointShapedRows(int j, const JointRows &shaped)
    {
        checkColumns(shaped);
        m_shapedGram[size_t(j)] = scattered(gramOf(shaped.a), shaped.columns);
    }
    /// The weight of joint j's rows (default 1).
    void setJointWeight(int j, double weight) { m_weight[j] = weight; }

    const Eigen::MatrixXd &gram(int j) const { return m_gram[size_t(j)]; }
    const Eigen::VectorXd &gradient(int j) const { return m_gradient[size_t(j)]; }
    double residualSquares(int j) const { return m_residualSquares[j]; }
    /// ||b_j||^2: joint j's targets (the measured torque the rows explain); 0 until set.
    double targetSquares(int j) const { return m_targetSquares[j]; }
    const Eigen::MatrixXd &shapedGram(int j) const { return m_shapedGram[size_t(j)]; }
    /// True when every joint's shaped rows were set.
    bool shaped() const;
    double weight(int j) const { return m_weight[j]; }

    /// A_j^T (b_j - A_j phi) (m): the gradient about another estimate.
    Eigen::VectorXd gradientAt(int j, const Eigen::VectorXd &phi) const;
    /// ||b_j - A_j phi||^2 for every joint (n), clamped at 0 against rounding.
    Eigen::VectorXd residualSquaresAt(const Eigen::VectorXd &phi) const;
    /// The Gram matrices, gradients, reference and weights finite (rr_j may be NaN: not set).
    bool allFinite() const;

private:
    /// a^T a. Few columns (the paper's arm: 3): m^2 coefficient-wise dot products of the long
    /// columns, no GEMM packing. Many (a URDF robot's base parameters): Eigen's blocked
    /// symmetric rank update, several times faster there.
    template <typename A> static Eigen::MatrixXd gramOf(const A &a)
    {
        if (a.cols() <= 8)
            return a.transpose().lazyProduct(a);
        Eigen::MatrixXd g = Eigen::MatrixXd::Zero(a.cols(), a.cols());
        g.selfadjointView<Eigen::Lower>().rankUpdate(a.transpose());
        return g.selfadjointView<Eigen::Lower>();
    }

    /// Throws Error unless rows.columns are rows.a.cols() ascending parameter indices.
    void checkColumns(const JointRows &rows) const;
    /// The c x c Gram matrix of columns `columns` as the m x m one of all (0 elsewhere).
    Eigen::MatrixXd scattered(const Eigen::MatrixXd &gram, const std::vector<int> &columns) const;
    /// The same for a vector of c entries.
    Eigen::VectorXd scattered(const Eigen::VectorXd &v, const std::vector<int> &columns) const;

    Eigen::VectorXd m_reference;
    Eigen::Index m_samples = 0;
    std::vector<Eigen::MatrixXd> m_gram;
    std::vector<Eigen::VectorXd> m_gradient;
    Eigen::VectorXd m_residualSquares;
    Eigen::VectorXd m_targetSquares;
    std::vector<Eigen::MatrixXd> m_shapedGram;
    Eigen::VectorXd m_weight;
};

/// The error for least-squares sizes that do not match (what and how many of each).
Error sizeError(Eigen::Index rows, Eigen::Index columns, Eigen::Index targets, int joints,
                Eigen::Index parameters);

/// Joint j's rows a[j] (N x m) and targets column j of b (N x n) as one block, solved from
/// phiPrev (tolerance: the rank tolerance of observableUpdate()) and taken about that fit, where
/// its residuals are the rows' own and any later fit's residual follows without cancellation.
/// The shaped Gram matrices and weights are left to the caller.
GramBlock selfFittedBlock(const std::vector<Eigen::MatrixXd> &a, const Eigen::MatrixXd &b,
                          const Eigen::VectorXd &phiPrev, double tolerance);

/// The block of sample-major stacked rows as observableUpdate() takes them: row k*n + j of a
/// (N n x m) and b (N n) is joint j of sample k; shaped: H^T a of the same layout, or empty.
GramBlock stackedGramBlock(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                           const Eigen::VectorXd &reference, const Eigen::MatrixXd &shaped = {});

} // namespace learnid
