#pragma once

#include "types/Trial.h"

#include <Eigen/Core>
#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>
#include <QVector>

namespace learnid {

/// One trial as CSV (docs/file-formats.md). Header
///   t_s,qd1_rad,q1_rad,e1_deg,tauf1_Nm,tau1_Nm,qd2_rad,...
/// then one row per recorded sample k: t_k = k Ts [s], and per joint j the desired angle
/// q_d [rad] (not a velocity), the measured angle q [rad], the tracking error q_d - q [deg], the
/// feedforward torque tau_f [N m] and the measured torque tau [N m]. A record that ended early
/// has as many rows as it has samples. Numbers are written in the shortest form that reads back
/// to the same double; non-finite measurements as nan, inf, -inf. Lines end with \n.
/// Throws Error when the record does not fit the plan (joints, more samples than planned).
QByteArray trialCsv(const TrialPlan &plan, const TrialRecord &record);

/// A trial CSV read back: the columns by name, sample k in column k.
struct TrialRecordCsv
{
    Eigen::VectorXd t;                ///< [s] (N)
    Eigen::MatrixXd qDesired;         ///< q_d [rad] (n x N)
    Eigen::MatrixXd q;                ///< [rad] (n x N)
    Eigen::MatrixXd trackingErrorDeg; ///< q_d - q [deg] (n x N)
    Eigen::MatrixXd feedforward;      ///< tau_f [N m] (n x N)
    Eigen::MatrixXd tau;              ///< [N m] (n x N)

    int dof() const { return int(q.rows()); }
    int samples() const { return int(q.cols()); }
    /// t_1 - t_0 [s]; 0 with fewer than two samples.
    double samplePeriod() const { return t.size() > 1 ? t[1] - t[0] : 0.0; }
    /// The measured part as a TrialRecord. The CSV does not hold the status: it is Completed
    /// unless the caller knows better.
    TrialRecord record() const;
};

/// Reads a trial CSV as trialCsv() writes it (\r\n accepted). Throws Error
/// "<sourceName>: line <L>: <problem>" for a wrong header, a wrong number of fields, a field
/// that is not a number, or times that do not increase.
TrialRecordCsv readTrialCsv(const QByteArray &csv, const QString &sourceName);

/// readFile() then readTrialCsv() with the path as the source name.
TrialRecordCsv readTrialCsvFile(const QString &path);

} // namespace learnid
