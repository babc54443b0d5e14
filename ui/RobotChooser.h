#pragma once

#include "model/RobotModel.h"
#include "types/ChainSettings.h"

#include <QGroupBox>
#include <memory>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace learnid {

/// The robot the scenario is for, chosen before any motion: the paper's arm, a built-in URDF
/// robot or a URDF file; then what the model is: its joints with their type, limits and
/// effort, each link's mass, the friction terms on, and how many base parameters the trials
/// learn. Choosing another robot emits robotChosen(); the form then starts from that robot's
/// default scenario.
class RobotChooser : public QGroupBox
{
    Q_OBJECT

public:
    explicit RobotChooser(QWidget *parent = nullptr);

    /// Shows the scenario's robot (no signal). model: the model made from it, or null with
    /// error saying why it cannot be made.
    void showRobot(const QString &modelId, const UrdfRobotSettings &urdf,
                   const std::shared_ptr<const RobotModel> &model, const QString &error);
    /// As if the technician chose this URDF file in the dialog.
    void chooseUrdfFile(const QString &path);
    void setEditable(bool editable);

    QComboBox *modelBox() const { return m_model; }
    QTableWidget *jointTable() const { return m_joints; }
    /// The summary line, e.g. "7 revolute joints, 16.06 kg; 57 base parameters (of 84)".
    QString summaryText() const;

signals:
    void robotChosen(const QString &modelId, const learnid::UrdfRobotSettings &urdf);

private:
    void onModelActivated(int index);
    void showModel(const RobotModel &model);

    QComboBox *m_model;
    QPushButton *m_openUrdf;
    QLabel *m_file;
    QLabel *m_summary;
    QTableWidget *m_joints;
    UrdfRobotSettings m_urdf;
};

} // namespace learnid
