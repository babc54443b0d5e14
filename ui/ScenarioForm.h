#pragma once

#include "model/RobotModel.h"
#include "types/Scenario.h"
#include "ui/ScenarioFields.h"

#include <QWidget>
#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;

namespace learnid {

class RobotChooser;
class WaypointEditor;

/// The scenario as a form: the robot (RobotChooser; choosing one starts from its default
/// scenario, scenarioForRobot()), the path (the paper's line, or joint waypoints checked
/// against the robot's joint limits as they are typed), torque limits and planning fraction, gains
/// with lambda, rho, the estimator law, the number of trials and the initial parameters. Every edit
/// is parsed and validated at once (validateScenario()); the reason a value is refused is shown
/// next to its field. Settings the form does not show are kept from the last setScenario().
class ScenarioForm : public QWidget
{
    Q_OBJECT

public:
    explicit ScenarioForm(QWidget *parent = nullptr);

    void setScenario(const Scenario &scenario);
    /// The edited scenario, or nullopt while a field is refused.
    std::optional<Scenario> scenario() const
    {
        return m_valid ? std::optional(m_current) : std::nullopt;
    }
    bool isValid() const { return m_valid; }
    /// The first refused field's key and reason ("controller.lambda: must be positive"), or "".
    QString firstError() const { return m_firstError; }
    /// The reason shown next to a field (key as in the scenario file), "" when it is accepted.
    QString reasonFor(const QString &key) const;
    /// Names parameters in the label of the initial parameters, e.g. {"a", "b", "c"}.
    void setParameterNames(const QStringList &names);
    void setEditable(bool editable);
    RobotChooser *robotChooser() const { return m_robot; }
    WaypointEditor *waypointEditor() const { return m_waypoints; }
    /// A URDF robot's path from a recorded joint path (PathCsv.h), as the technician chose it
    /// with "Path CSV..."; a file it cannot use is refused naming line and column.
    void usePathFile(const QString &path);
    /// Back from a path file to the waypoint table.
    void useWaypoints();
    /// The robot model of the scenario shown (null when it cannot be made).
    std::shared_ptr<const RobotModel> model() const { return m_model; }

signals:
    /// After every edit; scenario() holds the result when valid.
    void edited(bool valid);

private:
    struct Row
    {
        ScenarioField field;
        QLineEdit *edit = nullptr;
        QLabel *label = nullptr;
        QLabel *reason = nullptr;
        QLabel *unit = nullptr;
    };

    void revalidate();
    void chooseRobot(const QString &modelId, const UrdfRobotSettings &urdf);
    void updatePathRows();
    void showReason(Row &row, const QString &reason);

    QList<Row> m_rows;
    QComboBox *m_law;
    QComboBox *m_sensor; ///< estimator.jointTorqueSensor
    RobotChooser *m_robot;
    WaypointEditor *m_waypoints;
    std::shared_ptr<const RobotModel> m_model;
    QString m_modelError;
    QLabel *m_otherError;
    Scenario m_base;
    Scenario m_current;
    bool m_valid = true;
    QString m_firstError;
};

} // namespace learnid
