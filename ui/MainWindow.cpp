#include "ui/MainWindow.h"

#include "service/SessionController.h"
#include "ui/ApplyConfirmDialog.h"
#include "ui/ApplyPanel.h"
#include "ui/ConvergenceChart.h"
#include "ui/ConvergencePanel.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/FileController.h"
#include "ui/MainActions.h"
#include "ui/MessageBar.h"
#include "ui/ParameterTableModel.h"
#include "ui/PayloadDialog.h"
#include "ui/PreTrialCheckView.h"
#include "ui/RecordedDataDialog.h"
#include "ui/RobotPanel.h"
#include "ui/RunPanel.h"
#include "ui/ScenarioForm.h"
#include "ui/SessionPresenter.h"
#include "ui/TrackingErrorPlot.h"
#include "ui/WidgetFactory.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QStatusBar>
#include <QToolBar>
#include <QVBoxLayout>

namespace learnid {

namespace {

QDockWidget *dock(const QString &title, const QString &name, QWidget *content, QWidget *parent)
{
    auto *d = new QDockWidget(title, parent);
    d->setObjectName(name);
    d->setWidget(content);
    d->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    return d;
}

} // namespace

MainWindow::MainWindow(QSettings *settings, QWidget *parent)
    : QMainWindow(parent)
    , m_settings(settings)
    , m_controller(new SessionController(this))
    , m_actions(new MainActions(this))
    , m_message(new MessageBar)
    , m_robot(new RobotPanel)
    , m_form(new ScenarioForm)
    , m_check(new PreTrialCheckView)
    , m_run(new RunPanel(m_actions->runTrial, m_actions->runAll, m_actions->stop))
    , m_apply(new ApplyPanel(m_actions->accept, m_actions->apply, m_actions->revert))
    , m_plot(new TrackingErrorPlot)
    , m_table(new ConvergenceTableModel(this))
    , m_parameters(new ParameterTableModel(this))
    , m_chart(new ConvergenceChart)
    , m_statusRobot(new QLabel)
    , m_confirm([this](const ApplyPreview &preview) {
        return ApplyConfirmDialog(preview, this).exec() == QDialog::Accepted;
    })
{
    setWindowTitle(tr("learnid \u2013 commissioning"));
    setWindowIcon(QIcon(QStringLiteral(":/icons/learnid.svg")));
    m_files = new FileController(
        m_controller, {m_form, m_table, m_parameters, m_plot, m_chart, m_apply}, &m_settings, this);
    m_form->setScenario(m_settings.scenario());
    m_plot->setAutoScale(m_settings.plotAutoScale());
    m_actions->setLanguage(m_settings.language());
    buildLayout();
    connectViews();
    m_presenter = new SessionPresenter(m_controller,
                                       {m_robot, m_form, m_check, m_run, m_apply, m_plot, m_table,
                                        m_parameters, m_chart, m_message},
                                       this);
    connect(m_controller, &SessionController::stateChanged, this, &MainWindow::updateActions);
    statusBar()->addPermanentWidget(m_statusRobot);
    restoreGeometry(m_settings.windowGeometry());
    restoreState(m_settings.windowState());
    updateActions();
}

MainWindow::~MainWindow() = default;

void MainWindow::buildLayout()
{
    m_actions->populate(menuBar(), addToolBar(tr("Main")));
    auto *convergence = new ConvergencePanel(m_table, m_parameters, m_chart);

    auto *controls = new QHBoxLayout;
    controls->addWidget(titledGroup(tr("Pre-trial check"), m_check), 3);
    controls->addWidget(titledGroup(tr("Run"), m_run), 2);
    controls->addWidget(titledGroup(tr("Accept / apply"), m_apply), 2);
    auto *central = new QWidget;
    auto *layout = new QVBoxLayout(central);
    layout->addWidget(m_message);
    layout->addLayout(controls);
    layout->addWidget(m_plot, 1);
    setCentralWidget(central);

    auto *setup = new QWidget;
    setup->setMinimumWidth(480);
    auto *setupLayout = new QVBoxLayout(setup);
    setupLayout->addWidget(titledGroup(tr("Robot"), m_robot));
    auto *scroll = new QScrollArea;
    scroll->setWidget(m_form);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFrameShape(QFrame::NoFrame);
    setupLayout->addWidget(titledGroup(tr("Scenario"), scroll), 1);
    QDockWidget *setupDock = dock(tr("Setup"), QStringLiteral("setupDock"), setup, this);
    QDockWidget *convergenceDock =
        dock(tr("Parameter convergence"), QStringLiteral("convergenceDock"), convergence, this);
    addDockWidget(Qt::LeftDockWidgetArea, setupDock);
    addDockWidget(Qt::BottomDockWidgetArea, convergenceDock);
    resize(1600, 1000);
    resizeDocks({setupDock}, {480}, Qt::Horizontal);
    resizeDocks({convergenceDock}, {300}, Qt::Vertical);
}

void MainWindow::connectViews()
{
    const MainActions *a = m_actions;
    connect(m_robot, &RobotPanel::connectRequested, this, &MainWindow::connectOrDisconnect);
    connect(m_robot, &RobotPanel::disconnectRequested, m_controller, &SessionController::close);
    connect(a->connectRobot, &QAction::triggered, this, &MainWindow::connectOrDisconnect);
    connect(a->newSession, &QAction::triggered, this, [this] {
        if (const auto s = m_form->scenario())
            m_controller->open(*s);
    });
    connect(a->identifyFromLogs, &QAction::triggered, this, [this] {
        if (!m_recordedData)
            m_recordedData = new RecordedDataDialog(&m_settings, this);
        m_recordedData->show();
        m_recordedData->raise();
    });
    connect(a->learnPayload, &QAction::triggered, this,
            [this] { openPayloadStep(m_form->scenario().value_or(m_settings.scenario())); });
    connect(a->runTrial, &QAction::triggered, this, [this] {
        m_run->startSeries(1);
        m_controller->runTrial();
    });
    connect(a->runAll, &QAction::triggered, this, [this] {
        const int n = m_controller->info()->scenario.iterations;
        m_run->startSeries(n);
        m_controller->runTrials(n);
    });
    connect(a->stop, &QAction::triggered, m_controller, &SessionController::stop);
    connect(a->accept, &QAction::triggered, this,
            [this] { m_controller->accept(m_apply->chosenEstimate()); });
    connect(a->apply, &QAction::triggered, this, &MainWindow::requestApply);
    connect(a->revert, &QAction::triggered, m_controller, &SessionController::revert);
    connect(a->openScenario, &QAction::triggered, m_files, &FileController::openScenario);
    connect(a->saveScenario, &QAction::triggered, m_files, &FileController::saveScenario);
    connect(a->exportParameters, &QAction::triggered, m_files,
            &FileController::exportParameterFile);
    connect(a->exportTrialCsv, &QAction::triggered, m_files, &FileController::exportTrialCsv);
    connect(a->exportPlot, &QAction::triggered, m_files, &FileController::exportPlot);
    connect(a->exportReport, &QAction::triggered, m_files, &FileController::exportReport);
    connect(a->exportUrdf, &QAction::triggered, m_files, &FileController::exportIdentifiedUrdf);
    connect(a->quit, &QAction::triggered, this, &QWidget::close);
    connect(a->about, &QAction::triggered, this, &MainWindow::showAbout);
    connect(a->aboutQt, &QAction::triggered, qApp, &QApplication::aboutQt);
    connect(a, &MainActions::languageChosen, this, [this](const QString &language) {
        m_settings.setLanguage(language);
        m_message->showMessage(tr("The language changes when learnid is started again."),
                               MessageBar::Severity::Info);
    });
    connect(m_plot, &TrackingErrorPlot::autoScaleChanged, this,
            [this](bool on) { m_settings.setPlotAutoScale(on); });
    connect(m_files, &FileController::scenarioLoaded, m_form, &ScenarioForm::setScenario);
    connect(m_files, &FileController::scenarioLoaded, this, [this](const Scenario &s) {
        if (s.payload.enabled)
            openPayloadStep(s);
    });
    connect(m_files, &FileController::finished, this, [this](const QString &text, bool ok) {
        m_message->showMessage(text,
                               ok ? MessageBar::Severity::Success : MessageBar::Severity::Error);
    });
    connect(m_form, &ScenarioForm::edited, this, [this](bool valid) {
        if (m_form->model())
            m_robot->setJointCount(m_form->model()->dof());
        if (!valid)
            return updateActions();
        m_settings.setScenario(*m_form->scenario());
        // Before the first trial the new settings replace the session, so the check is current.
        const SessionState state = m_controller->state();
        // A payload is learned in the payload step: the arm's session refuses its scenario.
        if ((state == SessionState::Idle || state == SessionState::Connecting) &&
            m_controller->history().isEmpty() && !m_form->scenario()->payload.enabled)
            m_controller->open(*m_form->scenario());
        updateActions();
    });
}

void MainWindow::updateActions()
{
    SessionFacts facts = m_controller->facts();
    facts.scenarioValid = m_form->isValid();
    const AllowedActions allowed = allowedActions(m_controller->state(), facts);
    MainActions *a = m_actions;
    a->connectRobot->setEnabled(allowed.connect || allowed.disconnect);
    a->connectRobot->setText(m_controller->isOpen() ? tr("Dis&connect robot")
                                                    : tr("&Connect robot"));
    a->newSession->setEnabled(allowed.newSession);
    a->runTrial->setEnabled(allowed.run);
    a->runAll->setEnabled(allowed.run);
    a->stop->setEnabled(allowed.stop);
    a->accept->setEnabled(allowed.accept);
    a->apply->setEnabled(allowed.apply);
    a->revert->setEnabled(allowed.revert);
    a->exportParameters->setEnabled(allowed.exportParameters);
    a->exportTrialCsv->setEnabled(allowed.exportTrialData);
    a->exportPlot->setEnabled(allowed.exportTrialData);
    a->exportReport->setEnabled(allowed.exportReport);
    a->exportUrdf->setEnabled(allowed.exportParameters && m_form->model() &&
                              m_form->model()->id() != QLatin1String("paper-2link"));
    a->openScenario->setEnabled(allowed.editScenario);
    const SessionController *c = m_controller;
    const bool open = c->isOpen(), busy = c->isBusy();
    m_form->setEditable(allowed.editScenario);
    m_robot->setBusy(busy);
    if (c->state() == SessionState::Idle && c->lastCheck() && !c->lastCheck()->passed())
        m_run->setStatus(tr("Run disabled: %1").arg(c->lastCheck()->reason()));
    const QString robot = open ? c->info()->robotDescription : tr("no robot");
    m_statusRobot->setText(tr("Robot: %1 \u2013 %2")
                               .arg(robot, busy   ? tr("busy")
                                           : open ? tr("idle")
                                                  : tr("not connected")));
}

void MainWindow::connectOrDisconnect()
{
    if (m_controller->isOpen())
        return m_controller->close();
    QString error;
    const auto scenario = m_form->scenario();
    const auto robot = m_robot->choice(&error, scenario ? scenario->controller.samplePeriod : 0.002,
                                       m_form->model() ? m_form->model()->dof() : 0);
    if (!robot)
        return m_message->showMessage(tr("Cannot connect: %1").arg(error),
                                      MessageBar::Severity::Error);
    m_controller->setRobotRequest(*robot);
    if (robot->kind == RobotRequest::Kind::Can)
        m_robot->setConnected(
            false, tr("connecting to %1/%2\u2026").arg(robot->can.plugin, robot->can.interface));
    if (scenario)
        m_controller->open(*scenario);
    else
        m_message->showMessage(tr("Correct the scenario first: %1").arg(m_form->firstError()),
                               MessageBar::Severity::Error);
}

void MainWindow::requestApply()
{
    const SessionController *c = m_controller;
    if (!c->acceptedIndex() || !c->info())
        return;
    ApplyPreview preview;
    preview.estimateIndex = *c->acceptedIndex();
    preview.parameters = c->info()->parameters;
    preview.oldValues = c->storedParameters();
    preview.newValues = c->estimates().at(preview.estimateIndex);
    if (m_confirm(preview))
        m_controller->apply();
    else
        m_message->showMessage(tr("Apply cancelled; the robot is unchanged."),
                               MessageBar::Severity::Info);
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About learnid"),
                       tr("<h3>learnid %1</h3><p>Learning identification of robot dynamics: "
                          "a commissioning tool.</p><p>Built with Qt %2.</p>")
                           .arg(QStringLiteral(LEARNID_VERSION), QString::fromLatin1(qVersion())));
}

