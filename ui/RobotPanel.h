#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;

namespace learnid {

/// Robot choice and connection: Simulated (the default) or CAN (shown, not yet available).
class RobotPanel : public QWidget
{
    Q_OBJECT

public:
    enum class RobotKind { Simulated, Can };

    explicit RobotPanel(QWidget *parent = nullptr);

    RobotKind robotKind() const;
    /// connected: the button offers Disconnect; state: one line such as "simulated paper-2link".
    void setConnected(bool connected, const QString &state);
    void setBusy(bool busy);

    QPushButton *connectButton() const { return m_connect; }

signals:
    void connectRequested(learnid::RobotPanel::RobotKind kind);
    void disconnectRequested();

private:
    QComboBox *m_kind;
    QPushButton *m_connect;
    QLabel *m_state;
    bool m_connected = false;
};

} // namespace learnid
