#pragma once

#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <array>

namespace learnid {

class PayloadModel;

/// What a path can tell about a payload, before it runs (docs/payload.md): the SVD of the
/// payload's regressor rows Y_k stacked over the path, each column scaled by its norm (as
/// LogFit scales the standard parameters). Directions whose singular value is below share times
/// the largest are not determined: the estimate keeps the prior there.
struct PayloadObservability
{
    /// Per payload parameter (m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz): the share of its
    /// own direction (scaled) that lies in what the path determines, 0 to 1 (LogFit's
    /// standardDetermined). At least 0.5: identified; below: kept from the prior.
    std::array<double, 10> determined{};
    int rank = 0;           ///< determined directions (0 to 10)
    double condition = 0.0; ///< largest / smallest determined singular value (scaled)
    /// The directions the path does not see (10 x (10 - rank)), in the parameters' own units,
    /// each of unit length in the scaled ones.
    Eigen::MatrixXd unseen;
    /// The singular values of the scaled rows, largest first (10).
    Eigen::VectorXd singularValues;
    /// The inverse of the scaled Gram matrix restricted to the determined directions, unscaled
    /// (10 x 10): (A^T A)^+ as the truncated fit uses it; the standard errors' shape.
    Eigen::MatrixXd truncatedInverse;

    bool identified(int parameter) const { return determined[size_t(parameter)] >= 0.5; }
    bool massIdentified() const { return identified(0); }
    /// The centre of mass: every component m cx, m cy, m cz identified.
    bool comIdentified() const;
    /// Every entry of the inertia identified.
    bool inertiaIdentified() const;
    /// The parameters' names as in reports: m, m·cx, ..., Izz.
    static QStringList parameterNames();
    /// One line per group (mass, each axis of the centre of mass, the inertia) that the path does
    /// not see, with what would let it see it, for the technician; empty when all are seen.
    /// link: the link's name in the text.
    QStringList advice(const QString &link) const;
};

/// The observability of rows A (r x 10) of the payload's regressor (weighted as a fit weighs
/// them); share in (0, 1). Throws Error for a wrong column count, a non-finite entry or a share
/// out of range.
PayloadObservability payloadObservability(const Eigen::MatrixXd &rows, double share = 0.03);

/// The same for a path: the regressor at each sample of q, qd, qdd (n x N each, the model's
/// joints). Throws Error for mismatched sizes or no samples.
PayloadObservability payloadPathObservability(const PayloadModel &model, const Eigen::MatrixXd &q,
                                              const Eigen::MatrixXd &qd, const Eigen::MatrixXd &qdd,
                                              double share = 0.03);

} // namespace learnid
