#pragma once

#include "service/LogIdentification.h"

#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <vector>

namespace learnid {

/// The arm a payload is identified on, its model held fixed (docs/payload.md, "The arm's
/// model"): a URDF (one an earlier identification wrote with --urdf-out, or a CAD one) or a
/// parameter file an earlier identification wrote with --export.
struct PayloadArm
{
    /// The URDF read (kinematics; its values are the arm's when there is no parameter file) and
    /// its model; with a parameter file, the joint terms are the file's.
    LogRobot robot;
    Eigen::VectorXd standard; ///< the arm's standard parameters held fixed (ChainModel's layout)
    /// Per standard parameter the share the data determined, from the parameter file; empty
    /// without one.
    std::vector<double> determined;
    QString parameterFile; ///< the parameter file (native path), or empty
    /// Identified earlier: from a parameter file, or a URDF learnid wrote (its comment says so).
    /// A CAD model puts its errors into the payload's estimate; front ends warn.
    bool identified = false;
    QStringList notes; ///< things the reading left out, in words (e.g. a payload the file held)
};

/// True when `head` (the start of a file) is a JSON object, as a parameter file is; a URDF
/// starts with '<'.
bool looksLikeParameterFile(const QByteArray &head);

/// The arm of request.robot: a built-in URDF robot or a URDF file (loadLogRobot(), the URDF's
/// values), or a parameter file (readParameterFile()) whose standardParameters are held fixed on
/// the URDF its robot.model names: a built-in robot's own, or for "urdf" armUrdf (the URDF it
/// was identified on; armUrdfName names that input in messages). The joint terms are the file's
/// (request.terms is not used then), the base and tip links request's. Throws Error naming the
/// file and key: a file without standardParameters, robot.model "urdf" without armUrdf, a URDF
/// whose model has other standard parameters than the file (another robot, other base or tip
/// links), a payload section whose link is not one of its moving links.
PayloadArm loadPayloadArm(const LogIdentificationRequest &request, const QString &armUrdf,
                          const QString &armUrdfName);

} // namespace learnid
