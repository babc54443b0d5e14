// The result side of the payload step (PayloadDialog.h): Accept, and the exports of an accepted
// result, written all or none.
#include "model/Error.h"
#include "service/PayloadRunExport.h"
#include "ui/MessageBar.h"
#include "ui/PayloadDialog.h"
#include "ui/UiSettings.h"

#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>

namespace learnid {

void PayloadDialog::acceptResult()
{
    if (!m_result || isRunning())
        return;
    m_accepted = true;
    updateActions();
    m_message->showMessage(tr("Payload accepted: export the parameter file or the URDF. It is "
                              "not applied to a robot (the simulated robot carries it already)."),
                           MessageBar::Severity::Info);
}

void PayloadDialog::exportParameterFile()
{
    writeExport(ExportKind::ParameterFile);
}

void PayloadDialog::exportUrdf()
{
    writeExport(ExportKind::Urdf);
}

void PayloadDialog::writeExport(ExportKind kind)
{
    if (!m_result || !m_accepted)
        return;
    const bool parameters = kind == ExportKind::ParameterFile;
    const QString dir = m_settings ? m_settings->lastDirectory() : QDir::homePath();
    const QString suggested = QDir(dir).filePath(parameters ? QStringLiteral("payload.json")
                                                            : QStringLiteral("payload.urdf"));
    const QString path =
        m_chooser    ? m_chooser(kind, suggested)
        : parameters ? QFileDialog::getSaveFileName(this, tr("Export parameter file"), suggested,
                                                    tr("Parameter files (*.json)"))
                     : QFileDialog::getSaveFileName(this, tr("Export URDF with the payload"),
                                                    suggested, tr("URDF (*.urdf)"));
    if (path.isEmpty())
        return;
    LogExportRequest request;
    (parameters ? request.parameterPath : request.urdfPath) = path;
    request.urdfComment = tr("learnid %1, %2")
                              .arg(QStringLiteral(LEARNID_VERSION),
                                   QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
    try {
        const QStringList paths = writePayloadRunExport(*m_result, request);
        if (m_settings)
            m_settings->setLastDirectory(QFileInfo(path).absolutePath());
        m_message->showMessage(
            tr("Written: %1").arg(QDir::toNativeSeparators(paths.join(QStringLiteral(", ")))),
            MessageBar::Severity::Success);
    } catch (const Error &e) {
        m_message->showMessage(tr("Not written: %1").arg(e.message()), MessageBar::Severity::Error);
    }
}

} // namespace learnid
