#pragma once

#include "io/ParameterFile.h"
#include "session/CommissioningSession.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonValue>

namespace learnid {

/// A figure of a report (JSON): non-finite as null, as JSON has no NaN or inf.
QJsonValue reportNumber(double value);
/// Figures of a report, each as reportNumber().
QJsonArray reportNumbers(const Eigen::VectorXd &values);

/// The session report (docs/file-formats.md): robot, estimator, truth (simulated robot only),
/// one entry per trial run with estimate k (phi = estimate after k learnings, the trial's
/// tracking error, duration and samples, and the figures of the fit made from that trial:
/// condition, rank, residualRms, phiStd), and the final estimate. Non-finite figures (the
/// standard deviation of a parameter the path does not observe) are written as null.
/// A trial learned from as far as the tracking limit let it run is marked
/// ("learnedFromPartialTrial", "learnedSeconds"); "proposedEstimate" is the estimate Accept
/// proposes (TrialSeries.h). endedEarly: why the session ended before its trials were done,
/// written as "endedEarly" (empty: it did not).
QByteArray sessionReportJson(const CommissioningSession &session, const QString &endedEarly = {});

/// The parameter file content for estimate k of a session (k >= 1), with the quality figures of
/// the trials that produced it and the SDO writes that apply performs.
ParameterFileContent parameterFileContent(const CommissioningSession &session, int estimateIndex,
                                          const QList<SdoWrite> &canWrites);

/// The same with the writes a CAN robot with one drive per joint, nodes 1..n, receives on apply
/// (can/ManufacturerObjects.h).
ParameterFileContent parameterFileContent(const CommissioningSession &session, int estimateIndex);

} // namespace learnid
