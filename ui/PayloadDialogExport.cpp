// The result side of the payload step (PayloadDialog.h): the robot, Accept, the apply to a CAN
// robot's drives, the exports of an accepted result, written all or none, and the scenario
// (gains designed for the payload, saved to a file), and the run's record (report, trial CSVs).
#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "service/PayloadRunExport.h"
#include "service/PayloadRunJob.h"
#include "session/RobotScenario.h"
#include "ui/MessageBar.h"
#include "ui/PayloadDialog.h"
#include "ui/PayloadForm.h"
#include "ui/UiSettings.h"

#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>

namespace learnid {

void PayloadDialog::acceptResult()
{
    if (!m_result || isRunning())
        return;
    m_accepted = true;
    updateActions();
    m_message->showMessage(
        m_robot.kind == RobotRequest::Kind::Can
            ? tr("Payload accepted: apply it to the robot's drives, or export the parameter file "
                 "or the URDF.")
            : tr("Payload accepted: export the parameter file or the URDF. It is not applied to a "
                 "robot (the simulated robot carries it already)."),
        MessageBar::Severity::Info);
}

void PayloadDialog::setRobotRequest(const RobotRequest &robot)
{
    if (isRunning())
        return;
    m_robot = robot;
    const bool can = robot.kind == RobotRequest::Kind::Can;
    setWindowTitle(
        can ? tr("Learn a payload (CAN robot %1/%2)").arg(robot.can.plugin, robot.can.interface)
            : tr("Learn a payload (simulated robot)"));
    m_apply->setVisible(can);
    m_record.reset();
    clearResult(); // a result belongs to the robot it was learned on
}

void PayloadDialog::applyToRobot()
{
    if (!m_result || !m_accepted || isRunning() || m_robot.kind != RobotRequest::Kind::Can)
        return;
    const PayloadBody &b = m_result->fit.estimate.body;
    const QString question =
        tr("Write the payload on %1 (%2 kg, centre of mass (%3, %4, %5) mm) to every drive of "
           "%6/%7 (object 0x2500), read it back and store it?")
            .arg(m_result->link)
            .arg(b.mass, 0, 'g', 5)
            .arg(1000.0 * b.com.x(), 0, 'f', 1)
            .arg(1000.0 * b.com.y(), 0, 'f', 1)
            .arg(1000.0 * b.com.z(), 0, 'f', 1)
            .arg(m_robot.can.plugin, m_robot.can.interface);
    const bool confirmed = m_confirmer ? m_confirmer(question)
                                       : QMessageBox::question(this, tr("Apply the payload"),
                                                               question) == QMessageBox::Yes;
    if (!confirmed) {
        m_message->showMessage(tr("Apply cancelled; the robot is unchanged."),
                               MessageBar::Severity::Info);
        return;
    }
    if (!m_job->applyResult())
        return;
    m_progress->setRange(0, 0);
    setBusy(true);
    m_stage->setText(tr("Writing the payload to the drives\u2026"));
}

void PayloadDialog::showApplied(const QString &error)
{
    setBusy(false);
    if (error.isEmpty())
        m_message->showMessage(tr("Applied: every drive stored the payload (0x2500)."),
                               MessageBar::Severity::Success);
    else
        m_message->showMessage(tr("Not applied: %1").arg(error), MessageBar::Severity::Error);
    emit applyFinished(error.isEmpty());
}

void PayloadDialog::exportParameterFile()
{
    writeExport(ExportKind::ParameterFile);
}

void PayloadDialog::exportUrdf()
{
    writeExport(ExportKind::Urdf);
}

QString PayloadDialog::choosePath(ExportKind kind, const QString &fileName, const QString &title,
                                  const QString &filter)
{
    const QString dir = m_settings ? m_settings->lastDirectory() : QDir::homePath();
    const QString suggested = QDir(dir).filePath(fileName);
    return m_chooser ? m_chooser(kind, suggested)
                     : QFileDialog::getSaveFileName(this, title, suggested, filter);
}

void PayloadDialog::rememberFolder(const QString &writtenPath)
{
    if (m_settings)
        m_settings->setLastDirectory(QFileInfo(writtenPath).absolutePath());
}

void PayloadDialog::writeExport(ExportKind kind)
{
    if (!m_result || !m_accepted)
        return;
    const bool parameters = kind == ExportKind::ParameterFile;
    const QString path =
        parameters ? choosePath(kind, QStringLiteral("payload.json"), tr("Export parameter file"),
                                tr("Parameter files (*.json)"))
                   : choosePath(kind, QStringLiteral("payload.urdf"),
                                tr("Export URDF with the payload"), tr("URDF (*.urdf)"));
    if (path.isEmpty())
        return;
    LogExportRequest request;
    (parameters ? request.parameterPath : request.urdfPath) = path;
    request.urdfComment = tr("learnid %1, %2")
                              .arg(QStringLiteral(LEARNID_VERSION),
                                   QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
    try {
        const QStringList paths = writePayloadRunExport(*m_result, request);
        rememberFolder(path);
        m_message->showMessage(
            tr("Written: %1").arg(QDir::toNativeSeparators(paths.join(QStringLiteral(", ")))),
            MessageBar::Severity::Success);
    } catch (const Error &e) {
        m_message->showMessage(tr("Not written: %1").arg(e.message()), MessageBar::Severity::Error);
    }
}

void PayloadDialog::designForPayload()
{
    const auto given = m_form->scenario();
    if (!given || isRunning())
        return;
    try {
        // For the robot's clock, which stays.
        const Scenario designed = scenarioForRobot(given->model, given->urdf, given->payload,
                                                   given->controller.samplePeriod);
        Scenario s = *given;
        s.controller = designed.controller;
        s.planningFraction = designed.planningFraction;
        s.payload.baselineKp = designed.payload.baselineKp;
        s.payload.baselineKi = designed.payload.baselineKi;
        s.payload.baselineKd = designed.payload.baselineKd;
        m_form->setScenario(s);
        m_message->showMessage(
            tr("Gains designed for the arm carrying %1 kg on %2 (planning fraction %3); the "
               "preview checks the first trial with them.")
                .arg(s.payload.mass)
                .arg(s.payload.link.isEmpty() ? tr("the tip link") : s.payload.link)
                .arg(s.planningFraction, 0, 'g', 2),
            MessageBar::Severity::Info);
    } catch (const Error &e) {
        m_message->showMessage(tr("Gains not designed: %1").arg(e.message()),
                               MessageBar::Severity::Error);
    }
}

void PayloadDialog::saveRecord()
{
    if (!m_record || isRunning())
        return;
    const QString path =
        choosePath(ExportKind::Record, QStringLiteral("payload-run.json"),
                   tr("Save the run's report and trials"), tr("Payload reports (*.json)"));
    if (path.isEmpty())
        return;
    try {
        writePayloadRecord(*m_record, path);
        rememberFolder(path);
        const int csvs = int(m_record->trialCsvs.size());
        const QString folder = QDir::toNativeSeparators(payloadRecordTrialFolder(path));
        m_message->showMessage(
            m_record->endedEarly.isEmpty()
                ? tr("Written: %1 and %n trial CSV(s) in %2", nullptr, csvs)
                      .arg(QDir::toNativeSeparators(path), folder)
                : tr("Written: %1 and %n trial CSV(s) in %2, of a run that ended early: %3",
                     nullptr, csvs)
                      .arg(QDir::toNativeSeparators(path), folder, m_record->endedEarly),
            MessageBar::Severity::Success);
    } catch (const Error &e) {
        m_message->showMessage(tr("Not written: %1").arg(e.message()), MessageBar::Severity::Error);
    }
}

void PayloadDialog::saveScenario()
{
    const auto scenario = m_form->scenario();
    if (!scenario || isRunning())
        return;
    const QString path = choosePath(ExportKind::Scenario, QStringLiteral("payload-scenario.json"),
                                    tr("Save scenario"), tr("Scenario files (*.json)"));
    if (path.isEmpty())
        return;
    try {
        writeScenarioFile(path, *scenario);
        rememberFolder(path);
        m_message->showMessage(tr("Scenario saved: %1").arg(QDir::toNativeSeparators(path)),
                               MessageBar::Severity::Success);
    } catch (const Error &e) {
        m_message->showMessage(tr("Scenario not saved: %1").arg(e.message()),
                               MessageBar::Severity::Error);
    }
}

} // namespace learnid
