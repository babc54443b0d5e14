#pragma once

#include "io/ParameterFile.h"
#include "model/ChainModel.h"
#include "session/CommissioningSession.h"

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>

namespace learnid {

/// What to export from a session; an empty path leaves that output out.
struct ExportRequest
{
    QString reportPath;     ///< the session report (JSON, docs/file-formats.md)
    QString parameterPath;  ///< the parameter file (JSON); its DCF fragment goes beside it (.dcf)
    int estimateIndex = -1; ///< the estimate of the parameter file; -1: the last one
    /// The parameter file holds the estimate's nearest physically consistent estimate (URDF
    /// robots, CommissioningSession::consistency), without standard deviations.
    bool nearestConsistent = false;
    QString trialCsvDir; ///< trial-NNN.csv of every trial that moved
    /// The robot's URDF with the estimate's physically consistent standard parameters (the
    /// estimate completed by the CAD model when it is consistent, else its nearest consistent
    /// estimate) and friction in <dynamics>: URDF robots only.
    QString urdfPath;
    QString urdfComment; ///< who made it and when, for the URDF's leading comment
    /// Why the session ended before its trials were done (the report says so); empty: it did
    /// not.
    QString endedEarly;
};

/// The URDF xml (read from source) with the links and joint terms of standard parameters pi of
/// model (ChainModel's layout): identifiedUrdf() with pi's bodies, friction, armature and
/// offsets, and determinedNotes() of the shares `determined` (empty: no such comment).
QByteArray urdfWithStandard(const ChainModel &model, const QByteArray &xml, const QString &source,
                            const Eigen::VectorXd &pi, const QString &comment,
                            const std::vector<double> &determined = {});

/// The files of a request, built in memory (path, content), so that the caller writes all or
/// none (writeFilesAtomically). The one export path of the window and learnid-cli. Throws
/// Error naming what cannot be exported (an estimate that does not exist, a value a DCF cannot
/// carry).
QList<QPair<QString, QByteArray>> exportFiles(const CommissioningSession &session,
                                              const ExportRequest &request);

/// Writes the files of a request, all or none (the trial CSV folder is created first), and
/// returns their paths. Throws Error naming the file or folder that could not be written.
QStringList writeExport(const CommissioningSession &session, const ExportRequest &request);

/// The CSV of every trial of a history that measured something, as (folder/trial-NNN.csv,
/// content) pairs for writeFilesAtomically(). Refused trials (nothing moved) have no file.
QList<QPair<QString, QByteArray>> trialCsvFiles(const QVector<TrialResult> &history,
                                                const QString &folder);

/// Where trial `index`'s CSV goes in folder: trial-NNN.csv.
QString trialCsvPath(const QString &folder, int index);

/// Where the DCF fragment of a parameter file goes: beside it, same base name, .dcf.
QString dcfPathFor(const QString &parameterPath);

/// Appends the parameter file (JSON) at `path` and its DCF fragment beside it (dcfPathFor).
void appendParameterFiles(QList<QPair<QString, QByteArray>> &files, const QString &path,
                          const ParameterFileContent &content);

/// Writes the files all or none (writeFilesAtomically) and returns their paths.
QStringList writeExportFiles(const QList<QPair<QString, QByteArray>> &files);

} // namespace learnid
