#pragma once

#include "types/Trial.h"

#include <Eigen/Core>
#include <QByteArray>
#include <QString>

namespace learnid {

/// The first line of every plan file this version writes and reads.
inline constexpr char planCsvSchema[] = "learnid-plan/1";

/// The next trial as a robot's own controller runs it ("bring your own controller",
/// docs/file-formats.md "Plan CSV"): comment lines
///   # learnid-plan/1
///   # plan-id: <64 lower-case hex digits>
///   # robot: <model id>, <n> joints
///   # sample-period: <Ts>
///   # estimate: <phi_1>, ..., <phi_m>
/// then the header `t,qd1..qdn,tauf1..taufn` and one row per sample k of the plan: t = k Ts [s],
/// the desired angles q_d [rad] (not velocities) and the feedforward torques tau_f [N m].
struct PlanCsv
{
    QString planId;              ///< planIdOfData() of the lines from the header on
    QString robotModel;          ///< model id, e.g. "paper-2link"
    double samplePeriod = 0.0;   ///< Ts [s]
    Eigen::VectorXd estimate;    ///< phi_hat the feedforward was built with (m)
    Eigen::VectorXd t;           ///< t_k = k Ts [s] (N)
    Eigen::MatrixXd qDesired;    ///< q_d [rad] (n x N)
    Eigen::MatrixXd feedforward; ///< tau_f [N m] (n x N)

    int joints() const { return int(qDesired.rows()); }
    int samples() const { return int(qDesired.cols()); }
};

/// The plan file of a plan. Numbers are written in the shortest form that reads back to the same
/// double; lines end with \n. Throws Error when the plan is empty, its sizes disagree or a number
/// is not finite.
QByteArray planCsv(const TrialPlan &plan, const QString &robotModel);

/// The plan-id of a plan: what planCsv() writes on its `# plan-id:` line.
QString planIdOf(const TrialPlan &plan);

/// Lower-case hex SHA-256 of the lines of a plan file from the header on, each ended by \n (a \r
/// at a line's end is not part of the line).
QString planIdOfData(const QByteArray &dataLines);

/// Reads a plan file as planCsv() writes it (\r\n accepted). Throws Error "<source>: line <L>:
/// ..." for a missing or wrong first line, a missing, repeated or malformed `# key:` line, a
/// header other than that of the robot's joints, a blank or comment line after the header, no
/// samples, and a plan-id that is not that of the numbers (a plan changed after it was written);
/// "<source>: line <L>, column <C> (<name>): ..." for a wrong number of fields, a field that is
/// not a finite number and a time other than k Ts.
PlanCsv readPlanCsv(const QByteArray &csv, const QString &source);

/// readFile() then readPlanCsv() with the path as the source.
PlanCsv readPlanCsvFile(const QString &path);

/// The id on a file's `# plan-id: <id>` comment line, as a controller copies it from the plan
/// into its log; empty when there is none. Throws Error "<source>: line <L>: ..." for an id that
/// is not 64 hex digits or a second plan-id line naming another plan.
QString planIdLine(const QByteArray &csv, const QString &source);

} // namespace learnid
