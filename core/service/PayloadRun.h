#pragma once

#include "identify/PayloadFit.h"
#include "model/ChainModel.h"
#include "model/PayloadPrior.h"
#include "service/RobotRequest.h"
#include "service/TrackingErrorData.h"
#include "session/PayloadSession.h"
#include "types/Scenario.h"

#include <Eigen/Core>
#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>
#include <array>
#include <limits>
#include <memory>
#include <vector>

namespace learnid {

// The window's payload step (docs/payload.md, "In the window"): the learning loop with the
// payload mounted on the simulated robot, as `learnid-cli run` runs a scenario's payload section.
// Value types only, so that they cross from the job's thread to the window's.

/// A payload session on a robot and the arm's model it holds fixed.
struct PayloadRunSession
{
    std::shared_ptr<const ChainModel> model;
    std::unique_ptr<PayloadSession> session; ///< null when the robot could not be reached
    QString connectError;                    ///< why the robot could not be reached
};

/// The session of scenario `given` (its payload section enabled) as `learnid-cli run` builds it:
/// withRobotDefaults(), the simulated robot carrying simulation.payload, and the same robot
/// without it for the baseline trials (payload.baselineTrials). Throws Error naming the key:
/// no payload section, an unknown robot model, a scenario that does not fit, a refused prior.
PayloadRunSession makeSimulatedPayloadSession(const Scenario &given);

/// The session of scenario `given` on the CAN robot of `request` (makeRobot(): connected here;
/// when it cannot be reached, no session and connectError says why). Its baseline trials
/// (payload.baselineTrials) run on the same robot: the caller has the technician take the
/// payload off before them and mount it after them (PayloadSession::nextTrialIsBaseline()).
/// Throws Error naming the key as makeSimulatedPayloadSession() does.
PayloadRunSession makeCanPayloadSession(const Scenario &given, const RobotRequest &request);

/// What the technician does before trial `trial` (from 0, baselines first) on a robot that
/// carries the payload itself (the CAN robot), with `baselineTrials` baseline trials: take the
/// payload off before the first of them, mount it before the first payload trial.
enum class PayloadMounting { Unchanged, TakeOff, Mount };
PayloadMounting payloadMountingBefore(int trial, int baselineTrials);

/// What the path lets the trials see before any motion (PayloadSession::observability()), and
/// the next trial's check.
struct PayloadPreview
{
    QString robotDescription; ///< the simulated robot in words
    QString link;             ///< the payload's link (the tip when the scenario names none)
    QString bound;            ///< PayloadBound::describe()
    int baselineTrials = 0;
    int trials = 0; ///< payload trials (scenario iterations)
    PayloadObservability observability;
    /// observability.advice(link): what the path does not see and why; then the smallest
    /// change of the path that would measure it (PayloadSession::pathChange), if one does
    QStringList advice;
    QString checkReason;    ///< why the first trial would be refused; empty: it passes
    QStringList jointNames; ///< the arm's, in joint order (as its URDF has them)
};

/// The preview of a session that has run no trial yet (plans its first trial).
PayloadPreview payloadPreview(PayloadSession &session);

/// One trial of a run as the window's table shows it.
struct PayloadTrialRow
{
    int index = 0;
    bool baseline = false; ///< a baseline trial without the payload
    bool usable = false;   ///< learned from, or a baseline kept
    bool learned = false;
    bool partial = false; ///< stopped at the tracking limit, learned from up to the stop
    double maxTrackingErrorDeg = std::numeric_limits<double>::quiet_NaN(); ///< worst joint
    double rmsTrackingErrorDeg = std::numeric_limits<double>::quiet_NaN(); ///< worst joint
    double mass = std::numeric_limits<double>::quiet_NaN(); ///< the fit after it [kg]
    Eigen::Vector3d com = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    std::array<bool, 10> identified{}; ///< PayloadEstimate::bodyIdentified
    double updateMs = 0.0;             ///< CPU time of the payload's update [ms]
    QString message;                   ///< why it was refused, ended early or not learned from
    /// Its tracking error per joint over time, decimated for a plot (trackingErrorCurves());
    /// empty for a trial that did not move.
    QList<TrackingErrorCurve> curves;
};

PayloadTrialRow payloadTrialRow(const PayloadTrial &trial);

/// A run's record, built in the job's thread: its report (payloadReportJson()) and the CSV of
/// every trial that moved, as (trial-NNN.csv, content) (payloadTrialCsvFiles()). Kept also for a
/// run that ended early, which the technician needs to see what happened.
struct PayloadRunRecord
{
    QByteArray report;
    QList<QPair<QString, QByteArray>> trialCsvs;
    QString
        endedEarly; ///< why the run ended before its last trial (in the report); empty: it did not
};

/// The record of the trials session `s` has run so far; endedEarly as payloadReportJson().
PayloadRunRecord payloadRunRecord(const PayloadSession &s, const QString &endedEarly = {});

/// A run that completed all its trials: the payload after the last one.
struct PayloadRunResult
{
    Scenario scenario; ///< with withRobotDefaults()
    std::shared_ptr<const ChainModel> model;
    QString robotDescription;
    QString link;
    PayloadPrior prior;
    std::vector<PayloadTrialRow> trials;
    int learnedTrial = -1; ///< the trial whose fit is the result
    PayloadFit fit;
    PayloadRunRecord record;             ///< the run's report and trial CSVs
    Eigen::VectorXd maxTrackingErrorDeg; ///< that trial's, per joint [deg] (n)
    Eigen::VectorXd rmsTrackingErrorDeg; ///< per joint [deg] (n)
};

/// The result of a session whose trials all completed; throws Error when none was learned from.
PayloadRunResult payloadRunResult(const PayloadRunSession &run);

/// Writes the result's payload to the session's robot and stores it (Robot::applyPayload: the
/// joint whose body carries the payload's link, the payload moved into that body's frame);
/// returns what failed, or empty.
QString applyRunPayload(const PayloadRunSession &run, const PayloadRunResult &result);

} // namespace learnid
