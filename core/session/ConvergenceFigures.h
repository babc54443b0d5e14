#pragma once

#include "model/RobotModel.h"
#include "types/JointTrajectory.h"

#include <Eigen/Core>
#include <QMetaType>
#include <QStringList>
#include <QVector>
#include <optional>

namespace learnid {

/// The largest relative difference of x from ref over the parameters, in percent, with its sign:
/// (x_i - ref_i) / |ref_i| * 100 for the i of largest magnitude (entries with ref_i = 0 are
/// skipped). The "relative change" of an estimate from the previous one and the "error against
/// the truth" of the convergence table (CLI and GUI alike).
double largestRelativeDifferencePercent(const Eigen::VectorXd &x, const Eigen::VectorXd &ref);

/// The path-torque error in percent: ||W_path (phiHat - phi)|| / ||W_path phi|| * 100, W_path
/// the regressor along the desired trajectory (all joints, all samples): how far the torque the
/// estimate predicts on the path is from the torque the robot phi needs there. Directions the
/// path does not excite do not count (docs/method.md). NaN when phi needs no torque there.
double pathTorqueErrorPercent(const RobotModel &model, const JointTrajectory &path,
                              const Eigen::VectorXd &phiHat, const Eigen::VectorXd &phi);

/// pathTorqueErrorPercent of every estimate against one reference on one path, with the
/// regressor along the path evaluated once (the window's convergence chart after every trial).
QVector<double> pathTorqueErrorsPercent(const RobotModel &model, const JointTrajectory &path,
                                        const QVector<Eigen::VectorXd> &estimates,
                                        const Eigen::VectorXd &reference);

/// The convergence figures of an n-joint arm: per estimate, on one planned path (the newest
/// trial's), the path-torque error against the truth (a simulated robot; empty otherwise) and
/// the path-torque change to the newest estimate (0 for the newest itself); and whether the
/// newest estimate describes real bodies (URDF robots, EstimateConsistency.h).
struct EstimateFigures
{
    QVector<double> vsTruth;
    QVector<double> vsNewest;
    bool consistencyChecked = false; ///< false: the model has no standard parameters
    /// The ParameterInfo::group of every link that is no real body and every joint with a
    /// negative friction or rotor inertia, in the newest estimate.
    QStringList inconsistentGroups;
    /// The group of every link that is a real body but not a plausible one (Plausibility.h): a
    /// point mass, needle or plate, or its centre of mass outside its bounding volume.
    QStringList implausibleGroups;
    QStringList consistencyLines; ///< EstimateConsistency::describe() of the newest estimate
};

EstimateFigures estimateFigures(const RobotModel &model, const JointTrajectory &path,
                                const QVector<Eigen::VectorXd> &estimates,
                                const std::optional<Eigen::VectorXd> &truth);

} // namespace learnid

Q_DECLARE_METATYPE(learnid::EstimateFigures)
