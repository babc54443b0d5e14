#include "ui/ConvergencePanel.h"

#include "ui/ConvergenceChart.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/ParameterTableModel.h"

#include <QHeaderView>
#include <QTabWidget>
#include <QTableView>

namespace learnid {

namespace {

QTableView *tableView(QAbstractItemModel *model, const QString &name)
{
    auto *view = new QTableView;
    view->setObjectName(name);
    view->setModel(model);
    view->setAlternatingRowColors(true);
    // Sized to the contents once per reset (a trial), not at every layout: ResizeToContents
    // measures every cell of a 57-row table each time the window lays out.
    view->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    view->verticalHeader()->hide();
    view->horizontalHeader()->setStretchLastSection(true);
    QObject::connect(model, &QAbstractItemModel::modelReset, view,
                     &QTableView::resizeColumnsToContents);
    return view;
}

} // namespace

ConvergencePanel::ConvergencePanel(ConvergenceTableModel *trials, ParameterTableModel *parameters,
                                   ConvergenceChart *chart, QWidget *parent)
    : QSplitter(Qt::Horizontal, parent)
    , m_tabs(new QTabWidget)
    , m_trials(tableView(trials, QStringLiteral("convergenceTable")))
    , m_parameters(tableView(parameters, QStringLiteral("parameterTable")))
{
    m_tabs->setObjectName(QStringLiteral("convergenceTabs"));
    m_tabs->addTab(m_trials, tr("Estimates"));
    m_tabs->addTab(m_parameters, tr("Parameters"));
    addWidget(m_tabs);
    addWidget(chart);
    setStretchFactor(0, 3);
    setStretchFactor(1, 1);
}

} // namespace learnid
