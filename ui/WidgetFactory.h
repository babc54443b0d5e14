#pragma once

#include <QString>

class QGroupBox;
class QPushButton;
class QWidget;

namespace learnid {

/// A push button with an object name, the handle tests and style sheets find it by.
QPushButton *namedButton(const QString &text, const char *objectName, QWidget *parent = nullptr);

/// A titled group box around one widget, with the window's margins.
QGroupBox *titledGroup(const QString &title, QWidget *content);

} // namespace learnid
