#pragma once

#include "io/ParameterFile.h"
#include "service/LogIdentification.h"
#include "service/PayloadRun.h"

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>

namespace learnid {

/// The parameter file of a payload learned in the window (docs/file-formats.md, "Payload
/// section"): the arm's model as the run held it fixed (the scenario's initial parameters as
/// base and standard parameters, their CAN writes), the scenario's controller gains, the payload
/// section (payloadSection(): per value whether the trials identified it and its standard
/// error), and as quality the learned trial's tracking errors and the payload fit's residual per
/// joint, condition and rank (of the payload's 10 directions).
ParameterFileContent payloadRunParameterFile(const PayloadRunResult &result);

/// The robot's URDF with the arm's standard parameters as the run held them and the payload as
/// a link fixed to its link (urdfWithPayload()); comment: who made it and when.
QByteArray payloadRunUrdf(const PayloadRunResult &result, const QString &comment);

/// The files of request (the parameter file and its DCF fragment, the URDF; its controller is
/// not used: the scenario's gains are), built in memory so that the caller writes all or none
/// (writeFilesAtomically). Throws Error naming what cannot be exported.
QList<QPair<QString, QByteArray>> payloadRunExportFiles(const PayloadRunResult &result,
                                                        const LogExportRequest &request);

/// The CSV of every trial of a payload session that measured something (baseline trials
/// included), as (folder/trial-NNN.csv, content) pairs for writeFilesAtomically(): the format of
/// the arm's session (trialCsv()), its feedforward the arm plus the payload that trial used.
QList<QPair<QString, QByteArray>> payloadTrialCsvFiles(const std::vector<PayloadTrial> &history,
                                                       const QString &folder);

/// Writes the request's files all or none and returns their paths; throws Error naming the file.
QStringList writePayloadRunExport(const PayloadRunResult &result, const LogExportRequest &request);

/// Where the trial CSVs of a run's record go: beside the report, in a folder named after it
/// (run.json -> run-trials/).
QString payloadRecordTrialFolder(const QString &reportPath);

/// Writes a run's record, all or none: its report (learnid-payload-report/1) at reportPath and
/// its trial CSVs in payloadRecordTrialFolder(reportPath), created first. Returns the paths;
/// throws Error naming the file or folder that could not be written.
QStringList writePayloadRecord(const PayloadRunRecord &record, const QString &reportPath);

} // namespace learnid