void MainWindow::openPayloadStep(const Scenario &scenario)
{
    // The payload step runs on the robot panel's choice; on CAN it opens its own connection, so
    // the arm's session must not hold the bus.
    QString error;
    const auto robot = m_robot->choice(&error, scenario.controller.samplePeriod,
                                       int(scenario.controller.kp.size()));
    if (robot && robot->kind == RobotRequest::Kind::Can && m_controller->isOpen())
        return m_message->showMessage(tr("The payload step needs the CAN bus: disconnect the "
                                         "arm's session first."),
                                      MessageBar::Severity::Error);
    if (!m_payload)
        m_payload = new PayloadDialog(&m_settings, this);
    m_payload->setRobotRequest(robot.value_or(RobotRequest()));
    m_payload->setScenario(scenario);
    m_payload->show();
    m_payload->raise();
    if (!robot)
        m_payload->messageBar()->showMessage(
            tr("The robot panel's choice cannot be used (%1): the payload step runs on the "
               "simulated robot.")
                .arg(error),
            MessageBar::Severity::Error);
    else if (scenario.payload.enabled)
        m_payload->messageBar()->showMessage(
            tr("The scenario has a payload section: its payload is learned here, in the payload "
               "step; the arm's session is not opened with it."),
            MessageBar::Severity::Info);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    m_controller->stop();
    m_settings.setWindow(saveGeometry(), saveState());
    event->accept();
}

} // namespace learnid
