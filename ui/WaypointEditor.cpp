#include "ui/WaypointEditor.h"

#include <QBrush>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

namespace learnid {

WaypointEditor::WaypointEditor(QWidget *parent)
    : QWidget(parent)
    , m_table(new QTableWidget(this))
    , m_add(new QPushButton(tr("Add waypoint"), this))
    , m_remove(new QPushButton(tr("Remove waypoint"), this))
    , m_reason(new QLabel(this))
    , m_file(new QLabel(this))
    , m_choosePathFile(new QPushButton(tr("Path CSV\u2026"), this))
    , m_useWaypoints(new QPushButton(tr("Waypoints"), this))
{
    m_file->setWordWrap(true);
    m_choosePathFile->setObjectName(QStringLiteral("choosePathFileButton"));
    m_choosePathFile->setToolTip(tr("Run a recorded joint path instead: CSV t, q1..qn [s, rad]"));
    m_useWaypoints->setObjectName(QStringLiteral("useWaypointsButton"));
    connect(m_choosePathFile, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Open a joint path"), QString(),
                                                          tr("CSV (*.csv);;All files (*)"));
        if (!path.isEmpty())
            emit pathFileChosen(path);
    });
    connect(m_useWaypoints, &QPushButton::clicked, this, &WaypointEditor::waypointsChosen);
    m_table->setObjectName(QStringLiteral("path.waypoints"));
    m_add->setObjectName(QStringLiteral("addWaypointButton"));
    m_remove->setObjectName(QStringLiteral("removeWaypointButton"));
    m_reason->setObjectName(QStringLiteral("path.waypoints.reason"));
    m_reason->setStyleSheet(QStringLiteral("color: #b3261e;"));
    m_reason->setWordWrap(true);
    m_reason->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setMaximumHeight(160);
    // As wide as the form, not as its 7 columns: the table scrolls sideways instead.
    m_table->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_table->setToolTip(tr("Joint positions the path passes through, in order: degrees for "
                           "revolute joints, metres for prismatic ones"));
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    buttons->addWidget(m_useWaypoints);
    buttons->addWidget(m_choosePathFile);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table);
    layout->addWidget(m_file);
    layout->addLayout(buttons);
    layout->addWidget(m_reason);
    connect(m_table, &QTableWidget::itemChanged, this, [this] {
        if (!m_filling)
            emit edited();
    });
    connect(m_add, &QPushButton::clicked, this, [this] {
        // A copy of the selected (or last) waypoint below it, to be edited.
        const int from =
            m_table->currentRow() >= 0 ? m_table->currentRow() : m_table->rowCount() - 1;
        m_filling = true;
        m_table->insertRow(from + 1);
        for (int j = 0; j < m_table->columnCount(); ++j) {
            const QTableWidgetItem *source = from >= 0 ? m_table->item(from, j) : nullptr;
            m_table->setItem(from + 1, j,
                             new QTableWidgetItem(source ? source->text() : QStringLiteral("0")));
        }
        m_filling = false;
        emit edited();
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int row =
            m_table->currentRow() >= 0 ? m_table->currentRow() : m_table->rowCount() - 1;
        if (row < 0)
            return;
        m_table->removeRow(row);
        emit edited();
    });
}

double WaypointEditor::scale(int joint) const
{
    return joint < m_prismatic.size() && m_prismatic.at(joint) ? 1.0 : 180.0 / M_PI;
}

void WaypointEditor::setPath(const JointPathSettings &path, const QStringList &jointNames,
                             const QList<bool> &prismatic, bool urdf)
{
    m_filling = true;
    m_prismatic = prismatic;
    m_table->clear();
    m_table->setColumnCount(int(jointNames.size()));
    for (int j = 0; j < jointNames.size(); ++j) {
        auto *title = new QTableWidgetItem(
            tr("q%1 [%2]").arg(j + 1).arg(scale(j) == 1.0 ? tr("m") : tr("deg")));
        title->setToolTip(jointNames.at(j));
        m_table->setHorizontalHeaderItem(j, title);
    }
    const std::vector<Eigen::VectorXd> &waypoints = path.waypoints;
    m_table->setRowCount(int(waypoints.size()));
    for (int i = 0; i < int(waypoints.size()); ++i)
        for (int j = 0; j < waypoints[size_t(i)].size() && j < jointNames.size(); ++j)
            m_table->setItem(
                i, j,
                new QTableWidgetItem(QString::number(waypoints[size_t(i)][j] * scale(j), 'g', 10)));
    m_filling = false;
    const bool table = path.kind == PathKind::Waypoints, file = path.kind == PathKind::File;
    m_table->setVisible(table);
    m_add->setVisible(table);
    m_remove->setVisible(table);
    m_file->setVisible(file);
    m_file->setText(file ? tr("Path: %1 (%2 samples)").arg(path.file).arg(path.fileTimes.size())
                         : QString());
    m_choosePathFile->setVisible(urdf);
    m_useWaypoints->setVisible(urdf && file);
    showReason(QString());
}

bool WaypointEditor::readInto(JointPathSettings &path, QString *error)
{
    if (path.kind != PathKind::Waypoints)
        return true;
    QString why;
    const auto read = waypoints(&why);
    showReason(why);
    if (!read) {
        *error = QStringLiteral("path.waypoints: ") + why;
        return false;
    }
    path.waypoints = *read;
    return true;
}

void WaypointEditor::showLimitError(const QString &error)
{
    static const QRegularExpression cell(
        QStringLiteral("^path\\.waypoints\\[(\\d+)\\]\\[(\\d+)\\]"));
    const auto match = cell.match(error);
    showReason(error, match.hasMatch() ? match.captured(1).toInt() : -1,
               match.hasMatch() ? match.captured(2).toInt() : -1);
}

std::optional<std::vector<Eigen::VectorXd>> WaypointEditor::waypoints(QString *error) const
{
    std::vector<Eigen::VectorXd> out;
    for (int i = 0; i < m_table->rowCount(); ++i) {
        Eigen::VectorXd w(m_table->columnCount());
        for (int j = 0; j < m_table->columnCount(); ++j) {
            const QTableWidgetItem *item = m_table->item(i, j);
            const QString text = item ? item->text().trimmed() : QString();
            bool ok = false;
            const double v = text.toDouble(&ok); // C locale, as the rest of the form
            if (!ok || !std::isfinite(v)) {
                *error = tr("waypoint %1, %2: \"%3\" is not a number")
                             .arg(i + 1)
                             .arg(m_table->horizontalHeaderItem(j)->toolTip(), text);
                return std::nullopt;
            }
            w[j] = v / scale(j);
        }
        out.push_back(w);
    }
    return out;
}

void WaypointEditor::showReason(const QString &reason, int row, int column)
{
    m_reason->setText(reason);
    m_reason->setHidden(reason.isEmpty());
    const bool filling = m_filling;
    m_filling = true; // colouring a cell is no edit
    for (int i = 0; i < m_table->rowCount(); ++i)
        for (int j = 0; j < m_table->columnCount(); ++j)
            if (QTableWidgetItem *item = m_table->item(i, j))
                item->setBackground(i == row && j == column ? QBrush(QColor(0xf9, 0xde, 0xdc))
                                                            : QBrush());
    m_filling = filling;
}

void WaypointEditor::setEditable(bool editable)
{
    m_table->setEditTriggers(editable ? QAbstractItemView::AllEditTriggers
                                      : QAbstractItemView::NoEditTriggers);
    m_add->setEnabled(editable);
    m_remove->setEnabled(editable);
    m_choosePathFile->setEnabled(editable);
    m_useWaypoints->setEnabled(editable);
}

} // namespace learnid
