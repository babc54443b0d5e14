#pragma once

#include "service/LogIdentification.h"
#include "ui/RecordedDataForm.h"

#include <QObject>
#include <memory>
#include <optional>

class QWidget;

namespace learnid {

class UiSettings;

/// Exports an accepted identification from logs as `learnid-cli identify` does: the parameter
/// file with its DCF fragment beside it, and the identified URDF, each written atomically
/// (writeLogExport). The parameter file records controller gains, which logs do not carry, only
/// when a scenario gives them (setGainsScenario); else it holds the model alone. Results and
/// errors come by finished(), never a box.
class LogExportController : public QObject
{
    Q_OBJECT

public:
    /// settings: where the last folder is remembered (may be null).
    LogExportController(UiSettings *settings, QWidget *dialogParent);

    void setPathChooser(RecordedDataPathChooser chooser) { m_chooser = std::move(chooser); }
    /// The accepted result; null: nothing to export.
    void setResult(std::shared_ptr<const LogIdentificationResult> result);
    /// The scenario whose controller gains the parameter file records; "": none (the file
    /// holds the model alone).
    void setGainsScenario(const QString &path) { m_gainsScenario = path; }

public slots:
    void exportParameterFile();
    void exportUrdf();
    void exportParameterFileTo(const QString &jsonPath);
    void exportUrdfTo(const QString &urdfPath);

signals:
    /// ok: the files were written (message names them); else nothing was, and message says why.
    void finished(const QString &message, bool ok);

private:
    QString choosePath(RecordedDataPath purpose, const QString &suggestedName);
    /// The gains the parameter file records: nullopt without a scenario, or with error set when
    /// the scenario cannot give them.
    std::optional<ControllerSettings> gains(QString *error) const;
    /// written, notWritten: the messages, %1 the paths or the error.
    void write(const LogExportRequest &request, const QString &written, const QString &notWritten);

    UiSettings *m_settings;
    QWidget *m_dialogParent;
    RecordedDataPathChooser m_chooser;
    std::shared_ptr<const LogIdentificationResult> m_result;
    QString m_gainsScenario;
};

} // namespace learnid
