#pragma once

#include "ui/MainWindow.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QLineEdit>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>
#include <memory>

namespace learnid::test {

/// A main window with settings of its own in a temporary folder, shown offscreen.
struct WindowFixture
{
    QTemporaryDir dir;
    std::unique_ptr<QSettings> settings;
    std::unique_ptr<MainWindow> window;

    WindowFixture()
        : settings(std::make_unique<QSettings>(dir.filePath(QStringLiteral("learnid.ini")),
                                               QSettings::IniFormat))
        , window(std::make_unique<MainWindow>(settings.get()))
    {
        window->show();
    }

    template <typename T = QAbstractButton> T *button(const char *name) const
    {
        return window->findChild<T *>(QLatin1String(name));
    }

    /// Clicks a button by object name (it must be enabled).
    bool click(const char *name) const
    {
        QAbstractButton *b = button(name);
        if (!b || !b->isEnabled())
            return false;
        QTest::mouseClick(b, Qt::LeftButton);
        return true;
    }

    /// The robot panel set to a CAN robot on plugin/interface with the node list.
    void chooseCan(const QString &plugin, const QString &interface, const QString &nodes) const
    {
        auto *kind = window->findChild<QComboBox *>(QStringLiteral("robotKind"));
        kind->setCurrentIndex(kind->findData(1));
        window->findChild<QComboBox *>(QStringLiteral("canPlugin"))->setCurrentText(plugin);
        window->findChild<QLineEdit *>(QStringLiteral("canInterface"))->setText(interface);
        window->findChild<QLineEdit *>(QStringLiteral("canNodes"))->setText(nodes);
    }
};

} // namespace learnid::test
