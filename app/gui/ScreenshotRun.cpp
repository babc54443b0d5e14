#include "ScreenshotRun.h"

#include "ui/MainActions.h"
#include "ui/MainWindow.h"
#include "ui/TrackingErrorPlot.h"
#include "ui/RobotPanel.h"
#include "ui/SessionController.h"

#include <QAction>
#include <QApplication>
#include <QPushButton>
#include <QTimer>
#include <cstdio>

namespace learnid {

ScreenshotRun::ScreenshotRun(MainWindow *window, QString path)
    : QObject(window)
    , m_window(window)
    , m_path(std::move(path))
{}

void ScreenshotRun::start()
{
    SessionController *c = m_window->controller();
    m_window->setApplyConfirmation([](const ApplyPreview &) { return true; });
    // stateChanged reaches the window first, so the actions are enabled when this runs.
    connect(c, &SessionController::stateChanged, this, [this, c] {
        if (!m_started && c->canRun() && c->history().isEmpty()) {
            m_started = true;
            m_window->actions()->runAll->trigger();
        }
    });
    connect(c, &SessionController::runFinished, this, [this, c](bool all) {
        if (!all)
            return finish(QStringLiteral("the simulated session did not complete"));
        c->accept(int(c->estimates().size()) - 1);
    });
    connect(c, &SessionController::acceptedChanged, this, [this, c] { c->apply(); });
    connect(c, &SessionController::applied, this, [this] {
        // Let the views lay out the final data before grabbing.
        m_window->plot()->setSelectedTrial(-1); // all trials overlaid, like the paper's figures
        QTimer::singleShot(300, this, [this] {
            const bool ok = m_window->grab().save(m_path, "PNG");
            finish(ok ? QString() : QStringLiteral("cannot write %1").arg(m_path));
        });
    });
    connect(c, &SessionController::openFailed, this, [this](const QString &e) { finish(e); });
    QTimer::singleShot(180000, this, [this] { finish(QStringLiteral("timed out")); });
    m_window->show();
    m_window->robotPanel()->connectButton()->click();
}

void ScreenshotRun::finish(const QString &error)
{
    if (m_done)
        return;
    m_done = true;
    if (!error.isEmpty())
        std::fprintf(stderr, "learnid: --screenshot: %s\n", qPrintable(error));
    QApplication::exit(error.isEmpty() ? 0 : 1);
}

} // namespace learnid
