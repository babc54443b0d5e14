#pragma once

#include "types/Scenario.h"

#include <QObject>
#include <functional>

class QWidget;

namespace learnid {

class ApplyPanel;
class ConvergenceChart;
class ConvergenceTableModel;
class ParameterTableModel;
class ScenarioForm;
class SessionController;
class TrackingErrorPlot;
class UiSettings;

/// Loads and saves scenario files and exports what a session produced: the parameter file (JSON
/// and DCF fragment), per-trial CSV, the tracking-error plot (PNG, SVG when built with Qt6::Svg)
/// and the one-page PDF report. Every write is atomic (writeFileAtomically): a failure leaves no
/// half-written file. Results and errors are reported by finished(), never by a modal box.
class FileController : public QObject
{
    Q_OBJECT

public:
    enum class Purpose {
        OpenScenario,
        SaveScenario,
        ParameterFile,
        TrialCsvFolder,
        Plot,
        Report,
        Urdf
    };
    /// Asks the technician for a path; returns "" when cancelled. The default uses QFileDialog;
    /// tests inject their own.
    using PathChooser = std::function<QString(Purpose, const QString &suggested)>;

    struct Views
    {
        ScenarioForm *form = nullptr;
        ConvergenceTableModel *table = nullptr;
        ParameterTableModel *parameters = nullptr;
        TrackingErrorPlot *plot = nullptr;
        ConvergenceChart *chart = nullptr;
        ApplyPanel *apply = nullptr;
    };

    FileController(SessionController *session, Views views, UiSettings *settings,
                   QWidget *dialogParent);

    void setPathChooser(PathChooser chooser) { m_chooser = std::move(chooser); }

public slots:
    void openScenario();
    void saveScenario();
    void exportParameterFile();
    void exportTrialCsv();
    void exportPlot();
    void exportReport();
    void exportIdentifiedUrdf();

    void openScenarioFrom(const QString &path);
    void saveScenarioTo(const QString &path);
    /// Exports the accepted estimate; the result arrives asynchronously by finished().
    void exportParameterFileTo(const QString &jsonPath);
    /// Writes the trial CSV files; the result arrives asynchronously by finished().
    void exportTrialCsvTo(const QString &folder);
    void exportPlotTo(const QString &path);
    void exportReportTo(const QString &path);
    /// The robot's URDF with the accepted estimate as real bodies (URDF robots); the result
    /// arrives asynchronously by finished().
    void exportIdentifiedUrdfTo(const QString &path);

signals:
    void scenarioLoaded(const learnid::Scenario &scenario);
    /// ok false: message says what failed and where.
    void finished(const QString &message, bool ok);

private:
    QString choose(Purpose purpose, const QString &suggested);
    QString dialogPath(Purpose purpose, const QString &suggested);
    void remember(const QString &path);

    SessionController *m_session;
    Views m_views;
    UiSettings *m_settings;
    QWidget *m_dialogParent;
    PathChooser m_chooser;
};

} // namespace learnid
