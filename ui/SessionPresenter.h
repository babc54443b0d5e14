#pragma once

#include <QObject>

namespace learnid {

class ApplyPanel;
class ConvergenceChart;
class ConvergenceTableModel;
class ParameterTableModel;
class MessageBar;
class PreTrialCheckView;
class RobotPanel;
class RunPanel;
class ScenarioForm;
class SessionController;
class TrackingErrorPlot;

/// Shows what the SessionController reports in the passive views: the robot state, the
/// pre-trial check, progress, plots, the convergence table and chart, the accept/apply state
/// and every failure in the message bar.
class SessionPresenter : public QObject
{
    Q_OBJECT

public:
    struct Views
    {
        RobotPanel *robot;
        ScenarioForm *form;
        PreTrialCheckView *check;
        RunPanel *run;
        ApplyPanel *apply;
        TrackingErrorPlot *plot;
        ConvergenceTableModel *table;
        ParameterTableModel *parameters;
        ConvergenceChart *chart;
        MessageBar *message;
    };

    SessionPresenter(SessionController *controller, Views views, QObject *parent = nullptr);

private:
    void refreshTables();

    SessionController *m_controller;
    Views m_views;
};

} // namespace learnid
