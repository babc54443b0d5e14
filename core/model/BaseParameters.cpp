#include "model/BaseParameters.h"

#include "model/Error.h"

#include <Eigen/QR>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

constexpr double zeroColumnTolerance = 1e-10;
constexpr double betaCleanTolerance = 1e-9;

} // namespace

BaseParameters BaseParameters::fromRegressor(const Eigen::MatrixXd &rows)
{
    if (!rows.allFinite() || rows.cols() == 0) {
        throw Error(QCoreApplication::translate("BaseParameters",
                                                "base parameters need finite regressor rows"));
    }
    const Eigen::Index p = rows.cols();
    const Eigen::VectorXd norms = rows.colwise().norm();
    const double largest = norms.maxCoeff();
    if (!(largest > 0.0)) {
        throw Error(QCoreApplication::translate(
            "BaseParameters", "the torques depend on no parameter: every regressor column is 0"));
    }
    Eigen::MatrixXd scaled = Eigen::MatrixXd::Zero(rows.rows(), p);
    std::vector<int> nonzero;
    for (Eigen::Index j = 0; j < p; ++j) {
        if (norms[j] > zeroColumnTolerance * largest) {
            scaled.col(j) = rows.col(j) / norms[j];
            nonzero.push_back(int(j));
        }
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> pivoted(scaled);
    pivoted.setThreshold(rankTolerance);
    const Eigen::Index rank = pivoted.rank();

    // Independent columns in the standard order: a column is kept when it adds a direction to
    // the span of those kept before it (the diagonal of an unpivoted QR of the kept columns).
    BaseParameters base;
    base.m_standardCount = int(p);
    Eigen::MatrixXd kept(rows.rows(), 0);
    for (const int j : nonzero) {
        Eigen::MatrixXd trial(rows.rows(), kept.cols() + 1);
        trial << kept, scaled.col(j);
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(trial);
        const double diagonal = std::abs(qr.matrixQR()(kept.cols(), kept.cols()));
        if (diagonal > rankTolerance && kept.cols() < rank) {
            kept = std::move(trial);
            base.m_independent.push_back(j);
        }
    }
    for (int j = 0; j < int(p); ++j) {
        if (std::find(base.m_independent.begin(), base.m_independent.end(), j) ==
            base.m_independent.end())
            base.m_dependent.push_back(j);
    }
    // beta: Y_D = Y_I beta, on the unscaled columns.
    Eigen::MatrixXd yI(rows.rows(), Eigen::Index(base.m_independent.size()));
    Eigen::MatrixXd yD(rows.rows(), Eigen::Index(base.m_dependent.size()));
    for (size_t i = 0; i < base.m_independent.size(); ++i)
        yI.col(Eigen::Index(i)) = rows.col(base.m_independent[i]);
    for (size_t i = 0; i < base.m_dependent.size(); ++i)
        yD.col(Eigen::Index(i)) = rows.col(base.m_dependent[i]);
    base.m_beta = yI.colPivHouseholderQr().solve(yD);
    const double scale = std::max(1.0, base.m_beta.cwiseAbs().maxCoeff());
    base.m_beta = base.m_beta.unaryExpr(
        [scale](double b) { return std::abs(b) < betaCleanTolerance * scale ? 0.0 : b; });
    return base;
}

Eigen::MatrixXd BaseParameters::baseMatrix() const
{
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(baseCount(), m_standardCount);
    for (size_t i = 0; i < m_independent.size(); ++i)
        k(Eigen::Index(i), m_independent[i]) = 1.0;
    for (size_t d = 0; d < m_dependent.size(); ++d)
        k.col(m_dependent[d]) = m_beta.col(Eigen::Index(d));
    return k;
}

Eigen::VectorXd BaseParameters::baseFromStandard(const Eigen::VectorXd &pi) const
{
    Eigen::VectorXd phi(baseCount());
    Eigen::VectorXd size(baseCount()); // the magnitude of each combination's terms
    for (size_t i = 0; i < m_independent.size(); ++i) {
        phi[Eigen::Index(i)] = pi[m_independent[i]];
        size[Eigen::Index(i)] = std::abs(pi[m_independent[i]]);
    }
    for (size_t d = 0; d < m_dependent.size(); ++d) {
        phi += m_beta.col(Eigen::Index(d)) * pi[m_dependent[d]];
        size += m_beta.col(Eigen::Index(d)).cwiseAbs() * std::abs(pi[m_dependent[d]]);
    }
    // Terms that cancel (m cy3 + m cy4 of two mirrored links) leave a rounding residue of 1e-17
    // instead of 0; the learning laws scale each parameter by its value, so a residue would never
    // be learned. A sum below 1e-12 of its terms' size is that residue: it is 0.
    for (Eigen::Index i = 0; i < phi.size(); ++i)
        if (std::abs(phi[i]) <= 1e-12 * size[i])
            phi[i] = 0.0;
    return phi;
}

Eigen::VectorXd BaseParameters::standardFromBase(const Eigen::VectorXd &phi,
                                                 const Eigen::VectorXd &prior) const
{
    Eigen::VectorXd pi = prior;
    Eigen::VectorXd independent = phi;
    for (size_t d = 0; d < m_dependent.size(); ++d)
        independent -= m_beta.col(Eigen::Index(d)) * prior[m_dependent[d]];
    for (size_t i = 0; i < m_independent.size(); ++i)
        pi[m_independent[i]] = independent[Eigen::Index(i)];
    return pi;
}

QString BaseParameters::describe(int i, const QStringList &standardNames) const
{
    QString text = standardNames.value(m_independent[size_t(i)]);
    for (size_t d = 0; d < m_dependent.size(); ++d) {
        const double b = m_beta(i, Eigen::Index(d));
        if (b == 0.0)
            continue;
        const QString name = standardNames.value(m_dependent[d]);
        const QString magnitude = QString::number(std::abs(b), 'g', 4);
        text += (b < 0.0 ? QStringLiteral(" − ") : QStringLiteral(" + ")) +
                (std::abs(std::abs(b) - 1.0) < 1e-12 ? name : magnitude + QChar(0x00B7) + name);
    }
    return text;
}

} // namespace learnid
