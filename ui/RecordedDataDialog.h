#pragma once

#include "service/LogIdentification.h"
#include "ui/RecordedDataForm.h"

#include <QDialog>
#include <memory>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableView;

namespace learnid {

class LogExportController;
class LogIdentificationJob;
class LogValidationTableModel;
class MessageBar;
class TorqueFitPlot;
class UiSettings;

/// "Identify from recorded data": a robot's parameters from logs its controller recorded. The
/// form names the robot, the training and validation logs and their columns; Identify runs
/// identifyFromLogs() in a worker thread (LogIdentificationJob) with its progress per stage and
/// a Cancel button. Then it shows the fit, the consistency verdict, the base parameters the logs
/// leave undetermined, per validation log the figures table (LogValidationTableModel) and the
/// predicted-against-measured plots (TorqueFitPlot). Accept enables the exports: the parameter
/// file with its DCF and the identified URDF, written as learnid-cli identify writes them
/// (atomically, LogExportController). Errors and results go to the dialog's message bar.
class RecordedDataDialog : public QDialog
{
    Q_OBJECT

public:
    /// settings: where the last folder is remembered (may be null).
    explicit RecordedDataDialog(UiSettings *settings, QWidget *parent = nullptr);
    ~RecordedDataDialog() override;

    /// For the form's file choices and the exports; the default shows file dialogs.
    void setPathChooser(const RecordedDataPathChooser &chooser);

    RecordedDataForm *form() const { return m_form; }
    LogValidationTableModel *tableModel() const { return m_table; }
    TorqueFitPlot *plot() const { return m_plot; }
    MessageBar *messageBar() const { return m_message; }
    /// Writes the accepted result; its finished() shows in the message bar.
    LogExportController *exports() const { return m_exports; }
    /// The last identification's result (null before one succeeded or after a failed one).
    std::shared_ptr<const LogIdentificationResult> result() const { return m_result; }
    bool isAccepted() const { return m_accepted; }
    bool isRunning() const;

public slots:
    void identify();
    void cancel();
    void acceptResult();
    /// Shows validation log i (its table and plots).
    void showValidation(int i);
    void reject() override;

signals:
    /// An identification ended: with a result, or not (failed or cancelled).
    void identificationFinished(bool succeeded);

private:
    void buildLayout();
    void setBusy(bool busy);
    void clearResult();
    void showResult(std::shared_ptr<const LogIdentificationResult> result);
    void showProgress(const LogIdentificationProgress &progress);
    void updateActions();

    UiSettings *m_settings;
    MessageBar *m_message;
    RecordedDataForm *m_form;
    QPushButton *m_identify;
    QPushButton *m_cancel;
    QProgressBar *m_progress;
    QLabel *m_stage;
    QLabel *m_summary;
    QComboBox *m_validationLog;
    LogValidationTableModel *m_table;
    QTableView *m_tableView;
    TorqueFitPlot *m_plot;
    QPushButton *m_accept;
    QPushButton *m_exportParameters;
    QPushButton *m_exportUrdf;
    LogIdentificationJob *m_job;
    LogExportController *m_exports;
    std::shared_ptr<const LogIdentificationResult> m_result;
    bool m_accepted = false;
};

} // namespace learnid
