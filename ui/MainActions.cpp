#include "ui/MainActions.h"

#include "ui/PlotImage.h"

#include <QAction>
#include <QActionGroup>
#include <QIcon>
#include <QMenu>
#include <QMenuBar>
#include <QToolBar>

namespace learnid {

namespace {

QAction *make(QObject *parent, const QString &icon, const QString &text, const QKeySequence &key,
              const QString &tip)
{
    auto *a = new QAction(text, parent);
    if (!icon.isEmpty())
        a->setIcon(QIcon(QStringLiteral(":/icons/%1.svg").arg(icon)));
    if (!key.isEmpty())
        a->setShortcut(key);
    a->setStatusTip(tip);
    a->setToolTip(key.isEmpty()
                      ? tip
                      : QStringLiteral("%1 (%2)").arg(tip, key.toString(QKeySequence::NativeText)));
    return a;
}

} // namespace

MainActions::MainActions(QObject *parent)
    : QObject(parent)
{
    connectRobot =
        make(this, QStringLiteral("connect"), tr("&Connect robot"), QKeySequence(tr("Ctrl+K")),
             tr("Connect to the chosen robot and plan the first trial"));
    newSession =
        make(this, QString(), tr("&New session"), QKeySequence::New,
             tr("Start a new session with the settings of the form (the history is discarded)"));
    identifyFromLogs =
        make(this, QString(), tr("Identify from recorded &data\u2026"), QKeySequence(),
             tr("Identify a robot's parameters from logs its controller recorded"));
    learnPayload = make(this, QString(), tr("Learn a &payload\u2026"), QKeySequence(),
                        tr("Learn the payload the robot carries with the arm's model held fixed "
                           "(simulated robot)"));
    openScenario = make(this, QStringLiteral("open"), tr("&Open scenario..."), QKeySequence::Open,
                        tr("Load a scenario file into the form"));
    saveScenario = make(this, QStringLiteral("save"), tr("&Save scenario..."), QKeySequence::Save,
                        tr("Save the form's scenario to a file"));
    exportParameters = make(this, QStringLiteral("export"), tr("Export &parameter file..."),
                            QKeySequence(tr("Ctrl+E")),
                            tr("Write the accepted estimate as a parameter file (JSON and DCF)"));
    exportUrdf = make(this, QString(), tr("Export identified &URDF..."), QKeySequence(),
                      tr("Write the robot's URDF with the accepted estimate as real bodies and "
                         "its friction (URDF robots)"));
    exportTrialCsv = make(this, QString(), tr("Export trial &CSV..."),
                          QKeySequence(tr("Ctrl+Shift+E")), tr("Write one CSV file per trial"));
    exportPlot =
        make(this, QString(), tr("Export p&lot..."), QKeySequence(tr("Ctrl+Shift+P")),
             svgExportAvailable() ? tr("Save the tracking-error plot as PNG or SVG")
                                  : tr("Save the tracking-error plot as PNG (SVG needs Qt6::Svg)"));
    exportReport = make(this, QStringLiteral("report"), tr("Export &report (PDF)..."),
                        QKeySequence::Print, tr("Write the one-page commissioning report"));
    quit = make(this, QString(), tr("&Quit"), QKeySequence::Quit, tr("Quit learnid"));
    runTrial = make(this, QStringLiteral("run"), tr("&Run trial"), QKeySequence(Qt::Key_F5),
                    tr("Run the next trial and learn from it"));
    runAll = make(this, QStringLiteral("run-all"), tr("Run &all"), QKeySequence(tr("Ctrl+F5")),
                  tr("Run the scenario's number of trials"));
    stop = make(this, QStringLiteral("stop"), tr("&Stop"), QKeySequence(tr("Shift+F5")),
                tr("Stop the running trial safely at the next sample"));
    accept = make(this, QStringLiteral("accept"), tr("A&ccept"), QKeySequence(tr("Ctrl+Return")),
                  tr("Accept the chosen estimate for apply"));
    apply = make(this, QStringLiteral("apply"), tr("A&pply..."), QKeySequence(tr("Ctrl+Shift+A")),
                 tr("Write the accepted estimate to the robot controller"));
    revert = make(this, QStringLiteral("revert"), tr("Re&vert"), QKeySequence(tr("Ctrl+Shift+Z")),
                  tr("Restore the parameter set the robot held before the last apply"));
    about = make(this, QStringLiteral("learnid"), tr("&About learnid"), QKeySequence(),
                 tr("Version and licence"));
    aboutQt = make(this, QString(), tr("About &Qt"), QKeySequence(), tr("Qt version"));
    quit->setMenuRole(QAction::QuitRole);
    about->setMenuRole(QAction::AboutRole);

    languages = new QActionGroup(this);
    const QList<QPair<QString, QString>> entries = {
        {QString(), tr("System language")},
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")},
        {QStringLiteral("zh_CN"), QStringLiteral("\u4e2d\u6587 (\u7b80\u4f53)")}};
    for (const auto &entry : entries) {
        QAction *a = languages->addAction(entry.second);
        a->setCheckable(true);
        a->setData(entry.first);
    }
    connect(languages, &QActionGroup::triggered, this,
            [this](QAction *a) { emit languageChosen(a->data().toString()); });
}

void MainActions::setLanguage(const QString &language)
{
    for (QAction *a : languages->actions())
        a->setChecked(a->data().toString() == language);
}

void MainActions::populate(QMenuBar *menuBar, QToolBar *toolBar)
{
    QMenu *file = menuBar->addMenu(tr("&File"));
    file->addActions({openScenario, saveScenario});
    file->addSeparator();
    file->addActions({exportParameters, exportUrdf, exportTrialCsv, exportPlot, exportReport});
    file->addSeparator();
    file->addAction(quit);
    QMenu *robot = menuBar->addMenu(tr("&Robot"));
    robot->addActions({connectRobot, newSession});
    robot->addSeparator();
    robot->addActions({identifyFromLogs, learnPayload});
    QMenu *trials = menuBar->addMenu(tr("&Trials"));
    trials->addActions({runTrial, runAll, stop});
    QMenu *params = menuBar->addMenu(tr("&Parameters"));
    params->addActions({accept, apply, revert});
    QMenu *view = menuBar->addMenu(tr("&View"));
    view->setObjectName(QStringLiteral("viewMenu"));
    QMenu *language = view->addMenu(tr("&Language"));
    language->addActions(languages->actions());
    QMenu *help = menuBar->addMenu(tr("&Help"));
    help->addActions({about, aboutQt});

    toolBar->setObjectName(QStringLiteral("mainToolBar"));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    toolBar->addActions({connectRobot, openScenario, saveScenario});
    toolBar->addSeparator();
    toolBar->addActions({runTrial, runAll, stop});
    toolBar->addSeparator();
    toolBar->addActions({accept, apply, revert});
    toolBar->addSeparator();
    toolBar->addActions({exportParameters, exportReport});
}

} // namespace learnid
