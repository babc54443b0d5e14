#include "ui/PayloadDialog.h"

#include "service/PayloadRunJob.h"
#include "ui/MessageBar.h"
#include "ui/PayloadEstimateTableModel.h"
#include "ui/PayloadForm.h"
#include "ui/PayloadText.h"
#include "ui/PayloadTrialTableModel.h"
#include "ui/TrackingErrorPlot.h"
#include "ui/WidgetFactory.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

namespace learnid {

namespace {

QTableView *tableView(QAbstractItemModel *model, const char *name)
{
    auto *view = new QTableView;
    view->setObjectName(QLatin1String(name));
    view->setModel(model);
    view->setAlternatingRowColors(true);
    view->verticalHeader()->hide();
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 6);
    view->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    view->horizontalHeader()->setStretchLastSection(true);
    return view;
}

} // namespace

PayloadDialog::PayloadDialog(UiSettings *settings, QWidget *parent)
    : QDialog(parent)
    , m_settings(settings)
    , m_message(new MessageBar)
    , m_form(new PayloadForm)
    , m_preview(new QLabel)
    , m_run(namedButton(tr("&Run trials"), "runPayloadButton"))
    , m_stop(namedButton(tr("&Stop"), "stopPayloadButton"))
    , m_continue(namedButton(tr("&Continue"), "continuePayloadButton"))
    , m_progress(new QProgressBar)
    , m_stage(new QLabel)
    , m_trials(new PayloadTrialTableModel(this))
    , m_trialView(tableView(m_trials, "payloadTrialTable"))
    , m_plot(new TrackingErrorPlot)
    , m_summary(new QLabel)
    , m_estimate(new PayloadEstimateTableModel(this))
    , m_estimateView(tableView(m_estimate, "payloadEstimateTable"))
    , m_accept(namedButton(tr("&Accept"), "acceptPayloadButton"))
    , m_exportParameters(
          namedButton(tr("Export &parameter file\u2026"), "exportPayloadParametersButton"))
    , m_exportUrdf(namedButton(tr("Export &URDF\u2026"), "exportPayloadUrdfButton"))
    , m_apply(namedButton(tr("A&pply to the robot\u2026"), "applyPayloadButton"))
    , m_saveScenario(namedButton(tr("Sa&ve scenario\u2026"), "savePayloadScenarioButton"))
    , m_design(namedButton(tr("Design &gains for this payload"), "designPayloadGainsButton"))
    , m_saveRecord(namedButton(tr("Save report and &trials\u2026"), "savePayloadRecordButton"))
    , m_job(new PayloadRunJob(this))
    , m_checkTimer(new QTimer(this))
{
    setObjectName(QStringLiteral("payloadDialog"));
    setRobotRequest(RobotRequest());
    m_preview->setObjectName(QStringLiteral("payloadPreview"));
    m_summary->setObjectName(QStringLiteral("payloadSummary"));
    m_stage->setObjectName(QStringLiteral("payloadStage"));
    m_progress->setObjectName(QStringLiteral("payloadProgress"));
    for (QLabel *label : {m_preview, m_summary, m_stage}) {
        label->setWordWrap(true);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        label->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    }
    m_run->setDefault(true);
    m_checkTimer->setSingleShot(true);
    m_checkTimer->setInterval(250); // one plan after a burst of typing
    buildLayout();
    connectJob();
    connect(m_form, &PayloadForm::edited, this, [this] {
        clearResult();
        updateActions();
        m_checkTimer->start();
    });
    connect(m_checkTimer, &QTimer::timeout, this, &PayloadDialog::requestCheck);
    connect(m_run, &QPushButton::clicked, this, &PayloadDialog::run);
    connect(m_stop, &QPushButton::clicked, this, &PayloadDialog::stop);
    connect(m_continue, &QPushButton::clicked, this, &PayloadDialog::continueAfterMounting);
    connect(m_accept, &QPushButton::clicked, this, &PayloadDialog::acceptResult);
    connect(m_exportParameters, &QPushButton::clicked, this, &PayloadDialog::exportParameterFile);
    connect(m_exportUrdf, &QPushButton::clicked, this, &PayloadDialog::exportUrdf);
    connect(m_apply, &QPushButton::clicked, this, &PayloadDialog::applyToRobot);
    connect(m_saveScenario, &QPushButton::clicked, this, &PayloadDialog::saveScenario);
    connect(m_design, &QPushButton::clicked, this, &PayloadDialog::designForPayload);
    connect(m_saveRecord, &QPushButton::clicked, this, &PayloadDialog::saveRecord);
    setBusy(false);
    clearResult();
    const QSize available = screen() ? screen()->availableGeometry().size() : QSize(1280, 860);
    resize(QSize(1280, 860).boundedTo(available * 0.95));
}

PayloadDialog::~PayloadDialog() = default;

