#pragma once

#include "identify/PayloadObservability.h"
#include "model/Payload.h"
#include "model/PayloadPrior.h"

#include <Eigen/Core>
#include <QString>
#include <array>

namespace learnid {

/// How estimatePayload() weighs the data against the prior.
struct PayloadEstimateSettings
{
    /// Directions (scaled by their columns) weaker than this share of the strongest are not
    /// determined: they keep the prior, and the report says so (LogFitSettings::priorShare).
    double priorShare = 0.03;
    /// The log-det prior's weight in the plausible estimate (PlausibleProblem::priorShare).
    double geometricShare = 0.003;
    /// The estimate's variance per unit of the rows' residual variance: 1 for independent rows;
    /// rows filtered by a filter of noise gain g (sum of its squared impulse response) and kept
    /// every s-th sample carry correlated residuals: 1 / (g s) (payloadVarianceFactor()).
    double varianceFactor = 1.0;
    /// The nearest real body (else parameters = leastSquares, which may not be one).
    bool plausible = true;
};

/// The payload as the data and the prior determine it.
struct PayloadEstimate
{
    InertialParameters parameters = InertialParameters::Zero();   ///< plausible: a real body
    PayloadBody body;                                             ///< the same as m, c, I_c
    InertialParameters leastSquares = InertialParameters::Zero(); ///< the fit, prior where unseen
    InertialParameters prior = InertialParameters::Zero();        ///< PayloadPrior::parameters()
    /// What unseen directions keep: the prior body moved to the mass and the components of the
    /// centre of mass the data identify, its inertia about the centre of mass the prior's
    /// scaled with the mass.
    InertialParameters anchor = InertialParameters::Zero();
    PayloadObservability observability;
    /// Covariance of the least-squares parameters (10 x 10): varianceFactor sigma^2 (A^T A)^+,
    /// sigma^2 the residual variance per row, (A^T A)^+ over the determined directions only.
    Eigen::Matrix<double, 10, 10> covariance = Eigen::Matrix<double, 10, 10>::Zero();
    /// The body's values and their standard errors in the order mass [kg], c x, y, z [m],
    /// I_c xx, xy, yy, xz, yz, zz [kg m^2] (first order through the covariance), and whether
    /// the data identified each (its parameters all determined; else it is the prior's).
    std::array<double, 10> bodyValue{};
    std::array<double, 10> bodyStandardError{};
    std::array<bool, 10> bodyIdentified{};
    Eigen::Index rows = 0;
    double residualRms = 0.0;    ///< of the least-squares fit, per row
    bool comInsideBound = false; ///< the estimate's centre of mass inside the prior's bound
    bool converged = false;
    QString solverReport;

    /// The names of the body's values in bodyValue's order: m, cx, ..., Izz.
    static QStringList bodyNames();
};

/// The payload fitted to rows A (r x 10, the payload's regressor, weighted) against targets b
/// (r, the measured torque minus the arm's): the least-squares fit about the prior in the
/// directions the rows determine (PayloadObservability), the rest at the prior body (moved to the
/// fitted mass and seen centre of mass), then the nearest real body to it (plausibleEstimate() for
/// one link: the data's determined directions as they are, the unseen ones held at the prior with
/// the strongest direction's weight, the log-det divergence from the prior body, the mass inside
/// the prior's bounding ellipsoid): what the data do not see stays the prior's. Throws Error for
/// sizes that do not match, values that are not finite, or a prior validatePayloadPrior() refuses.
PayloadEstimate estimatePayload(const Eigen::MatrixXd &rows, const Eigen::VectorXd &targets,
                                const PayloadPrior &prior,
                                const PayloadEstimateSettings &settings = {});

} // namespace learnid
