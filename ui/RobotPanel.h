#pragma once

#include "service/RobotRequest.h"

#include <QWidget>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QWidget;

namespace learnid {

/// Robot choice and connection: Simulated (the default) or CAN (plugin, interface, the node
/// of each joint, the SYNC timeout, first commissioning: learnid-cli's --commission), the
/// Connect button and the robot's state.
class RobotPanel : public QWidget
{
    Q_OBJECT

public:
    enum class RobotKind { Simulated, Can };

    explicit RobotPanel(QWidget *parent = nullptr);

    RobotKind robotKind() const;
    /// The chosen robot, or nullopt with error saying which CAN setting is wrong.
    /// samplePeriod: the scenario's controller period, the SYNC period the bus load is checked
    /// at; joints: the robot's, one node each (0: not checked).
    std::optional<RobotRequest> choice(QString *error, double samplePeriod = 0.002,
                                       int joints = 0) const;
    /// Offers nodes 1..joints while the node field still holds a default list 1..k.
    void setJointCount(int joints);
    /// connected: the button offers Disconnect; state: one line such as "simulated paper-2link".
    void setConnected(bool connected, const QString &state);
    void setBusy(bool busy);

    QPushButton *connectButton() const { return m_connect; }

signals:
    void connectRequested(learnid::RobotPanel::RobotKind kind);
    void disconnectRequested();

private:
    void updateCanFields();

    QComboBox *m_kind;
    QWidget *m_canFields;
    QComboBox *m_plugin;
    QLineEdit *m_interface;
    QLineEdit *m_nodes;
    QSpinBox *m_syncTimeout;
    QCheckBox *m_commission;
    QPushButton *m_connect;
    QLabel *m_state;
    bool m_connected = false;
};

} // namespace learnid
