#include "ui/ActionButton.h"

#include <QAction>
#include <QToolButton>

namespace learnid {

QToolButton *actionButton(QAction *action, const QString &objectName, QWidget *parent)
{
    auto *b = new QToolButton(parent);
    b->setDefaultAction(action);
    b->setObjectName(objectName);
    b->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    b->setIconSize(QSize(20, 20));
    b->setMinimumHeight(32);
    b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    return b;
}

} // namespace learnid
