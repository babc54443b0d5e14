#pragma once

#include <QObject>
#include <QString>

namespace learnid {

class MainWindow;

/// `learnid --screenshot FILE.png`: connects the simulated robot, runs the scenario's trials,
/// accepts and applies the last estimate, saves the window as PNG and quits the application
/// (exit code 0, or 1 with a message on stderr).
class ScreenshotRun : public QObject
{
    Q_OBJECT

public:
    ScreenshotRun(MainWindow *window, QString path);
    void start();

private:
    void finish(const QString &error);

    MainWindow *m_window;
    QString m_path;
    bool m_started = false;
    bool m_done = false;
};

} // namespace learnid
