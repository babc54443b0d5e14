#pragma once

#include "model/RobotModel.h"
#include "types/ChainSettings.h"

#include <QStringList>
#include <memory>

namespace learnid {

/// Ids of the models makeRobotModel() knows, for validation messages: "paper-2link" (the
/// paper's arm in closed form), "urdf" (any serial arm from urdf.file) and the built-in URDF
/// robots ("paper-2link-urdf", "double-pendulum", "puma560", "panda"; resources/robots/).
QStringList knownRobotModels();

/// True for the models read from a URDF (every known model but "paper-2link").
bool isUrdfModel(const QString &id);

/// The URDF file a URDF model reads: urdf.file for "urdf", the built-in resource otherwise.
QString urdfFileOf(const QString &id, const UrdfRobotSettings &urdf);

/// The model with this id, or nullptr when the id is unknown. URDF models are built from urdf
/// (its file only for "urdf"; the built-ins use their own) and are cached: the same settings and
/// the same file contents give the same model object. Throws Error when the URDF cannot be
/// read or is not a serial arm (UrdfChain.h).
std::shared_ptr<const RobotModel> makeRobotModel(const QString &id,
                                                 const UrdfRobotSettings &urdf = {});

} // namespace learnid
