#pragma once

#include "identify/LogSignals.h"

#include <Eigen/Core>
#include <QString>
#include <vector>

namespace learnid {

class ChainModel;

/// How the parameters are fitted to recorded logs (docs/identify.md).
struct LogFitSettings
{
    /// Directions of the parameters (each scaled by its regressor column's norm) whose singular
    /// value is below priorShare times the largest are not determined by the data: the plain
    /// fit holds them at the CAD prior, the plausible fit holds the joint terms among them there,
    /// and the reports say which standard parameters they are (standardDetermined).
    double priorShare = 0.03;
    /// The geometric prior's weight in the plausible fit (PlausibleProblem::priorShare): it
    /// counts 0.003^2 (1e-5) of the best-determined direction's information. On the KUKA LWR4+
    /// logs 0.002 to 0.007 predict the held-out runs within 0.3 points of each other; larger
    /// values hold the double pendulum's light links too close to its published model
    /// (docs/identify.md).
    double geometricShare = 0.003;
    /// Weigh each joint's rows by the inverse RMS of its residual after a first, unweighted fit
    /// (weighted least squares: a joint with noisy torque does not drown the others).
    bool weighted = true;
    /// Plausible standard parameters (plausibleEstimate(): every link a body near the CAD one,
    /// friction not negative), else the fit as is.
    bool consistent = true;
    /// Each link's mass kept inside its bounding volume (linkVolumes()).
    bool volumes = true;
    /// Each link kept inside the plausibility rule (PlausibilityRule) where the CAD link is.
    bool plausible = true;
};

/// The parameters fitted to logs, and what the data could determine.
struct LogFit
{
    Eigen::VectorXd standard;     ///< p: the result (consistent when asked)
    Eigen::VectorXd base;         ///< m: its base parameters
    Eigen::VectorXd leastSquares; ///< p: the weighted fit before consistency, prior where unseen
    Eigen::VectorXd prior;        ///< p: the CAD model made real bodies (CadPrior.h)
    Eigen::VectorXd jointNoise;   ///< n: RMS residual per joint of the unweighted fit [N m]
    Eigen::VectorXd trainingRms;  ///< n: RMS residual per joint of the result on the logs [N m]
    int rank = 0;                 ///< determined directions of the p standard parameters
    int baseCount = 0;            ///< m: the most any data could determine
    double condition = 0.0;       ///< largest / smallest determined singular value
    Eigen::Index samples = 0;     ///< samples used, all logs
    /// Per base parameter: the share of its direction the data determine (0 to 1).
    std::vector<double> observedShare;
    /// Per standard parameter (p): the share of its own direction (the parameter alone, scaled
    /// by its regressor column) that lies in what the data determine, 0 to 1. At least 0.5: the
    /// data determined it; below: it was kept from the prior (the CAD model), or is only
    /// known in combination with others.
    std::vector<double> standardDetermined;
    bool converged = true; ///< the consistent fit met its stopping rule
    QString solverReport;  ///< the solver's summary of the consistent fit

    /// Base parameters with a share below 0.5, in order.
    std::vector<int> undetermined() const;
};

/// Fits model's standard parameters (inertia of every link and the joint terms the model has
/// on) to the logs' torques by weighted least squares over all logs together, keeping the CAD
/// prior where the data are weak, then (when asked) the nearest physically consistent
/// parameters (nearestConsistentEstimate) in the metric of the data. Throws Error when a log's
/// joint count differs from the model's, no log has samples, or a value is not finite.
LogFit fitLogs(const ChainModel &model, const std::vector<FilteredLog> &logs,
               const LogFitSettings &settings);

/// How well standard parameters predict a log's torque, both filtered alike (F(s)F(-s) of the
/// fit, edges cut): the sensor noise above the filter is not counted as model error.
struct TorqueFigures
{
    Eigen::VectorXd rmsError;    ///< n: RMS of predicted minus measured [N m]
    Eigen::VectorXd rmsMeasured; ///< n: RMS of the measured torque [N m]
    double overall = 0.0;        ///< sqrt(sum e^2 / sum tau^2) over joints and samples
    double meanRatio = 0.0;      ///< mean over joints of rmsError / rmsMeasured

    double ratio(int joint) const;
};

/// The torque model predicts with standard parameters pi along log, against the log's torque.
TorqueFigures torqueFigures(const ChainModel &model, const Eigen::VectorXd &pi,
                            const FilteredLog &log);
/// The same figures from the torques themselves (n x K each, filtered alike).
TorqueFigures torqueFigures(const Eigen::MatrixXd &measured, const Eigen::MatrixXd &predicted);
/// The torque pi predicts along log, filtered as the fit filters it (n x log.keptSamples()).
Eigen::MatrixXd predictedTorque(const ChainModel &model, const Eigen::VectorXd &pi,
                                const FilteredLog &log);
/// The log's measured torque, filtered alike (n x log.keptSamples()).
Eigen::MatrixXd measuredTorque(const FilteredLog &log);

} // namespace learnid
