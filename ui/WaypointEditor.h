#pragma once

#include "types/ChainSettings.h"

#include <Eigen/Core>
#include <QWidget>
#include <optional>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace learnid {

/// The joint path of a URDF robot: its waypoints as a table, a row per waypoint, a column per
/// joint, revolute joints in degrees and prismatic ones in metres (the scenario keeps radians
/// and metres), or the name of a recorded path file; buttons to switch between them. Every edit
/// is parsed at once; the form checks the joint limits and shows the reason here, marking the
/// cell.
class WaypointEditor : public QWidget
{
    Q_OBJECT

public:
    explicit WaypointEditor(QWidget *parent = nullptr);

    /// jointNames: the column titles' tooltips; prismatic: per joint, true for metres; urdf:
    /// offer the path file (the paper's arm runs its line).
    void setPath(const JointPathSettings &path, const QStringList &jointNames,
                 const QList<bool> &prismatic, bool urdf);
    /// Reads the waypoint table into path (kind Waypoints; other kinds stay as they are); on a
    /// cell that is no number shows why and sets error ("path.waypoints: ...").
    bool readInto(JointPathSettings &path, QString *error);
    /// Shows a waypointLimitError() ("path.waypoints[i][j]: ..."), marking waypoint i, joint j.
    void showLimitError(const QString &error);
    /// The waypoints in radians and metres, or nullopt with error naming the cell.
    std::optional<std::vector<Eigen::VectorXd>> waypoints(QString *error) const;
    /// Shows why the waypoints are refused ("" clears it); marks waypoint row, joint column
    /// when both are >= 0.
    void showReason(const QString &reason, int row = -1, int column = -1);
    void setEditable(bool editable);
    QTableWidget *table() const { return m_table; }

signals:
    void edited();
    /// The technician chose a recorded path file (CSV t, q1..qn), or asked for waypoints again.
    void pathFileChosen(const QString &path);
    void waypointsChosen();

private:
    double scale(int joint) const; ///< display unit per scenario unit

    QTableWidget *m_table;
    QPushButton *m_add;
    QPushButton *m_remove;
    QLabel *m_reason;
    QLabel *m_file;
    QPushButton *m_choosePathFile;
    QPushButton *m_useWaypoints;
    QList<bool> m_prismatic;
    bool m_filling = false;
};

} // namespace learnid