void PayloadDialog::buildLayout()
{
    auto *previewScroll = new QScrollArea;
    previewScroll->setWidget(m_preview);
    previewScroll->setWidgetResizable(true);
    previewScroll->setFrameShape(QFrame::NoFrame);
    auto *left = new QWidget;
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(titledGroup(tr("Payload and prior"), m_form));
    auto *designRow = new QHBoxLayout;
    designRow->addStretch(1);
    designRow->addWidget(m_design);
    leftLayout->addLayout(designRow);
    leftLayout->addWidget(titledGroup(tr("What the path lets the trials see"), previewScroll), 1);
    left->setMinimumWidth(460);

    auto *runRow = new QHBoxLayout;
    runRow->addWidget(m_run);
    runRow->addWidget(m_stop);
    runRow->addWidget(m_continue);
    runRow->addWidget(m_progress, 1);
    auto *trials = new QGroupBox(tr("Trials"));
    auto *trialLayout = new QVBoxLayout(trials);
    trialLayout->addLayout(runRow);
    trialLayout->addWidget(m_stage);
    trialLayout->addWidget(m_trialView, 1);
    auto *estimate = new QGroupBox(tr("Payload estimate"));
    auto *estimateLayout = new QVBoxLayout(estimate);
    estimateLayout->addWidget(m_summary);
    estimateLayout->addWidget(m_estimateView, 1);
    m_plot->setObjectName(QStringLiteral("payloadTrackingPlot"));
    auto *right = new QSplitter(Qt::Vertical);
    right->setChildrenCollapsible(false);
    right->addWidget(trials);
    right->addWidget(titledGroup(tr("Tracking error"), m_plot));
    right->addWidget(estimate);
    for (const int i : {0, 1, 2})
        right->setStretchFactor(i, i + 2); // the estimate most, the trial table least
    right->setSizes({200, 280, 360});

    auto *main = new QSplitter(Qt::Horizontal);
    main->addWidget(left);
    main->addWidget(right);
    main->setStretchFactor(1, 1);
    main->setSizes({480, 800});

    auto *close = namedButton(tr("Close"), "closePayloadButton");
    connect(close, &QPushButton::clicked, this, &PayloadDialog::reject);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_accept);
    buttons->addWidget(m_exportParameters);
    buttons->addWidget(m_exportUrdf);
    buttons->addWidget(m_apply);
    buttons->addWidget(m_saveRecord);
    buttons->addStretch(1);
    buttons->addWidget(m_saveScenario);
    buttons->addWidget(close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_message);
    layout->addWidget(main, 1);
    layout->addLayout(buttons);
}

void PayloadDialog::connectJob()
{
    connect(m_job, &PayloadRunJob::checked, this, [this](const PayloadPreview &p) {
        // The check plans on the simulated arm; the run goes to the robot the dialog was given.
        PayloadPreview shown = p;
        SimulatedPayload simulated = m_form->scenario().value_or(Scenario()).simulation.payload;
        if (m_robot.kind == RobotRequest::Kind::Can) {
            shown.robotDescription =
                tr("The CAN robot %1/%2").arg(m_robot.can.plugin, m_robot.can.interface);
            simulated = SimulatedPayload(); // what it carries is what is mounted
        }
        QString text = payloadPreviewHtml(shown, simulated);
        if (m_robot.kind == RobotRequest::Kind::Can && p.baselineTrials > 0) {
            text += QStringLiteral("<p>") +
                    tr("The run asks you to take the payload off before the baseline trials and "
                       "to mount it after them.") +
                    QStringLiteral("</p>");
        }
        m_preview->setText(text);
        m_plot->setJointNames(p.jointNames);
        emit previewShown(true);
    });
    connect(m_job, &PayloadRunJob::checkFailed, this, [this](const QString &message) {
        m_preview->setText(tr("The trials cannot be planned: %1").arg(message.toHtmlEscaped()));
        emit previewShown(false);
    });
    connect(m_job, &PayloadRunJob::trialStarted, this, [this](int index, int total, bool baseline) {
        m_progress->setRange(0, total);
        m_progress->setValue(index);
        m_stage->setText(
            baseline
                ? tr("Trial %1 of %2 running: baseline, without the payload\u2026")
                      .arg(index + 1)
                      .arg(total)
                : tr("Trial %1 of %2 running with the payload\u2026").arg(index + 1).arg(total));
    });
    connect(m_job, &PayloadRunJob::trialFinished, this, [this](const PayloadTrialRow &row) {
        m_trials->addRow(row);
        if (!row.curves.isEmpty())
            m_plot->setTrialCurves(row.index, row.curves);
        m_progress->setValue(row.index + 1);
        m_trialView->resizeColumnsToContents();
        m_trialView->scrollToBottom();
    });
    connect(m_job, &PayloadRunJob::succeeded, this,
            [this](std::shared_ptr<const PayloadRunResult> result) {
                m_result = std::move(result);
                m_record = std::shared_ptr<const PayloadRunRecord>(m_result, &m_result->record);
                setBusy(false);
                m_summary->setText(payloadResultHtml(*m_result));
                m_estimate->setEstimate(m_result->fit.estimate);
                m_message->showMessage(
                    m_robot.kind == RobotRequest::Kind::Can
                        ? tr("Payload learned: check the estimate, then accept it to apply it to "
                             "the robot or export it.")
                        : tr("Payload learned: check the estimate, then accept it to export."),
                    MessageBar::Severity::Success);
                emit runFinished(true);
            });
    connect(
        m_job, &PayloadRunJob::endedEarlyRecord, this,
        [this](std::shared_ptr<const PayloadRunRecord> record) { m_record = std::move(record); });
    connect(m_job, &PayloadRunJob::failed, this, [this](const QString &message) {
        setBusy(false);
        m_message->showMessage(
            m_record ? tr("Payload not learned: %1. The report and trials of the run can be "
                          "saved (Save report and trials).")
                           .arg(message)
                     : tr("Payload not learned: %1").arg(message),
            MessageBar::Severity::Error);
        emit runFinished(false);
    });
    connect(m_job, &PayloadRunJob::applied, this, &PayloadDialog::showApplied);
    connect(m_job, &PayloadRunJob::mountingRequested, this, &PayloadDialog::askForMounting);
    connect(m_job, &PayloadRunJob::cancelled, this, [this] {
        setBusy(false);
        m_message->showMessage(
            m_record ? tr("Stopped; no payload is kept from this run. Its report and trials can "
                          "be saved (Save report and trials).")
                     : tr("Stopped; nothing of this run is kept or written."),
            MessageBar::Severity::Info);
        emit runFinished(false);
    });
}

