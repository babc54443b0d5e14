#pragma once

#include "model/RobotModel.h"

#include <QStringList>
#include <memory>

namespace learnid {

/// Ids of the models makeRobotModel() knows, for validation messages.
QStringList knownRobotModels();

/// The model with this id, or nullptr when the id is unknown.
std::shared_ptr<const RobotModel> makeRobotModel(const QString &id);

} // namespace learnid
