#include "ui/FileController.h"

#include "io/AtomicFile.h"
#include "io/ScenarioFile.h"
#include "io/TrialCsv.h"
#include "model/Error.h"
#include "service/SessionController.h"
#include "ui/ApplyPanel.h"
#include "ui/ConvergenceChart.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/PlotImage.h"
#include "ui/ReportContent.h"
#include "ui/ReportWriter.h"
#include "ui/ScenarioForm.h"
#include "ui/TrackingErrorPlot.h"
#include "ui/UiLogging.h"
#include "ui/UiSettings.h"

#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QtCharts/QChartView>

namespace learnid {

FileController::FileController(SessionController *session, Views views, UiSettings *settings,
                               QWidget *dialogParent)
    : QObject(dialogParent)
    , m_session(session)
    , m_views(views)
    , m_settings(settings)
    , m_dialogParent(dialogParent)
{
    connect(m_session, &SessionController::parameterFileExported, this,
            [this](const QStringList &paths, const QString &error) {
                if (error.isEmpty())
                    emit finished(
                        tr("Parameter file written: %1")
                            .arg(QDir::toNativeSeparators(paths.join(QStringLiteral(", ")))),
                        true);
                else
                    emit finished(tr("Parameter file not written: %1").arg(error), false);
            });
    connect(m_session, &SessionController::urdfExported, this,
            [this](const QStringList &paths, const QString &error) {
                if (error.isEmpty())
                    emit finished(
                        tr("Identified URDF written: %1")
                            .arg(QDir::toNativeSeparators(paths.join(QStringLiteral(", ")))),
                        true);
                else
                    emit finished(tr("URDF not written: %1").arg(error), false);
            });
    connect(m_session, &SessionController::trialCsvExported, this,
            [this](const QString &folder, int files, const QString &error) {
                if (error.isEmpty()) {
                    remember(QDir(folder).filePath(QStringLiteral("x")));
                    emit finished(tr("%n trial CSV file(s) written to %1", nullptr, files)
                                      .arg(QDir::toNativeSeparators(folder)),
                                  true);
                } else
                    emit finished(tr("Trial CSV not written: %1").arg(error), false);
            });
}

QString FileController::choose(Purpose purpose, const QString &suggested)
{
    const QString dir = m_settings->lastDirectory();
    const QString path = QDir(dir).filePath(suggested);
    return m_chooser ? m_chooser(purpose, path) : dialogPath(purpose, path);
}

QString FileController::dialogPath(Purpose purpose, const QString &suggested)
{
    switch (purpose) {
    case Purpose::OpenScenario:
        return QFileDialog::getOpenFileName(m_dialogParent, tr("Open scenario"), suggested,
                                            tr("Scenario files (*.json);;All files (*)"));
    case Purpose::SaveScenario:
        return QFileDialog::getSaveFileName(m_dialogParent, tr("Save scenario"), suggested,
                                            tr("Scenario files (*.json)"));
    case Purpose::ParameterFile:
        return QFileDialog::getSaveFileName(m_dialogParent, tr("Export parameter file"), suggested,
                                            tr("Parameter files (*.json)"));
    case Purpose::TrialCsvFolder:
        return QFileDialog::getExistingDirectory(
            m_dialogParent, tr("Folder for the trial CSV files"), QFileInfo(suggested).path());
    case Purpose::Plot:
        return QFileDialog::getSaveFileName(m_dialogParent, tr("Export plot"), suggested,
                                            svgExportAvailable()
                                                ? tr("PNG image (*.png);;SVG drawing (*.svg)")
                                                : tr("PNG image (*.png)"));
    case Purpose::Report:
        return QFileDialog::getSaveFileName(m_dialogParent, tr("Export commissioning report"),
                                            suggested, tr("PDF (*.pdf)"));
    case Purpose::Urdf:
        return QFileDialog::getSaveFileName(m_dialogParent, tr("Export identified URDF"), suggested,
                                            tr("URDF (*.urdf)"));
    }
    return {};
}

void FileController::remember(const QString &path)
{
    m_settings->setLastDirectory(QFileInfo(path).absolutePath());
}

void FileController::openScenario()
{
    const QString path = choose(Purpose::OpenScenario, QString());
    if (!path.isEmpty())
        openScenarioFrom(path);
}

void FileController::saveScenario()
{
    const QString path = choose(Purpose::SaveScenario, QStringLiteral("scenario.json"));
    if (!path.isEmpty())
        saveScenarioTo(path);
}

void FileController::exportParameterFile()
{
    const QString path = choose(Purpose::ParameterFile, QStringLiteral("parameters.json"));
    if (!path.isEmpty())
        exportParameterFileTo(path);
}

void FileController::exportIdentifiedUrdf()
{
    const QString path = choose(Purpose::Urdf, QStringLiteral("identified.urdf"));
    if (!path.isEmpty())
        exportIdentifiedUrdfTo(path);
}

void FileController::exportIdentifiedUrdfTo(const QString &path)
{
    if (!m_session->acceptedIndex()) {
        emit finished(tr("URDF not written: accept an estimate first"), false);
        return;
    }
    remember(path);
    m_session->exportIdentifiedUrdf(
        path, *m_session->acceptedIndex(),
        tr("identified by learnid %1 (estimate %2 of a commissioning session) on %3")
            .arg(QStringLiteral(LEARNID_VERSION))
            .arg(*m_session->acceptedIndex())
            .arg(QDateTime::currentDateTimeUtc().toString(Qt::ISODate)));
}

void FileController::exportTrialCsv()
{
    const QString path = choose(Purpose::TrialCsvFolder, QStringLiteral("trials"));
    if (!path.isEmpty())
        exportTrialCsvTo(path);
}

void FileController::exportPlot()
{
    const QString path = choose(Purpose::Plot, QStringLiteral("tracking-error.png"));
    if (!path.isEmpty())
        exportPlotTo(path);
}

void FileController::exportReport()
{
    const QString path = choose(Purpose::Report, QStringLiteral("commissioning-report.pdf"));
    if (!path.isEmpty())
        exportReportTo(path);
}

void FileController::openScenarioFrom(const QString &path)
{
    try {
        const Scenario scenario = readScenarioFile(path);
        validateScenario(scenario);
        remember(path);
        emit scenarioLoaded(scenario);
        emit finished(tr("Scenario loaded: %1").arg(QDir::toNativeSeparators(path)), true);
    } catch (const Error &e) {
        emit finished(tr("Scenario not loaded: %1").arg(e.message()), false);
    }
}

void FileController::saveScenarioTo(const QString &path)
{
    const auto scenario = m_views.form->scenario();
    if (!scenario) {
        emit finished(tr("Scenario not saved: %1").arg(m_views.form->firstError()), false);
        return;
    }
    try {
        writeScenarioFile(path, *scenario);
        remember(path);
        emit finished(tr("Scenario saved: %1").arg(QDir::toNativeSeparators(path)), true);
    } catch (const Error &e) {
        emit finished(tr("Scenario not saved: %1").arg(e.message()), false);
    }
}

void FileController::exportParameterFileTo(const QString &jsonPath)
{
    if (!m_session->acceptedIndex()) {
        emit finished(tr("Parameter file not written: accept an estimate first"), false);
        return;
    }
    remember(jsonPath);
    m_session->exportParameterFile(jsonPath, *m_session->acceptedIndex());
}

void FileController::exportTrialCsvTo(const QString &folder)
{
    if (m_session->history().isEmpty()) {
        emit finished(tr("No trial CSV written: no trial has run yet"), false);
        return;
    }
    m_session->exportTrialCsv(folder); // the samples are with the session in its thread
}

void FileController::exportPlotTo(const QString &path)
{
    const bool svg = path.endsWith(QStringLiteral(".svg"), Qt::CaseInsensitive);
    if (svg && !svgExportAvailable()) {
        emit finished(tr("Plot not written: this build has no SVG support (Qt6::Svg); "
                         "export as PNG instead"),
                      false);
        return;
    }
    QWidget *view = m_views.plot->chartView();
    const QSize size(1200, 700);
    const QByteArray bytes =
        svg ? widgetSvg(view, tr("Tracking error"), size) : widgetPng(view, size);
    try {
        writeFileAtomically(path, bytes);
        remember(path);
        emit finished(tr("Plot written: %1").arg(QDir::toNativeSeparators(path)), true);
    } catch (const Error &e) {
        emit finished(tr("Plot not written: %1").arg(e.message()), false);
    }
}

void FileController::exportReportTo(const QString &path)
{
    if (!m_session->info()) {
        emit finished(tr("Report not written: no session"), false);
        return;
    }
    const ReportContent c = sessionReportContent(
        *m_session, {m_views.table, m_views.parameters, m_views.plot, m_views.chart});
    try {
        writeFileAtomically(path, commissioningReportPdf(c));
        remember(path);
        emit finished(tr("Report written: %1").arg(QDir::toNativeSeparators(path)), true);
    } catch (const Error &e) {
        emit finished(tr("Report not written: %1").arg(e.message()), false);
    }
}

} // namespace learnid
