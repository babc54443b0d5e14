#pragma once
// Test support for the learning loop through files (`learnid-cli plan` / `learn`): the robot's
// own controller played by a simulated robot that only exchanges plan and log files.

#include "io/PlanCsv.h"
#include "types/Scenario.h"
#include "types/Trial.h"

#include <QByteArray>
#include <QLocale>
#include <QString>
#include <cmath>

namespace learnid::test {

/// A number as the controller logs it: the shortest form that reads back to the same double.
inline QByteArray shortestNumber(double v)
{
    return QByteArray::number(v, 'g', QLocale::FloatingPointShortest);
}

/// What the other controller makes of plan.csv: the trajectory and feedforward it runs, with
/// its own gains and limits (here the scenario's, as the session's robot gets them).
inline TrialPlan planFromCsv(const PlanCsv &csv, const Scenario &scenario)
{
    TrialPlan plan;
    plan.desired.samplePeriod = csv.samplePeriod;
    plan.desired.q = csv.qDesired;
    plan.desired.qd = Eigen::MatrixXd::Zero(csv.joints(), csv.samples());
    plan.desired.qdd = Eigen::MatrixXd::Zero(csv.joints(), csv.samples());
    plan.feedforward = csv.feedforward;
    plan.feedforwardParameters = csv.estimate;
    plan.controller = scenario.controller;
    plan.torqueLimit = scenario.torqueLimits;
    plan.maxTrackingError = scenario.maxTrackingErrorDeg * M_PI / 180.0;
    return plan;
}

/// The controller's log: its own comment, the plan-id line copied from the plan, then one row
/// per sample (extra columns ignored by learn); samples < 0: all of the record's; joints < 0:
/// all of the record's joints.
inline QByteArray logCsv(const QString &planId, const TrialRecord &record, int samples = -1,
                         int joints = -1)
{
    const int n = joints < 0 ? int(record.q.rows()) : joints;
    QByteArray out = "# logged by the other controller\n# plan-id: " + planId.toLatin1() + '\n';
    out += "t,status";
    for (int j = 1; j <= n; ++j)
        out += ",q" + QByteArray::number(j);
    for (int j = 1; j <= n; ++j)
        out += ",tau" + QByteArray::number(j);
    out += '\n';
    for (int k = 0; k < (samples < 0 ? record.samples() : samples); ++k) {
        out += shortestNumber(k * record.samplePeriod) + ",ok";
        for (int j = 0; j < n; ++j)
            out += ',' + shortestNumber(record.q(j, k));
        for (int j = 0; j < n; ++j)
            out += ',' + shortestNumber(record.tau(j, k));
        out += '\n';
    }
    return out;
}

} // namespace learnid::test
