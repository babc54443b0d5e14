#pragma once

#include "can/SdoWrite.h"
#include "io/ParameterFilePayload.h"

#include "model/RobotModel.h"
#include "types/ControllerSettings.h"
#include "types/DriveIdentity.h"

#include <Eigen/Core>
#include <QByteArray>
#include <QDateTime>
#include <QJsonObject>
#include <QList>
#include <QString>
#include <optional>
#include <vector>

namespace learnid {

/// The "schema" of parameter files this version writes; it reads these and
/// parameterFileSchemaV1's (docs/file-formats.md).
inline constexpr char parameterFileSchema[] = "learnid-parameters/2";
/// The first version: always controller gains, no standard parameters.
inline constexpr char parameterFileSchemaV1[] = "learnid-parameters/1";

/// Everything a parameter file holds (docs/file-formats.md), filled by the caller.
struct ParameterFileContent
{
    QString robotModel;       ///< model id, e.g. "paper-2link"
    QString robotDescription; ///< the robot in words (simulated, CAN interface and nodes)
    QList<int> jointNodes;    ///< CANopen node of each joint's drive; empty means 1, 2, ...
    /// The identity (0x1018) of each joint's drive when the robot is on CAN, else empty
    /// (written as robot.drives only when there are some).
    QList<DriveIdentity> drives;
    /// false: the file records no controller gains ("controller": null), as an identification
    /// from logs without a scenario writes it; jointNodes then give the joint count.
    bool hasController = true;
    ControllerSettings controller; ///< the gains the parameters were identified with
    QDateTime created;             ///< stored in UTC to the millisecond
    QString toolVersion;           ///< LEARNID_VERSION of the writer
    QString law;                   ///< learning law id
    int sourceTrial = -1; ///< trial whose data gave the accepted estimate; -1 = not recorded
    QList<ParameterInfo> parameters; ///< names and units, as the model lists them (m)
    Eigen::VectorXd values;          ///< the accepted estimate (m), finite
    /// Estimated standard deviation per parameter (m), +inf for one the path does not observe
    /// (written as null); empty when not available.
    Eigen::VectorXd standardDeviations;
    Eigen::VectorXd maxTrackingErrorDeg; ///< per joint [deg] (n), or empty
    Eigen::VectorXd rmsTrackingErrorDeg; ///< per joint [deg] (n), or empty
    Eigen::VectorXd residualRms;         ///< per joint [N m] (n), or empty
    double condition = 0.0;              ///< cond(W^T W), columns scaled; +inf when rank deficient
    int rank = 0;                        ///< observable directions of the fit (0..m)
    QList<SdoWrite> canWrites;           ///< the exact writes "apply" performs, in order
    /// The whole model as standard parameters (URDF robots, ChainModel's layout: 10 per link,
    /// then each joint's terms, offsets included); empty when not recorded.
    QList<ParameterInfo> standardParameters;
    Eigen::VectorXd standardValues; ///< one per standardParameters entry, finite
    /// Per standard parameter the share of its direction the data determined (0..1; at least
    /// 0.5: determined by the data, below: kept from the prior); NaN where not known. Empty:
    /// not known for any.
    std::vector<double> standardDetermined;
    /// A payload fixed to a link of the arm, not part of the arm's parameters above (version 2,
    /// optional; ParameterFilePayload.h); none: the file holds the arm alone.
    std::optional<ParameterFilePayload> payload;

    /// jointNodes, or 1..n when it is empty.
    QList<int> nodes() const;
    /// The joint count: the controller's, or the nodes' when there is no controller.
    int dof() const;
};

/// Checks the content against its model: known model and law, one name/value (and standard
/// deviation, if any) per model parameter with the model's names, one figure per joint, finite
/// values, node ids 1..127. Throws Error "<key path>: <problem>" with the key paths of the JSON
/// form, e.g. "parameters[1].value: must be a finite number, got nan".
void validateParameterFileContent(const ParameterFileContent &content);

/// The parameter file: indented JSON in the documented key order, with "schema" and a
/// "checksum" (parameterFileChecksum()). Validates first; throws Error naming the key.
QByteArray parameterFileToJson(const ParameterFileContent &content);

/// Reads and checks a parameter file (schema 2, or 1 as older learnid versions wrote it): schema,
/// checksum, every key present with the right type (standardDeviation of all parameters or of
/// none), no unknown keys, then validateParameterFileContent(). Throws Error
/// "<sourceName>: <key path>: <problem>".
ParameterFileContent parameterFileFromJson(const QByteArray &json, const QString &sourceName);

/// readFile() then parameterFileFromJson() with the path as the source name.
ParameterFileContent readParameterFile(const QString &path);

/// Lower-case hex SHA-256 of QJsonDocument(object).toJson(QJsonDocument::Compact), where object
/// is the file's top-level object without its "checksum" key (docs/file-formats.md).
QByteArray parameterFileChecksum(const QJsonObject &withoutChecksum);

/// The CiA 306 DCF fragment for the drive of one joint (0-based): [DeviceComissioning] NodeID,
/// [ManufacturerObjects], object 0x2100 (the joint's gains kp, ki, kd, lambda as REAL32; only
/// when the file records a controller) and object 0x2200 (all identified parameters as REAL32,
/// sub0 = their count).
QByteArray parameterDcfFragment(const ParameterFileContent &content, int joint);

/// The fragments of all joints, one after another, each starting with its comment lines and
/// [DeviceComissioning]; split there to get one node's fragment (docs/file-formats.md).
QByteArray parameterDcfFragment(const ParameterFileContent &content);

} // namespace learnid
