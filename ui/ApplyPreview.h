#pragma once

#include "model/RobotModel.h"

#include <Eigen/Core>
#include <QList>
#include <QString>
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

/// A parameter set in one line, as the window and the report name what the robot holds: the
/// values, or for an n-joint arm's dozens of them how many there are (the Parameters table
/// lists them).
QString parameterSetText(const Eigen::VectorXd &values);

} // namespace learnid
