#pragma once

#include "identify/LogFit.h"
#include "identify/LogSignals.h"
#include "identify/UniformLog.h"
#include "io/ParameterFile.h"
#include "io/RobotLogCsv.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/SerialChain.h"
#include "session/EstimateConsistency.h"
#include "types/ChainSettings.h"
#include "types/ControllerSettings.h"

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace learnid {

/// What to identify from recorded logs, for both front ends (the window's "Identify from
/// recorded data", `learnid-cli identify`; docs/cli.md, docs/identify.md).
struct LogIdentificationRequest
{
    QString robot;    ///< a built-in URDF robot id (builtInUrdfRobots()) or a URDF file
    QString baseLink; ///< empty: the URDF's root link
    QString tipLink;  ///< empty: the one leaf below the base
    JointTerms terms{false, true, true, true}; ///< viscous, Coulomb friction and an offset
    QStringList trainingLogs;                  ///< the logs fitted together (at least one)
    QStringList validationLogs;                ///< the logs the result is checked on
    LogColumns columns;                        ///< the same for every log
    LogFilterSettings filter;
    LogFitSettings fit;
    ResampleOptions resample;
};

/// The robot a request names, read: its URDF text (the identified URDF edits it) and the model.
struct LogRobot
{
    QString modelId; ///< the parameter file's robot.model: the built-in id, or "urdf"
    QString source;  ///< the URDF in messages: "built-in <id>" or the file's native path
    QByteArray urdf; ///< the URDF as given
    SerialChain chain;
    std::shared_ptr<const ChainModel> model; ///< chain with the request's joint terms
    /// What is wrong with the URDF's own values as a real robot's (modelWarnings()): the prior
    /// is used all the same, the report lists them.
    QStringList warnings;
};

/// One validation log predicted with the URDF as given and with the identified parameters. The
/// torques are filtered alike, as the figures count them (LogFit.h: F(s)F(-s), edges cut).
struct LogValidation
{
    QString source;                      ///< the log's path
    Eigen::VectorXd time;                ///< K: time of each kept sample [s]
    Eigen::MatrixXd measured;            ///< n x K [N m] or [N]
    Eigen::MatrixXd predictedGiven;      ///< n x K: the URDF as given
    Eigen::MatrixXd predictedIdentified; ///< n x K: the identified standard parameters
    TorqueFigures given;
    TorqueFigures identified;

    Eigen::Index samples() const { return time.size(); }
};

/// How one log was read: the rows the reader dropped (io/RobotLogCsv.h).
struct LogReading
{
    QString source;           ///< the log's path
    Eigen::Index samples = 0; ///< the samples kept
    int repeated = 0;         ///< rows written twice (the same time, the same values), dropped
    int stale = 0; ///< stale rows (the values before under a new time stamp), treated as missing
};

/// What an identification from logs produced. Nothing of it is written anywhere until
/// logExportFiles()/writeLogExport() is asked to.
struct LogIdentificationResult
{
    LogRobot robot;
    QStringList trainingLogs; ///< the paths fitted, in order
    LogFit fit;
    /// The verdict on the identified standard parameters themselves, one line per problem or
    /// one that they are consistent (EstimateConsistency::describe()).
    QStringList consistency;
    bool consistent = false;
    /// The same per link: consistent, and plausible (LinkVerdictTable.h shows it).
    EstimateConsistency verdict;
    QStringList undetermined; ///< names of the base parameters the logs leave undetermined
    std::vector<LogValidation> validation; ///< one per validation log, in order
    std::vector<LogReading> readings;      ///< the training logs, then the validation logs

    const ChainModel &model() const { return *robot.model; }
};

/// The stages an identification goes through, in order; progress is reported as each begins.
enum class LogIdentificationStage {
    Robot,          ///< reading the URDF (identifyFromLogs(request) only)
    ReadTraining,   ///< reading, resampling and filtering training log `index`
    ReadValidation, ///< the same for validation log `index`
    Fit,            ///< fitting the parameters to all training logs
    Validate,       ///< predicting validation log `index` with both parameter sets
};

struct LogIdentificationProgress
{
    LogIdentificationStage stage = LogIdentificationStage::Robot;
    int index = 0; ///< the log's number within its stage (0-based); 0 for Robot and Fit
    int count = 0; ///< the logs of that stage; for Fit the training logs
    QString path;  ///< the log (or for Robot the URDF) this stage reads
    int step = 0;  ///< stages begun before this one
    int steps = 0; ///< all stages of the run
};

/// Called as each stage begins, in the thread that runs the identification.
using LogIdentificationObserver = std::function<void(const LogIdentificationProgress &)>;

/// Thrown when the cancel flag was found set between two stages: nothing was produced.
class LogIdentificationCancelled : public Error
{
public:
    LogIdentificationCancelled();
};

/// The built-in robots that can be identified from logs (URDF models of ModelFactory.h).
QStringList builtInUrdfRobots();

/// The robot of request.robot, base/tip and terms. Throws Error when it is neither a built-in
/// robot nor a URDF file, or the URDF cannot be read or is not a serial arm (naming the file).
LogRobot loadLogRobot(const LogIdentificationRequest &request);

/// The pipeline of `learnid-cli identify` (bench/realdata.cpp): every log read
/// (readRobotLogFile: revolute angles beyond 1.05 turns refused as degrees, stale rows dropped),
/// resampled (resampleUniform; the default gap allowed follows request.filter.rho,
/// defaultMaxGap()) and filtered (filterLog), the training logs fitted together (fitLogs),
/// the validation logs predicted with the URDF as given and the fit (torqueFigures). observer
/// hears of each stage as it begins; cancel (may be null) is read before each stage and once
/// more at the end: when set, LogIdentificationCancelled is thrown. Throws Error for no
/// training log and whatever the reading, fitting and validating throw (a log's message names
/// its file, line and column).
LogIdentificationResult identifyFromLogs(const LogRobot &robot,
                                         const LogIdentificationRequest &request,
                                         const LogIdentificationObserver &observer = {},
                                         const std::atomic<bool> *cancel = nullptr);
/// loadLogRobot() (stage Robot) then the above.
LogIdentificationResult identifyFromLogs(const LogIdentificationRequest &request,
                                         const LogIdentificationObserver &observer = {},
                                         const std::atomic<bool> *cancel = nullptr);

/// What to export from an identification; an empty path leaves that file out.
struct LogExportRequest
{
    QString parameterPath; ///< the parameter file (JSON); its DCF fragment beside it
    /// The gains the parameter file records (logs do not say; a scenario may); none: the file
    /// holds the model alone ("controller": null).
    std::optional<ControllerSettings> controller;
    QString urdfPath;    ///< the robot's URDF with the identified bodies and joint terms
    QString urdfComment; ///< who made it and when, for the URDF's leading comment
};

/// The parameter file of the identification: robot.model the built-in id or "urdf", nodes
/// 1..n, the controller's gains when given, law "improved" (its filter prepares the logs), no
/// source trial, the identified base parameters, the whole model as standard parameters
/// (offsets included) with what the data determined (LogFit::standardDetermined), the
/// training residual, the fit's condition and rank, and the CAN writes of an apply.
ParameterFileContent logParameterFile(const LogIdentificationResult &result,
                                      const std::optional<ControllerSettings> &controller);

/// The robot's URDF as given with each moving body the identified one, each joint's <dynamics>
/// its identified viscous and Coulomb friction and learnid's element its armature and offset (0
/// for a term the model leaves out), and a comment on what the data determined;
/// identifiedUrdf() checks it reads back.
QByteArray logIdentifiedUrdf(const LogIdentificationResult &result, const QString &comment);

/// The files of a request, built in memory (path, content), so that the caller writes all or
/// none (writeFilesAtomically): the parameter file and its DCF, the URDF. Throws Error naming
/// what cannot be exported (gains for another joint count, a value a DCF cannot carry, a path
/// given twice).
QList<QPair<QString, QByteArray>> logExportFiles(const LogIdentificationResult &result,
                                                 const LogExportRequest &request);

/// Writes the request's files all or none (writeFilesAtomically) and returns their paths.
QStringList writeLogExport(const LogIdentificationResult &result, const LogExportRequest &request);

} // namespace learnid
