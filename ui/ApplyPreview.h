#pragma once

#include "model/RobotModel.h"

#include <Eigen/Core>
#include <QList>
#include <optional>

namespace learnid {

/// What an apply would change on the robot: the set it holds now (empty before the first apply)
/// against the accepted estimate, parameter by parameter.
struct ApplyPreview
{
    int estimateIndex = 0;
    QList<ParameterInfo> parameters;
    Eigen::VectorXd oldValues; ///< may be empty
    Eigen::VectorXd newValues;

    /// (new - old) / |old| of parameter i, or nullopt when there is no old value or it is 0.
    std::optional<double> relativeChange(int i) const;
};

} // namespace learnid
