#pragma once

#include <Eigen/Core>
#include <QStringList>
#include <vector>

namespace learnid {

/// The base parameters of a model linear in its standard parameters pi (p): the combinations
///   phi = pi_I + beta pi_D      (r = rank, pi_I: r independent, pi_D: p - r dependent)
/// that the torques determine, from regressor rows Y (rows x p, tau = Y pi) at many states.
/// Then Y pi = Y_I phi for every pi: Y_I (the independent columns) is the base regressor.
///
/// The rank comes from QR with column pivoting of Y with its columns scaled to unit norm:
/// |R_jj| <= rankTolerance (1e-8) counts as zero; columns whose norm is below 1e-10 of the
/// largest are zero columns (parameters the torques never see). Which columns are independent
/// is then decided in the standard order (a column is dependent when it lies in the span of
/// the independent ones before it, the same tolerance), so an earlier link's parameter absorbs
/// the later ones it cannot be told from ("Izz1 + Ia1", "m cx2 + 0.3 m3"), as in the classic
/// regrouping of Khalil and Gautier. beta by least squares on those columns.
class BaseParameters
{
public:
    static constexpr double rankTolerance = 1e-8;

    BaseParameters() = default;
    /// Throws Error when rows holds non-finite numbers or no column is nonzero.
    static BaseParameters fromRegressor(const Eigen::MatrixXd &rows);

    int standardCount() const { return m_standardCount; }
    int baseCount() const { return int(m_independent.size()); }
    /// Standard indices of pi_I, ascending: base parameter i combines standard independent()[i]
    const std::vector<int> &independent() const { return m_independent; }
    /// Standard indices of pi_D, ascending (zero columns included: their beta column is zero).
    const std::vector<int> &dependent() const { return m_dependent; }
    const Eigen::MatrixXd &beta() const { return m_beta; } ///< r x (p - r)
    /// K (r x p) with phi = K pi.
    Eigen::MatrixXd baseMatrix() const;

    Eigen::VectorXd baseFromStandard(const Eigen::VectorXd &pi) const;
    /// A standard vector with phi's base parameters whose dependent part is prior's:
    /// pi_D = prior_D, pi_I = phi - beta prior_D.
    Eigen::VectorXd standardFromBase(const Eigen::VectorXd &phi,
                                     const Eigen::VectorXd &prior) const;

    /// Base parameter i written out in the standard names, e.g. "Izz₁ + Ia₁ + 0.25·m₂".
    QString describe(int i, const QStringList &standardNames) const;

private:
    int m_standardCount = 0;
    std::vector<int> m_independent;
    std::vector<int> m_dependent;
    Eigen::MatrixXd m_beta;
};

} // namespace learnid
