#pragma once

#include "io/ParameterFile.h"
#include "io/UrdfExport.h"
#include "model/ChainModel.h"

#include <Eigen/Core>
#include <QStringList>
#include <optional>
#include <vector>

namespace learnid {

/// Where a standard parameter's value came from (docs/identify.md, "What the export says"):
/// determined by the data (share >= 0.5, LogFit::standardDetermined), kept from the prior, or not
/// known (no share, e.g. a session estimate without a path).
enum class ParameterOrigin { Data, Prior, Unknown };

/// The origin of standard parameter i for the shares `determined` (empty: unknown for all).
ParameterOrigin parameterOrigin(const std::vector<double> &determined, int i);

/// The origin in words, translated, for tables ("data", "undetermined (kept near the prior)",
/// "?"). The parameter file keeps its schema's "prior" (ParameterFile.h).
QString parameterOriginText(ParameterOrigin origin);

/// Each joint's terms of standard vector pi (ChainModel's layout) as the URDF holds them:
/// viscous and Coulomb friction in <dynamics>, armature and offset in learnid's element; 0 for a
/// term the model leaves out.
std::vector<IdentifiedJoint> urdfJointTerms(const ChainModel &model, const Eigen::VectorXd &pi);

/// The URDF comment block on what the data determined: a heading, then per link and joint one
/// line per standard parameter (name, value, unit, share, "data" or "undetermined"). English, as
/// the file's other comments. Empty when determined is empty.
QStringList determinedNotes(const ChainModel &model, const Eigen::VectorXd &pi,
                            const std::vector<double> &determined);

/// Puts the whole model into a parameter file's standard section: the model's standard
/// parameters' names and units, pi, and the shares (empty: unknown).
void setStandardParameters(ParameterFileContent &content, const ChainModel &model,
                           const Eigen::VectorXd &pi, const std::vector<double> &determined);

/// The part of a parameter file every identification from logs fills alike: the robot model's
/// id and description, the controller (when given), joint j on node j + 1, the time and tool
/// version, the law whose zero-phase filter prepares the logs ("improved"), and the model's
/// parameter names.
ParameterFileContent logFileHeader(const ChainModel &model, const QString &robotModel,
                                   const QString &description,
                                   const std::optional<ControllerSettings> &controller);

} // namespace learnid
