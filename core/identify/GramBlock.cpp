#include "identify/GramBlock.h"

#include "identify/ObservableUpdate.h"
#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

Error sizeError(Eigen::Index rows, Eigen::Index columns, Eigen::Index targets, int joints,
                Eigen::Index parameters)
{
    return Error(QCoreApplication::translate(
                     "ObservableUpdate",
                     "least squares sizes do not match: %1 x %2 regressor, %3 targets, "
                     "%4 joints, %5 parameters")
                     .arg(rows)
                     .arg(columns)
                     .arg(targets)
                     .arg(joints)
                     .arg(parameters));
}

GramBlock::GramBlock(int n, int m, Eigen::Index samples, const Eigen::VectorXd &reference)
    : m_reference(reference)
    , m_samples(samples)
    , m_gram(size_t(n), Eigen::MatrixXd::Zero(m, m))
    , m_gradient(size_t(n), Eigen::VectorXd::Zero(m))
    , m_residualSquares(Eigen::VectorXd::Zero(n))
    , m_targetSquares(Eigen::VectorXd::Zero(n))
    , m_shapedGram(size_t(n))
    , m_weight(Eigen::VectorXd::Ones(n))
{
    if (reference.size() != m || n <= 0)
        throw sizeError(Eigen::Index(n) * samples, m, Eigen::Index(n) * samples, n,
                        reference.size());
}

bool GramBlock::shaped() const
{
    for (const Eigen::MatrixXd &s : m_shapedGram)
        if (s.rows() != parameters())
            return false;
    return !m_shapedGram.empty();
}

Eigen::VectorXd GramBlock::gradientAt(int j, const Eigen::VectorXd &phi) const
{
    return m_gradient[size_t(j)] - m_gram[size_t(j)] * (phi - m_reference);
}

Eigen::VectorXd GramBlock::residualSquaresAt(const Eigen::VectorXd &phi) const
{
    const Eigen::VectorXd d = phi - m_reference;
    Eigen::VectorXd out(joints());
    for (int j = 0; j < joints(); ++j) {
        const double r = m_residualSquares[j] - 2.0 * d.dot(m_gradient[size_t(j)]) +
                         d.dot(m_gram[size_t(j)] * d);
        out[j] = std::max(r, 0.0);
    }
    return out;
}

bool GramBlock::allFinite() const
{
    // rr_j is left out: NaN marks a residual not set yet (setJointNormalEquations()).
    if (!m_reference.allFinite() || !m_weight.allFinite())
        return false;
    for (int j = 0; j < joints(); ++j) {
        if (!m_gram[size_t(j)].allFinite() || !m_gradient[size_t(j)].allFinite() ||
            !m_shapedGram[size_t(j)].allFinite())
            return false;
    }
    return true;
}

void GramBlock::checkColumns(const JointRows &rows) const
{
    const int m = parameters();
    const std::vector<int> &c = rows.columns;
    bool ascending = rows.a.cols() == Eigen::Index(c.size());
    for (size_t s = 0; ascending && s < c.size(); ++s)
        ascending = c[s] >= (s > 0 ? c[s - 1] + 1 : 0) && c[s] < m;
    if (!ascending)
        throw sizeError(rows.a.rows(), rows.a.cols(), m_samples, joints(), m);
}

Eigen::MatrixXd GramBlock::scattered(const Eigen::MatrixXd &gram,
                                     const std::vector<int> &columns) const
{
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(parameters(), parameters());
    out(columns, columns) = gram;
    return out;
}

Eigen::VectorXd GramBlock::scattered(const Eigen::VectorXd &v,
                                     const std::vector<int> &columns) const
{
    Eigen::VectorXd out = Eigen::VectorXd::Zero(parameters());
    out(columns) = v;
    return out;
}

GramBlock selfFittedBlock(const std::vector<Eigen::MatrixXd> &a, const Eigen::MatrixXd &b,
                          const Eigen::VectorXd &phiPrev, double tolerance)
{
    const int n = int(a.size());
    if (n == 0 || b.cols() != n)
        throw sizeError(b.rows() * b.cols(), phiPrev.size(), b.size(), n, phiPrev.size());
    GramBlock block(n, int(phiPrev.size()), b.rows(), phiPrev);
    for (int j = 0; j < n; ++j) {
        if (a[size_t(j)].rows() != b.rows() || a[size_t(j)].cols() != phiPrev.size())
            throw sizeError(a[size_t(j)].rows(), a[size_t(j)].cols(), b.rows(), n, phiPrev.size());
        block.setJointNormalEquations(j, a[size_t(j)], b.col(j));
    }
    block.setReference(observableUpdate({&block}, phiPrev, tolerance).phi);
    for (int j = 0; j < n; ++j)
        block.setJointResidual(j, a[size_t(j)], b.col(j));
    return block;
}

GramBlock stackedGramBlock(const Eigen::MatrixXd &a, const Eigen::VectorXd &b, int n,
                           const Eigen::VectorXd &reference, const Eigen::MatrixXd &shaped)
{
    if (n <= 0 || a.rows() % n != 0 || b.size() != a.rows() || reference.size() != a.cols() ||
        (shaped.size() != 0 && (shaped.rows() != a.rows() || shaped.cols() != a.cols())))
        throw sizeError(a.rows(), a.cols(), b.size(), n, reference.size());
    const Eigen::Index samples = a.rows() / n;
    const Eigen::Index m = a.cols();
    GramBlock block(n, int(m), samples, reference);
    using Strided =
        Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>;
    using StridedVector = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>;
    const Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic> stride(a.rows(), n);
    for (int j = 0; j < n; ++j) {
        // Contiguous copies of joint j's rows: the products below then run at full speed.
        const Eigen::MatrixXd aj = Strided(a.data() + j, samples, m, stride);
        const Eigen::VectorXd bj = StridedVector(b.data() + j, samples, Eigen::InnerStride<>(n));
        block.setJointRows(j, aj, bj);
        if (shaped.size() != 0)
            block.setJointShapedRows(
                j, Eigen::MatrixXd(Strided(shaped.data() + j, samples, m, stride)));
    }
    return block;
}

} // namespace learnid
