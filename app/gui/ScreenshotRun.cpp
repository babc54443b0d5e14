#include "ScreenshotRun.h"

#include "service/SessionController.h"
#include "ui/ApplyConfirmDialog.h"
#include "ui/ApplyPreview.h"
#include "ui/MainActions.h"
#include "ui/MainWindow.h"
#include "ui/MessageBar.h"
#include "ui/PayloadDialog.h"
#include "ui/RecordedDataDialog.h"
#include "ui/RobotChooser.h"
#include "ui/RobotPanel.h"
#include "ui/ScenarioForm.h"
#include "ui/TrackingErrorPlot.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QPushButton>
#include <QTabWidget>
#include <QTimer>
#include <cstdio>

namespace learnid {

namespace {

const QStringList kViewNames = {QStringLiteral("main"),          QStringLiteral("apply-dialog"),
                                QStringLiteral("refused-check"), QStringLiteral("recorded-data"),
                                QStringLiteral("seven-axis"),    QStringLiteral("payload")};

} // namespace

ScreenshotRun::ScreenshotRun(MainWindow *window, QString path, View view)
    : QObject(window)
    , m_window(window)
    , m_path(std::move(path))
    , m_view(view)
{}

std::optional<ScreenshotRun::View> ScreenshotRun::viewNamed(const QString &name)
{
    const int i = int(kViewNames.indexOf(name));
    return i < 0 ? std::nullopt : std::optional<View>(View(i));
}

QStringList ScreenshotRun::viewNames()
{
    return kViewNames;
}

void ScreenshotRun::start()
{
    if (m_view == View::RecordedData)
        return startRecordedData();
    if (m_view == View::Payload)
        return startPayload();
    SessionController *c = m_window->controller();
    m_window->setApplyConfirmation(
        [this](const ApplyPreview &preview) { return confirmByScreenshot(preview); });
    if (m_view == View::SevenAxis) {
        // The built-in 7-axis arm with its default scenario, as chosen in the robot box.
        QComboBox *box = m_window->form()->robotChooser()->modelBox();
        const int i = box->findData(QStringLiteral("panda"));
        box->setCurrentIndex(i);
        emit box->activated(i);
    }
    if (m_view == View::RefusedCheck) {
        // The paper's derivative filter: stable for the initial estimate, not for the truth.
        if (auto s = m_window->form()->scenario()) {
            s->controller.lambda = 40.0;
            m_window->form()->setScenario(*s);
        }
    }
    // stateChanged reaches the window first, so the actions are enabled when this runs.
    connect(c, &SessionController::stateChanged, this, [this, c] {
        if (!m_started && c->canRun() && c->history().isEmpty()) {
            m_started = true;
            m_window->actions()->runAll->trigger();
        }
    });
    connect(c, &SessionController::runFinished, this, [this, c](bool all) {
        if (m_view == View::RefusedCheck) {
            if (all || c->history().isEmpty() ||
                c->history().constLast().status() != TrialStatus::Refused)
                return finish(QStringLiteral("the pre-trial check refused no trial"));
            return grabWindowLater();
        }
        if (!all)
            return finish(QStringLiteral("the simulated session did not complete"));
        c->accept(int(c->estimates().size()) - 1);
    });
    connect(c, &SessionController::acceptedChanged, this, [this] {
        // The window's Apply action, so the confirmation (the dialog view) is asked for.
        QTimer::singleShot(0, this, [this] {
            QAction *apply = m_window->actions()->apply;
            if (!apply->isEnabled())
                return finish(QStringLiteral("Apply is not enabled after Accept"));
            apply->trigger();
        });
    });
    connect(c, &SessionController::applied, this, [this] { grabWindowLater(); });
    connect(c, &SessionController::openFailed, this, [this](const QString &e) { finish(e); });
    QTimer::singleShot(180000, this, [this] { finish(QStringLiteral("timed out")); });
    m_window->show();
    m_window->robotPanel()->connectButton()->click();
}

void ScreenshotRun::startRecordedData()
{
    const QDir data(qEnvironmentVariable("LEARNID_DATA"));
    const QString urdf = data.filePath(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (qEnvironmentVariableIsEmpty("LEARNID_DATA") || !QFileInfo::exists(urdf)) {
        // After exec() has started: exit() before it would be lost.
        QTimer::singleShot(0, this, [this] {
            finish(QStringLiteral("set LEARNID_DATA to the folder of the recorded robot data "
                                  "(with kuka-lwr4/)"));
        });
        return;
    }
    m_window->show();
    m_window->actions()->identifyFromLogs->trigger();
    RecordedDataDialog *dialog = m_window->recordedDataDialog();
    dialog->resize(1440, 940); // the picture's size, whatever the screen's
    const auto log = [&data](int run) {
        return data.filePath(QStringLiteral("kuka-lwr4/measurements_%1.csv").arg(run));
    };
    dialog->form()->setRobot(urdf);
    dialog->form()->setTrainingLogs({log(1), log(2)});
    dialog->form()->setValidationLogs({log(3)});
    connect(dialog, &RecordedDataDialog::identificationFinished, this, [this, dialog](bool ok) {
        if (!ok)
            return finish(dialog->messageBar()->text());
        // Let the table and the plots lay out the result before grabbing.
        QTimer::singleShot(300, this, [this, dialog] {
            const bool saved = dialog->grab().save(m_path, "PNG");
            finish(saved ? QString() : QStringLiteral("cannot write %1").arg(m_path));
        });
    });
    QTimer::singleShot(180000, this, [this] { finish(QStringLiteral("timed out")); });
    dialog->identify();
}

void ScreenshotRun::startPayload()
{
    PayloadDialog *dialog = m_window->payloadDialog(); // opened by --scenario with a payload
    if (!dialog) {
        QTimer::singleShot(0, this, [this] {
            finish(QStringLiteral("give --scenario FILE with a payload section"));
        });
        return;
    }
    dialog->resize(1280, 860);
    connect(dialog, &PayloadDialog::runFinished, this, [this, dialog](bool ok) {
        if (!ok)
            return finish(dialog->messageBar()->text());
        QTimer::singleShot(300, this, [this, dialog] {
            const bool saved = dialog->grab().save(m_path, "PNG");
            finish(saved ? QString() : QStringLiteral("cannot write %1").arg(m_path));
        });
    });
    QTimer::singleShot(180000, this, [this] { finish(QStringLiteral("timed out")); });
    // After the preview of what the path sees is shown.
    connect(dialog, &PayloadDialog::previewShown, this, [dialog](bool) {
        if (!dialog->isRunning() && !dialog->result())
            dialog->run();
    });
}

void ScreenshotRun::grabWindowLater()
{
    m_window->plot()->setSelectedTrial(-1); // all trials overlaid, like the paper's figures
    if (m_view == View::SevenAxis) {        // what is new for n joints: the parameters as rows
        if (auto *tabs = m_window->findChild<QTabWidget *>(QStringLiteral("convergenceTabs")))
            tabs->setCurrentIndex(1);
    }
    // Let the views lay out the final data before grabbing.
    QTimer::singleShot(300, this, [this] {
        const bool ok = m_window->grab().save(m_path, "PNG");
        finish(ok ? QString() : QStringLiteral("cannot write %1").arg(m_path));
    });
}

bool ScreenshotRun::confirmByScreenshot(const ApplyPreview &preview)
{
    if (m_view != View::ApplyDialog)
        return true;
    ApplyConfirmDialog dialog(preview, m_window);
    dialog.show();
    const bool ok = dialog.grab().save(m_path, "PNG");
    finish(ok ? QString() : QStringLiteral("cannot write %1").arg(m_path));
    return false; // the dialog view applies nothing
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
