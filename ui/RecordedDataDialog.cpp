#include "ui/RecordedDataDialog.h"

#include "service/LogIdentificationJob.h"
#include "ui/LogExportController.h"
#include "ui/LogIdentificationText.h"
#include "ui/LogValidationTableModel.h"
#include "ui/MessageBar.h"
#include "ui/TorqueFitPlot.h"
#include "ui/UiSettings.h"
#include "ui/WidgetFactory.h"

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
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
#include <QVBoxLayout>

namespace learnid {

namespace {

QStringList jointNames(const ChainModel &model)
{
    QStringList names;
    for (const ChainJoint &j : model.chain().joints)
        names << j.name;
    return names;
}

} // namespace

RecordedDataDialog::RecordedDataDialog(UiSettings *settings, QWidget *parent)
    : QDialog(parent)
    , m_settings(settings)
    , m_message(new MessageBar)
    , m_form(new RecordedDataForm)
    , m_identify(namedButton(tr("&Identify"), "identifyButton"))
    , m_cancel(namedButton(tr("Cancel"), "cancelIdentifyButton"))
    , m_progress(new QProgressBar)
    , m_stage(new QLabel)
    , m_summary(new QLabel)
    , m_validationLog(new QComboBox)
    , m_table(new LogValidationTableModel(this))
    , m_tableView(new QTableView)
    , m_plot(new TorqueFitPlot)
    , m_accept(namedButton(tr("&Accept"), "acceptIdentifiedButton"))
    , m_exportParameters(
          namedButton(tr("Export &parameter file\u2026"), "exportParameterFileButton"))
    , m_exportUrdf(namedButton(tr("Export &URDF\u2026"), "exportUrdfButton"))
    , m_job(new LogIdentificationJob(this))
    , m_exports(new LogExportController(settings, this))
{
    setObjectName(QStringLiteral("recordedDataDialog"));
    setWindowTitle(tr("Identify from recorded data"));
    m_progress->setObjectName(QStringLiteral("identifyProgress"));
    m_stage->setObjectName(QStringLiteral("identifyStage"));
    m_summary->setObjectName(QStringLiteral("identifySummary"));
    m_validationLog->setObjectName(QStringLiteral("validationLogChoice"));
    m_tableView->setObjectName(QStringLiteral("validationTable"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_stage->setWordWrap(true);
    m_tableView->setModel(m_table);
    m_tableView->setAlternatingRowColors(true);
    m_tableView->verticalHeader()->hide();
    m_tableView->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_tableView->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    m_tableView->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    m_identify->setDefault(true);
    if (m_settings)
        m_form->setStartDirectory(m_settings->lastDirectory());

    buildLayout();
    connect(m_form, &RecordedDataForm::directoryUsed, this, [this](const QString &dir) {
        if (m_settings)
            m_settings->setLastDirectory(dir);
    });
    connect(m_identify, &QPushButton::clicked, this, &RecordedDataDialog::identify);
    connect(m_cancel, &QPushButton::clicked, this, &RecordedDataDialog::cancel);
    connect(m_accept, &QPushButton::clicked, this, &RecordedDataDialog::acceptResult);
    connect(m_exportParameters, &QPushButton::clicked, this, [this] {
        m_exports->setGainsScenario(m_form->gainsScenario());
        m_exports->exportParameterFile();
    });
    connect(m_exportUrdf, &QPushButton::clicked, m_exports, &LogExportController::exportUrdf);
    connect(m_validationLog, &QComboBox::activated, this, &RecordedDataDialog::showValidation);
    connect(m_job, &LogIdentificationJob::progress, this, &RecordedDataDialog::showProgress);
    connect(m_job, &LogIdentificationJob::succeeded, this, &RecordedDataDialog::showResult);
    connect(m_job, &LogIdentificationJob::failed, this, [this](const QString &message) {
        setBusy(false);
        m_message->showMessage(tr("Not identified: %1").arg(message), MessageBar::Severity::Error);
        emit identificationFinished(false);
    });
    connect(m_job, &LogIdentificationJob::cancelled, this, [this] {
        setBusy(false);
        m_message->showMessage(tr("Identification cancelled; nothing was identified or written."),
                               MessageBar::Severity::Info);
        emit identificationFinished(false);
    });
    connect(m_exports, &LogExportController::finished, this, [this](const QString &text, bool ok) {
        m_message->showMessage(text,
                               ok ? MessageBar::Severity::Success : MessageBar::Severity::Error);
    });
    setBusy(false);
    clearResult();
    // Room for the table and seven joints' plots, within the screen of a small laptop too.
    const QSize available = screen() ? screen()->availableGeometry().size() : QSize(1440, 940);
    resize(QSize(1440, 940).boundedTo(available * 0.95));
}

RecordedDataDialog::~RecordedDataDialog() = default;

void RecordedDataDialog::buildLayout()
{
    auto *runRow = new QHBoxLayout;
    runRow->addWidget(m_identify);
    runRow->addWidget(m_cancel);
    runRow->addWidget(m_progress, 1);
    auto *inputs = new QGroupBox(tr("Robot and logs"));
    auto *inputLayout = new QVBoxLayout(inputs);
    inputLayout->addWidget(m_form);
    inputLayout->addLayout(runRow);
    inputLayout->addWidget(m_stage);
    auto *fit = new QGroupBox(tr("Fit"));
    auto *fitLayout = new QVBoxLayout(fit);
    // The fit's text grows with the robot (a row per link): it scrolls rather than being cut.
    auto *summaryScroll = new QScrollArea;
    summaryScroll->setWidget(m_summary);
    summaryScroll->setWidgetResizable(true);
    summaryScroll->setFrameShape(QFrame::NoFrame);
    fitLayout->addWidget(summaryScroll);
    auto *logRow = new QHBoxLayout;
    logRow->addWidget(new QLabel(tr("Validation on:")));
    logRow->addWidget(m_validationLog, 1);
    auto *validation = new QGroupBox(tr("Validation"));
    auto *validationLayout = new QVBoxLayout(validation);
    validationLayout->addLayout(logRow);
    validationLayout->addWidget(m_tableView, 1);
    auto *left = new QWidget;
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(inputs);
    // The fit's text (with its per-link table) and the validation table share what is left, and
    // the technician can drag between them: neither squeezes the other to a row.
    auto *results = new QSplitter(Qt::Vertical);
    results->setChildrenCollapsible(false);
    results->addWidget(fit);
    results->addWidget(validation);
    results->setStretchFactor(0, 1);
    results->setStretchFactor(1, 1);
    results->setSizes({1, 1});
    leftLayout->addWidget(results, 1);
    left->setMinimumWidth(480);

    auto *plots = new QGroupBox(tr("Predicted against measured torque (validation log)"));
    auto *plotLayout = new QVBoxLayout(plots);
    plotLayout->addWidget(m_plot);
    auto *main = new QSplitter(Qt::Horizontal);
    main->addWidget(left);
    main->addWidget(plots);
    main->setStretchFactor(0, 0);
    main->setStretchFactor(1, 1);
    main->setSizes({640, 800});

    auto *close = namedButton(tr("Close"), "closeRecordedDataButton");
    connect(close, &QPushButton::clicked, this, &RecordedDataDialog::reject);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_accept);
    buttons->addWidget(m_exportParameters);
    buttons->addWidget(m_exportUrdf);
    buttons->addStretch(1);
    buttons->addWidget(close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_message);
    layout->addWidget(main, 1);
    layout->addLayout(buttons);
}

void RecordedDataDialog::setPathChooser(const RecordedDataPathChooser &chooser)
{
    m_exports->setPathChooser(chooser);
    m_form->setPathChooser(chooser);
}

bool RecordedDataDialog::isRunning() const
{
    return m_job->isRunning();
}

void RecordedDataDialog::setBusy(bool busy)
{
    m_form->setEditable(!busy);
    m_identify->setEnabled(!busy);
    m_cancel->setEnabled(busy);
    m_progress->setVisible(busy);
    if (!busy)
        m_stage->clear();
    updateActions();
}

void RecordedDataDialog::updateActions()
{
    const bool result = m_result && !isRunning();
    m_accept->setEnabled(result && !m_accepted);
    m_exportParameters->setEnabled(result && m_accepted);
    m_exportUrdf->setEnabled(result && m_accepted);
}

void RecordedDataDialog::clearResult()
{
    m_result.reset();
    m_accepted = false;
    m_exports->setResult(nullptr);
    m_summary->setText(tr("Add the robot's logs and press Identify."));
    m_validationLog->clear();
    m_table->clear();
    m_plot->clear();
    updateActions();
}

void RecordedDataDialog::identify()
{
    QString error;
    const auto request = m_form->request(&error);
    if (!request) {
        m_message->showMessage(tr("Cannot identify: %1").arg(error), MessageBar::Severity::Error);
        return;
    }
    clearResult();
    m_message->hide();
    m_progress->setRange(0, 0);
    if (m_job->start(*request))
        setBusy(true);
}

void RecordedDataDialog::cancel()
{
    m_job->cancel();
    m_stage->setText(tr("Cancelling after the current step\u2026"));
}

void RecordedDataDialog::reject()
{
    m_job->cancel(); // closing the window stops the run
    QDialog::reject();
}

void RecordedDataDialog::showProgress(const LogIdentificationProgress &p)
{
    m_progress->setRange(0, p.steps);
    m_progress->setValue(p.step);
    m_stage->setText(logIdentificationStageText(p));
}

void RecordedDataDialog::showResult(std::shared_ptr<const LogIdentificationResult> result)
{
    m_result = std::move(result);
    setBusy(false);
    const LogIdentificationResult &r = *m_result;
    m_summary->setText(logIdentificationSummaryHtml(r));
    for (const LogValidation &v : r.validation) {
        m_validationLog->addItem(QFileInfo(v.source).fileName());
        m_validationLog->setItemData(m_validationLog->count() - 1,
                                     QDir::toNativeSeparators(v.source), Qt::ToolTipRole);
    }
    showValidation(0);
    m_message->showMessage(logIdentificationMessage(r), MessageBar::Severity::Success);
    emit identificationFinished(true);
}

void RecordedDataDialog::showValidation(int i)
{
    if (!m_result || i < 0 || i >= int(m_result->validation.size())) {
        m_table->clear();
        m_plot->clear();
        return;
    }
    m_validationLog->setCurrentIndex(i);
    const LogValidation &v = m_result->validation[size_t(i)];
    const QStringList names = jointNames(m_result->model());
    m_table->setFigures(names, v.given, v.identified);
    m_plot->setData(names, v.time, v.measured, v.predictedIdentified, v.predictedGiven);
}

void RecordedDataDialog::acceptResult()
{
    if (!m_result || isRunning())
        return;
    m_accepted = true;
    m_exports->setResult(m_result);
    updateActions();
    m_message->showMessage(tr("Result accepted: export the parameter file or the URDF."),
                           MessageBar::Severity::Info);
}

} // namespace learnid
