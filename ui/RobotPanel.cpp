#include "ui/RobotPanel.h"

#include <QCanBus>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QIcon>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace learnid {

RobotPanel::RobotPanel(QWidget *parent)
    : QWidget(parent)
    , m_kind(new QComboBox(this))
    , m_canFields(new QWidget(this))
    , m_plugin(new QComboBox(m_canFields))
    , m_interface(new QLineEdit(QStringLiteral("can0"), m_canFields))
    , m_nodes(new QLineEdit(QStringLiteral("1,2"), m_canFields))
    , m_syncTimeout(new QSpinBox(m_canFields))
    , m_commission(new QCheckBox(
          tr("First commissioning: I confirmed each node's joint on the arm"), m_canFields))
    , m_connect(new QPushButton(QIcon(QStringLiteral(":/icons/connect.svg")), tr("Connect"), this))
    , m_state(new QLabel(this))
{
    m_kind->setObjectName(QStringLiteral("robotKind"));
    m_plugin->setObjectName(QStringLiteral("canPlugin"));
    m_interface->setObjectName(QStringLiteral("canInterface"));
    m_nodes->setObjectName(QStringLiteral("canNodes"));
    m_syncTimeout->setObjectName(QStringLiteral("canSyncTimeout"));
    m_commission->setObjectName(QStringLiteral("canCommission"));
    m_connect->setObjectName(QStringLiteral("connectButton"));
    m_kind->addItem(tr("Simulated (the scenario's robot)"), int(RobotKind::Simulated));
    m_kind->addItem(tr("CAN (CANopen / CiA 402)"), int(RobotKind::Can));
    m_plugin->addItems(QCanBus::instance()->plugins());
    m_plugin->setCurrentText(QStringLiteral("socketcan"));
    m_plugin->setToolTip(tr("QCanBus plugin: socketcan for a CAN adapter on Linux; virtualcan "
                            "to try learnid-robot-sim first"));
    m_interface->setToolTip(tr("e.g. can0 (socketcan) or tcp://127.0.0.1:35468/can0 (virtualcan)"));
    m_nodes->setToolTip(tr("CANopen node id of joint 1, 2, ... (docs/can-protocol.md)"));
    m_syncTimeout->setRange(0, 60000);
    m_syncTimeout->setValue(0);
    m_syncTimeout->setSpecialValueText(tr("10 SYNC periods, at least 50 ms"));
    m_syncTimeout->setSuffix(tr(" ms"));
    m_syncTimeout->setToolTip(tr("A trial stops when no SYNC arrives for this long"));
    m_commission->setToolTip(
        tr("Only for drives never commissioned (or taken from another robot): tick it after "
           "checking on the arm that the drive of each node (its serial number on the type "
           "plate) moves the joint the node is listed for. Apply then stores the joint identity "
           "in the drives, and later sessions check it without this (docs/can-protocol.md 2.4)."));

    auto *can = new QFormLayout(m_canFields);
    can->setContentsMargins(0, 0, 0, 0);
    can->addRow(tr("Plugin:"), m_plugin);
    can->addRow(tr("Interface:"), m_interface);
    can->addRow(tr("Nodes:"), m_nodes);
    can->addRow(tr("SYNC timeout:"), m_syncTimeout);
    can->addRow(tr("Drives:"), m_commission);

    auto *layout = new QFormLayout(this);
    layout->addRow(tr("Robot:"), m_kind);
    layout->addRow(m_canFields);
    layout->addRow(QString(), m_connect);
    layout->addRow(tr("State:"), m_state);
    setConnected(false, tr("not connected"));
    updateCanFields();

    connect(m_kind, &QComboBox::currentIndexChanged, this, &RobotPanel::updateCanFields);
    connect(m_connect, &QPushButton::clicked, this, [this] {
        if (m_connected)
            emit disconnectRequested();
        else
            emit connectRequested(robotKind());
    });
}

RobotPanel::RobotKind RobotPanel::robotKind() const
{
    return RobotKind(m_kind->currentData().toInt());
}

void RobotPanel::setJointCount(int joints)
{
    QString why;
    const QList<int> nodes = parseNodeList(m_nodes->text(), &why);
    for (int i = 0; i < nodes.size(); ++i)
        if (nodes.at(i) != i + 1)
            return; // the technician's own list stays
    QStringList ids;
    for (int j = 1; j <= joints; ++j)
        ids << QString::number(j);
    m_nodes->setText(ids.join(QLatin1Char(',')));
}

std::optional<RobotRequest> RobotPanel::choice(QString *error, double samplePeriod,
                                               int joints) const
{
    RobotRequest c;
    if (robotKind() != RobotKind::Can)
        return c;
    c.kind = RobotRequest::Kind::Can;
    c.can.plugin = m_plugin->currentText();
    c.can.interface = m_interface->text().trimmed();
    setSyncPeriod(c.can, samplePeriod);
    setSyncTimeoutMs(c.can, m_syncTimeout->value());
    c.can.commissioning = m_commission->isChecked();
    QString why;
    c.can.nodes = parseNodeList(m_nodes->text(), &why);
    if (c.can.nodes.isEmpty())
        *error = tr("CAN nodes: %1").arg(why);
    else if (joints > 0 && c.can.nodes.size() != joints)
        *error = tr("CAN nodes: %1 node ids for a robot of %2 joints: one node per joint")
                     .arg(c.can.nodes.size())
                     .arg(joints);
    else if (c.can.interface.isEmpty())
        *error = tr("CAN interface: enter one, e.g. can0");
    else
        *error = canRobotOptionsError(c.can);
    if (!error->isEmpty())
        return std::nullopt;
    return c;
}

void RobotPanel::updateCanFields()
{
    m_canFields->setVisible(robotKind() == RobotKind::Can);
}

void RobotPanel::setConnected(bool connected, const QString &state)
{
    m_connected = connected;
    m_connect->setText(connected ? tr("Disconnect") : tr("Connect"));
    m_kind->setEnabled(!connected);
    m_canFields->setEnabled(!connected);
    m_state->setText(state);
}

void RobotPanel::setBusy(bool busy)
{
    m_connect->setEnabled(!busy);
}

} // namespace learnid
