#pragma once

#include <QString>

class QAction;
class QToolButton;
class QWidget;

namespace learnid {

/// A panel button showing an action (icon and text), named for tests, sized alike in every panel.
QToolButton *actionButton(QAction *action, const QString &objectName, QWidget *parent);

} // namespace learnid
