#pragma once

#include "service/PayloadRun.h"

#include <QDialog>
#include <functional>
#include <memory>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableView;
class QTimer;

namespace learnid {

class MessageBar;
class PayloadEstimateTableModel;
class PayloadForm;
class PayloadRunJob;
class PayloadTrialTableModel;
class TrackingErrorPlot;
class UiSettings;

/// The payload step (docs/payload.md, "In the window"): a payload learned on the simulated robot,
/// or on the window's CAN robot, with the arm's model held fixed. The form (PayloadForm) gives the
/// link, the prior, the bound and the trials, each refused value named at its field; before any
/// motion the dialog shows what the path lets the trials see and whether the first trial passes its
/// check (PayloadRunJob:: check(), redone after each edit). Run runs the baseline and payload
/// trials in a worker thread (PayloadRunJob) with progress per trial and Stop; each finished trial
/// adds a row (PayloadTrialTableModel) and its tracking error over time (TrackingErrorPlot). A run
/// that completes shows the estimate with each value's standard error, prior and source
/// (PayloadEstimateTableModel); Accept enables the exports: the parameter file with a payload
/// section (and its DCF) and the URDF with a fixed payload link, written all or none
/// (writePayloadRunExport); Save scenario keeps the step's edits as a scenario file at any time but
/// a run; on the CAN robot Accept also enables Apply, which writes the payload to the drives
/// (PayloadRunJob::applyResult). Baseline trials on the CAN robot wait for the technician to take
/// the payload off, then to mount it (Continue). A stopped or failed run leaves no result, but the
/// record of the trials it ran (Save report and trials, the report marked as ended early and why).
class PayloadDialog : public QDialog
{
    Q_OBJECT

public:
    enum class ExportKind { ParameterFile, Urdf, Scenario, Record };
    /// Asks for a path to write (empty: cancelled); the default shows a file dialog.
    using PathChooser = std::function<QString(ExportKind kind, const QString &suggested)>;
    /// Asks whether to go on (the question in words); the default shows a message box.
    using Confirmer = std::function<bool(const QString &question)>;

    /// settings: where the last folder is remembered (may be null).
    explicit PayloadDialog(UiSettings *settings, QWidget *parent = nullptr);
    ~PayloadDialog() override;

    /// The scenario whose payload is learned (a scenario without a payload section gets one).
    void setScenario(const Scenario &scenario);
    void setPathChooser(PathChooser chooser) { m_chooser = std::move(chooser); }
    void setApplyConfirmer(Confirmer confirmer) { m_confirmer = std::move(confirmer); }
    /// The robot the trials run on: the simulated one (default), or the window's CAN robot,
    /// whose drives an accepted payload can then be applied to (0x2500).
    void setRobotRequest(const RobotRequest &robot);

    PayloadForm *form() const { return m_form; }
    PayloadTrialTableModel *trialTable() const { return m_trials; }
    PayloadEstimateTableModel *estimateTable() const { return m_estimate; }
    /// Each trial's tracking error per joint over time (the trials that moved).
    TrackingErrorPlot *trackingPlot() const { return m_plot; }
    MessageBar *messageBar() const { return m_message; }
    /// The rich text of what the path lets the trials see (or why it cannot be planned).
    QString previewText() const;
    /// The last completed run's result (null before one, after a stopped or failed one).
    std::shared_ptr<const PayloadRunResult> result() const { return m_result; }
    bool isRunning() const;
    bool isAccepted() const { return m_accepted; }

public slots:
    void run();
    void stop();
    /// The technician has taken the payload off or mounted it, as the run asked (CAN robot).
    void continueAfterMounting();
    void acceptResult();
    /// Writes the accepted payload to the CAN robot's drives and stores it, after a confirmation.
    void applyToRobot();
    void exportParameterFile();
    void exportUrdf();
    /// Saves the form's scenario, its payload section included, to a scenario file.
    void saveScenario();
    /// Saves the last run's report and trial CSVs (writePayloadRecord), accepted or not, also of
    /// a run that ended early.
    void saveRecord();
    /// Designs the gains, the planning fraction and the baseline trials' gains for the arm
    /// carrying the form's prior (the payload starter: scenarioForRobot() with the payload), and
    /// keeps everything else of the form's scenario; the preview checks them.
    void designForPayload();
    void reject() override;

signals:
    /// The preview after an edit is shown (ok false: the scenario cannot be planned).
    void previewShown(bool ok);
    /// A run ended: with a result, or not (failed or stopped).
    void runFinished(bool succeeded);
    /// An apply ended: the drives stored the payload, or not.
    void applyFinished(bool succeeded);

private:
    void buildLayout();
    void connectJob();
    void setBusy(bool busy);
    void clearResult();
    void updateActions();
    void requestCheck();
    void writeExport(ExportKind kind);
    /// Where to write (empty: cancelled): the chooser, or a file dialog in the last folder.
    QString choosePath(ExportKind kind, const QString &fileName, const QString &title,
                       const QString &filter);
    /// Remembers the folder of a file just written, for the next choice.
    void rememberFolder(const QString &writtenPath);
    void showApplied(const QString &error);
    void askForMounting(bool mount, const QString &link, int baselineTrials);

    UiSettings *m_settings;
    MessageBar *m_message;
    PayloadForm *m_form;
    QLabel *m_preview;
    QPushButton *m_run;
    QPushButton *m_stop;
    QPushButton *m_continue; ///< shown while the run waits for the technician
    QProgressBar *m_progress;
    QLabel *m_stage;
    PayloadTrialTableModel *m_trials;
    QTableView *m_trialView;
    TrackingErrorPlot *m_plot;
    QLabel *m_summary;
    PayloadEstimateTableModel *m_estimate;
    QTableView *m_estimateView;
    QPushButton *m_accept;
    QPushButton *m_exportParameters;
    QPushButton *m_exportUrdf;
    QPushButton *m_apply;
    QPushButton *m_saveScenario;
    QPushButton *m_design;
    QPushButton *m_saveRecord;
    PayloadRunJob *m_job;
    QTimer *m_checkTimer;
    PathChooser m_chooser;
    Confirmer m_confirmer;
    RobotRequest m_robot;
    std::shared_ptr<const PayloadRunResult> m_result;
    /// The last run's record (of m_result, or of a run that ended early); null before a run.
    std::shared_ptr<const PayloadRunRecord> m_record;
    bool m_accepted = false;
};

} // namespace learnid
