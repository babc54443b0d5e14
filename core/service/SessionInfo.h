#pragma once

#include "model/RobotModel.h"
#include "types/Scenario.h"

#include <Eigen/Core>
#include <QList>
#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVector>
#include <optional>

namespace learnid {

/// What the GUI knows about an opened session: a value copy made in the worker thread.
struct SessionInfo
{
    Scenario scenario;
    QString robotDescription;
    QString modelId;
    QList<ParameterInfo> parameters; ///< names and units of phi (m)
    int dof = 0;
    QStringList jointNames;               ///< the URDF's joint names, or "joint 1", ... (dof)
    std::optional<Eigen::VectorXd> truth; ///< simulated robot only
    Eigen::VectorXd storedParameters;     ///< what the robot controller holds (may be empty)
};

/// Registers the value types that travel between the worker and the GUI thread.
void registerSessionMetaTypes();

} // namespace learnid

Q_DECLARE_METATYPE(learnid::SessionInfo)
Q_DECLARE_METATYPE(QVector<Eigen::VectorXd>)
