#include "ui/RobotPanel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QIcon>
#include <QLabel>
#include <QPushButton>
#include <QStandardItemModel>

namespace learnid {

RobotPanel::RobotPanel(QWidget *parent)
    : QWidget(parent)
    , m_kind(new QComboBox(this))
    , m_connect(new QPushButton(QIcon(QStringLiteral(":/icons/connect.svg")), tr("Connect"), this))
    , m_state(new QLabel(this))
{
    m_kind->setObjectName(QStringLiteral("robotKind"));
    m_connect->setObjectName(QStringLiteral("connectButton"));
    m_kind->addItem(tr("Simulated (paper 2-link arm)"), int(RobotKind::Simulated));
    m_kind->addItem(tr("CAN (CANopen / CiA 402)"), int(RobotKind::Can));
    if (auto *model = qobject_cast<QStandardItemModel *>(m_kind->model()))
        model->item(1)->setEnabled(false);
    const QString canHint = tr("available when the CAN link lands");
    m_kind->setItemData(1, canHint, Qt::ToolTipRole);
    m_kind->setToolTip(tr("Simulated robot; CAN: %1").arg(canHint));

    auto *layout = new QFormLayout(this);
    layout->addRow(tr("Robot:"), m_kind);
    layout->addRow(QString(), m_connect);
    layout->addRow(tr("State:"), m_state);
    setConnected(false, tr("not connected"));

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

void RobotPanel::setConnected(bool connected, const QString &state)
{
    m_connected = connected;
    m_connect->setText(connected ? tr("Disconnect") : tr("Connect"));
    m_kind->setEnabled(!connected);
    m_state->setText(state);
}

void RobotPanel::setBusy(bool busy)
{
    m_connect->setEnabled(!busy);
}

} // namespace learnid