void PayloadDialog::setScenario(const Scenario &scenario)
{
    if (isRunning())
        return;
    m_form->setScenario(scenario);
    m_trials->clear();
    m_plot->clear();
    m_record.reset();
    m_message->hide();
}

QString PayloadDialog::previewText() const
{
    return m_preview->text();
}

bool PayloadDialog::isRunning() const
{
    return m_job->isRunning();
}

void PayloadDialog::setBusy(bool busy)
{
    m_form->setEditable(!busy);
    m_stop->setEnabled(busy);
    m_continue->hide();
    m_progress->setVisible(busy);
    if (!busy)
        m_stage->clear();
    updateActions();
}

void PayloadDialog::updateActions()
{
    const bool running = isRunning();
    m_run->setEnabled(!running && m_form->isValid());
    m_saveScenario->setEnabled(!running && m_form->isValid());
    m_design->setEnabled(!running && m_form->isValid());
    const bool result = m_result && !running;
    m_accept->setEnabled(result && !m_accepted);
    m_saveRecord->setEnabled(m_record && !running);
    m_exportParameters->setEnabled(result && m_accepted);
    m_exportUrdf->setEnabled(result && m_accepted);
    m_apply->setEnabled(result && m_accepted);
}

void PayloadDialog::clearResult()
{
    m_result.reset();
    m_accepted = false;
    m_estimate->clear();
    m_summary->setText(tr("Run the trials to learn the payload."));
    updateActions();
}

void PayloadDialog::requestCheck()
{
    if (const auto s = m_form->scenario()) {
        m_preview->setText(tr("Planning the first trial\u2026"));
        m_job->check(*s);
    } else {
        m_preview->setText(
            tr("Correct the payload first: %1").arg(m_form->firstError().toHtmlEscaped()));
        emit previewShown(false);
    }
}

void PayloadDialog::run()
{
    const auto s = m_form->scenario();
    if (!s) {
        m_message->showMessage(tr("Cannot run: %1").arg(m_form->firstError()),
                               MessageBar::Severity::Error);
        return;
    }
    if (m_checkTimer->isActive()) { // the preview of the last edit, planned before the run
        m_checkTimer->stop();
        requestCheck();
    }
    clearResult();
    m_trials->clear();
    m_plot->clear();
    m_record.reset();
    m_message->hide();
    m_progress->setRange(0, 0);
    if (m_job->start(*s, m_robot))
        setBusy(true);
}

void PayloadDialog::stop()
{
    m_job->cancel();
    m_stage->setText(tr("Stopping the running trial\u2026"));
}

void PayloadDialog::askForMounting(bool mount, const QString &link, int baselineTrials)
{
    const QString what =
        mount ? tr("The baseline trials are done: mount the payload on %1, then press Continue.")
                    .arg(link)
              : tr("Take the payload off %1 for the %n baseline trial(s), then press Continue.",
                   nullptr, baselineTrials)
                    .arg(link);
    m_stage->setText(what);
    m_message->showMessage(what, MessageBar::Severity::Info);
    m_continue->show();
    m_continue->setFocus();
}

void PayloadDialog::continueAfterMounting()
{
    m_continue->hide();
    m_message->hide();
    m_stage->setText(tr("Starting the next trial…"));
    m_job->confirmMounting();
}

void PayloadDialog::reject()
{
    m_job->cancel(); // closing the window stops the run
    QDialog::reject();
}

} // namespace learnid
