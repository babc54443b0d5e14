#pragma once

#include "types/RobotLog.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace learnid {

/// Which columns of a robot's log hold what: the time column's name, and name patterns in which
/// %1 stands for the joint number 1..n. An empty velocity pattern: the velocities are not read.
struct LogColumns
{
    QString time = QStringLiteral("t");
    QString position = QStringLiteral("q%1");
    QString velocity = QStringLiteral("dq%1");
    QString torque = QStringLiteral("tau%1");
};

/// The text of the `--columns` option, e.g. `t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1`:
/// comma-separated key=pattern entries with the keys t, q, dq and tau; a key not given keeps
/// its default (LogColumns), `dq=` (empty) reads no velocities. Throws Error "--columns: ..."
/// naming the entry for an unknown or repeated key, an entry without '=', a q, dq or tau pattern
/// without %1, and an empty t.
LogColumns parseLogColumns(const QString &spec);

/// The largest |q| [rad] accepted for a revolute joint: 1.05 turns. Beyond it the log is taken
/// to hold degrees.
constexpr double maxLoggedAngle = 2.0 * 3.14159265358979323846 * 1.05;
/// The largest |dq| [rad/s] accepted for a revolute joint; no robot joint turns that fast
/// (5730 deg/s), a velocity logged in deg/s soon does.
constexpr double maxLoggedAngularVelocity = 100.0;

/// A robot's log as CSV, as its controller recorded it: a header line naming the columns, then
/// one row per sample. The columns are found by name (columns: the time, then per joint
/// j = 1..joints the position, the velocity if the log has any, and the torque); other columns
/// are ignored and not even read as numbers. The velocities are optional: a log without the
/// column of joint 1's velocity has none (dq is 0 x 0). Lines whose first non-blank character is
/// '#' and blank lines are skipped, \r\n is accepted, spaces around fields are ignored, a UTF-8
/// byte order mark is skipped; numbers as QByteArray::toDouble reads them (C locale).
///
/// A row with the same time as the sample before and the same values in every column read is a
/// repeat the logger wrote twice: it is dropped and counted (RobotLog::repeatedSamples). A row
/// with a new time stamp but exactly the values of the sample before (every value read: q, dq if
/// read, tau, all joints) is stale, a logger that sampled a state the controller had not updated:
/// it is dropped too and its line kept in RobotLog::staleRows, so that the grid interpolates
/// across it as across a missing sample (the gap rule of resampleUniform() then applies to the
/// gap it leaves). Sensor noise makes exact repeats of every value vanishingly rare on a real
/// robot; a noise-free log of a robot at rest looks stale too, and a rest longer than the
/// gap allowed is then refused, the message naming the repeating lines.
///
/// angular: one flag per joint, true for a revolute joint (empty: no unit check). For those,
/// |q| beyond maxLoggedAngle or |dq| beyond maxLoggedAngularVelocity is refused as degrees.
///
/// Throws Error "<source>: ..." for joints < 1, angular of another size than joints, and columns
/// that parseLogColumns() would refuse; "<source>: line <L>: ..." for the header (a missing or
/// repeated column name, position columns for another number of joints than `joints`, velocities of
/// some joints only), an empty file and fewer than 4 samples (stale rows not counted), and
/// "<source>: line <L>, column <C>
/// (<name>): ..." for a wrong number of fields, a field that is not a finite number, a time that
/// does not increase, a repeated time with other values, and degrees where radians are expected.
/// What readRobotLog() does with stale rows: Drop them (a logger's log, the default), or Keep
/// them as samples (a log that must hold every sample of a known grid, written by the controller
/// itself: a noise-free simulation at rest repeats its values exactly, io/ControllerLogCsv.h).
enum class StaleRows { Drop, Keep };

RobotLog readRobotLog(const QByteArray &csv, const QString &source, int joints,
                      const LogColumns &columns = {}, const QList<bool> &angular = {},
                      StaleRows stale = StaleRows::Drop);

/// readFile() then readRobotLog() with the path as the source; a missing or unreadable file
/// throws Error naming the path and the reason.
RobotLog readRobotLogFile(const QString &path, int joints, const LogColumns &columns = {},
                          const QList<bool> &angular = {});

} // namespace learnid
