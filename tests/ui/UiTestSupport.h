#pragma once

#include "ui/MainWindow.h"

#include <QAbstractButton>
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
};

} // namespace learnid::test
