#pragma once

#include <Eigen/Core>
#include <QWidget>
#include <optional>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace learnid {

/// The joint waypoints of a path as a table: a row per waypoint, a column per joint, revolute
/// joints in degrees and prismatic ones in metres (the scenario keeps radians and metres).
/// Every edit is parsed at once; the form checks the joint limits and shows the reason here,
/// marking the cell.
class WaypointEditor : public QWidget
{
    Q_OBJECT

public:
    explicit WaypointEditor(QWidget *parent = nullptr);

    /// jointNames: the column titles; prismatic: per joint, true for metres.
    void setWaypoints(const std::vector<Eigen::VectorXd> &waypoints, const QStringList &jointNames,
                      const QList<bool> &prismatic);
    /// The waypoints in radians and metres, or nullopt with error naming the cell.
    std::optional<std::vector<Eigen::VectorXd>> waypoints(QString *error) const;
    /// Shows why the waypoints are refused ("" clears it); marks waypoint row, joint column
    /// when both are >= 0.
    void showReason(const QString &reason, int row = -1, int column = -1);
    void setEditable(bool editable);
    QTableWidget *table() const { return m_table; }

signals:
    void edited();

private:
    double scale(int joint) const; ///< display unit per scenario unit

    QTableWidget *m_table;
    QPushButton *m_add;
    QPushButton *m_remove;
    QLabel *m_reason;
    QList<bool> m_prismatic;
    bool m_filling = false;
};

} // namespace learnid
