#pragma once

#include <QSplitter>

class QTabWidget;
class QTableView;

namespace learnid {

class ConvergenceChart;
class ConvergenceTableModel;
class ParameterTableModel;

/// The convergence of a session below the plot: the trials and estimates (Table 1 of the paper)
/// and the parameters as rows (any number of them) in two tabs, the chart beside them. It only
/// lays out the views of the models it is given.
class ConvergencePanel : public QSplitter
{
    Q_OBJECT

public:
    ConvergencePanel(ConvergenceTableModel *trials, ParameterTableModel *parameters,
                     ConvergenceChart *chart, QWidget *parent = nullptr);

    QTabWidget *tabs() const { return m_tabs; }
    QTableView *trialView() const { return m_trials; }
    QTableView *parameterView() const { return m_parameters; }

private:
    QTabWidget *m_tabs;
    QTableView *m_trials;
    QTableView *m_parameters;
};

} // namespace learnid
