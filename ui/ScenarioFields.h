#pragma once

#include "types/Scenario.h"

#include <Eigen/Core>
#include <QList>
#include <QString>
#include <functional>
#include <optional>

namespace learnid {

/// One editable setting of the scenario form: its key path in the scenario file (which is also
/// how validateScenario() names it), label, unit and how it reads and writes a Scenario.
struct ScenarioField
{
    enum class Kind { Number, Integer, Vector };

    QString key;   ///< e.g. "controller.kp"; validation errors at "controller.kp[1]" belong here
    QString label; ///< translated
    QString unit;  ///< e.g. "N m/rad"; empty for dimensionless settings
    Kind kind = Kind::Number;
    std::function<Eigen::VectorXd(const Scenario &)> read;
    std::function<void(Scenario &, const Eigen::VectorXd &)> write;
    int expectedCount = 1;  ///< values a Number/Integer field takes; vectors: 0 = any
    double minimum = -1e15; ///< Integer: the range of the setting's type (written as is)
    double maximum = 1e15;
    bool lineOnly = false;        ///< shown for the paper's Cartesian line only
    bool emptyTakesRobot = false; ///< a URDF robot's vector left empty takes the robot's values
};

/// The settings of the form, grouped as the form shows them.
struct ScenarioFieldGroup
{
    QString title;
    QList<ScenarioField> fields;
};

QList<ScenarioFieldGroup> scenarioFieldGroups();

/// Parses "4500, 5000" or "4500 5000" (C locale numbers). error: why it is not a list of
/// finite numbers.
std::optional<Eigen::VectorXd> parseNumberList(const QString &text, QString *error);

/// The values as the form shows them: shortest exact form, separated by ", ".
QString formatNumberList(const Eigen::VectorXd &values);

/// True when a validation error at errorKey (e.g. "controller.kp[1]") concerns field key.
bool keyBelongsTo(const QString &errorKey, const QString &fieldKey);

} // namespace learnid
