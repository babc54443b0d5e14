#pragma once

#include "ui/ApplyPreview.h"
#include "ui/UiSettings.h"

#include <QMainWindow>
#include <functional>

class QLabel;
class QSettings;

namespace learnid {

class ApplyPanel;
class ConvergenceChart;
class ConvergenceTableModel;
class FileController;
class MainActions;
class MessageBar;
class ParameterTableModel;
class PreTrialCheckView;
class PayloadDialog;
class RecordedDataDialog;
class RobotPanel;
class RunPanel;
class ScenarioForm;
class SessionController;
class SessionPresenter;
class TrackingErrorPlot;

/// The commissioning window. It builds menus and docks and connects the passive views to the
/// SessionController and the FileController, nothing more.
class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    /// Asked before an apply writes to the robot; true = write. Default: ApplyConfirmDialog.
    using ApplyConfirmation = std::function<bool(const ApplyPreview &)>;

    /// settings: where the window remembers its state and the last scenario (caller owns it).
    explicit MainWindow(QSettings *settings, QWidget *parent = nullptr);
    ~MainWindow() override;

    void setApplyConfirmation(ApplyConfirmation confirm) { m_confirm = std::move(confirm); }

    SessionController *controller() const { return m_controller; }
    FileController *files() const { return m_files; }
    MainActions *actions() const { return m_actions; }
    ScenarioForm *form() const { return m_form; }
    RobotPanel *robotPanel() const { return m_robot; }
    PreTrialCheckView *checkView() const { return m_check; }
    RunPanel *runPanel() const { return m_run; }
    ApplyPanel *applyPanel() const { return m_apply; }
    TrackingErrorPlot *plot() const { return m_plot; }
    ConvergenceTableModel *tableModel() const { return m_table; }
    ParameterTableModel *parameterModel() const { return m_parameters; }
    MessageBar *messageBar() const { return m_message; }
    /// "Identify from recorded data", made when first opened (null before).
    RecordedDataDialog *recordedDataDialog() const { return m_recordedData; }
    /// The payload step (null until it is first opened).
    PayloadDialog *payloadDialog() const { return m_payload; }

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void buildLayout();
    void connectViews();
    void updateActions();
    void connectOrDisconnect();
    void requestApply();
    void showAbout();
    /// Opens the payload step with the scenario (Robot > Learn a payload, or a scenario file with
    /// a payload section: the arm's session does not learn one).
    void openPayloadStep(const Scenario &scenario);

    UiSettings m_settings;
    SessionController *m_controller;
    MainActions *m_actions;
    MessageBar *m_message;
    RobotPanel *m_robot;
    ScenarioForm *m_form;
    PreTrialCheckView *m_check;
    RunPanel *m_run;
    ApplyPanel *m_apply;
    TrackingErrorPlot *m_plot;
    ConvergenceTableModel *m_table;
    ParameterTableModel *m_parameters;
    ConvergenceChart *m_chart;
    FileController *m_files;
    SessionPresenter *m_presenter;
    QLabel *m_statusRobot;
    RecordedDataDialog *m_recordedData = nullptr;
    PayloadDialog *m_payload = nullptr;
    ApplyConfirmation m_confirm;
};

} // namespace learnid
