#include "ui/LogExportController.h"

#include "io/ScenarioFile.h"
#include "ui/UiSettings.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>

namespace learnid {

LogExportController::LogExportController(UiSettings *settings, QWidget *dialogParent)
    : QObject(dialogParent)
    , m_settings(settings)
    , m_dialogParent(dialogParent)
{}

void LogExportController::setResult(std::shared_ptr<const LogIdentificationResult> result)
{
    m_result = std::move(result);
}

QString LogExportController::choosePath(RecordedDataPath purpose, const QString &suggestedName)
{
    const QString dir = m_settings ? m_settings->lastDirectory() : QString();
    const QString suggested = QDir(dir).filePath(suggestedName);
    const QStringList paths = m_chooser
                                  ? m_chooser(purpose, suggested)
                                  : chooseRecordedDataPaths(m_dialogParent, purpose, suggested);
    if (paths.isEmpty())
        return {};
    if (m_settings)
        m_settings->setLastDirectory(QFileInfo(paths.constFirst()).absolutePath());
    return paths.constFirst();
}

void LogExportController::exportParameterFile()
{
    const QString path =
        choosePath(RecordedDataPath::ParameterFile, QStringLiteral("identified-parameters.json"));
    if (!path.isEmpty())
        exportParameterFileTo(path);
}

void LogExportController::exportUrdf()
{
    const QString path =
        choosePath(RecordedDataPath::IdentifiedUrdf, QStringLiteral("identified.urdf"));
    if (!path.isEmpty())
        exportUrdfTo(path);
}

std::optional<ControllerSettings> LogExportController::gains(QString *error) const
{
    const int joints = m_result->model().dof();
    if (m_gainsScenario.isEmpty())
        return std::nullopt; // the parameter file holds the model alone
    try {
        const Scenario s = readScenarioFile(m_gainsScenario);
        validateControllerSettings(
            s.controller, joints,
            QStringLiteral("%1: controller").arg(QDir::toNativeSeparators(m_gainsScenario)));
        return s.controller;
    } catch (const Error &e) {
        *error = e.message();
        return std::nullopt;
    }
}

void LogExportController::exportParameterFileTo(const QString &jsonPath)
{
    QString error;
    std::optional<ControllerSettings> controller;
    if (!m_result)
        error = tr("identify and accept a result first");
    else
        controller = gains(&error);
    if (!error.isEmpty()) {
        emit finished(tr("Parameter file not written: %1").arg(error), false);
        return;
    }
    LogExportRequest request;
    request.parameterPath = jsonPath;
    request.controller = controller;
    write(request, tr("Parameter file written: %1"), tr("Parameter file not written: %1"));
}

void LogExportController::exportUrdfTo(const QString &urdfPath)
{
    if (!m_result) {
        emit finished(tr("URDF not written: identify and accept a result first"), false);
        return;
    }
    LogExportRequest request;
    request.urdfPath = urdfPath;
    request.urdfComment = tr("identified by learnid %1 (Identify from recorded data) on %2")
                              .arg(QStringLiteral(LEARNID_VERSION),
                                   QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
    write(request, tr("URDF written: %1"), tr("URDF not written: %1"));
}

void LogExportController::write(const LogExportRequest &request, const QString &written,
                                const QString &notWritten)
{
    try {
        QStringList native;
        for (const QString &path : writeLogExport(*m_result, request))
            native << QDir::toNativeSeparators(path);
        emit finished(written.arg(native.join(QStringLiteral(", "))), true);
    } catch (const Error &e) {
        emit finished(notWritten.arg(e.message()), false);
    }
}

} // namespace learnid
