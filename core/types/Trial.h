#pragma once

#include "types/ControllerSettings.h"
#include "types/JointTrajectory.h"

#include <Eigen/Core>
#include <QString>
#include <atomic>
#include <functional>

namespace learnid {

/// Everything a robot needs to run one trial: the desired trajectory, the model feedforward
/// built from a parameter estimate, the controller and the limits.
struct TrialPlan
{
    JointTrajectory desired;
    /// tau_f = W(q_d, qd_d, qdd_d) phi_hat [N m] (n x N), the desired state taken at t_k or,
    /// with FeedforwardTime::MidSample, at t_k + Ts / 2: column k is held over sample k.
    Eigen::MatrixXd feedforward;
    Eigen::VectorXd feedforwardParameters; ///< phi_hat the feedforward was built with (m)
    ControllerSettings controller;
    Eigen::VectorXd torqueLimit;   ///< [N m] (n); commands saturate here
    double maxTrackingError = 0.0; ///< abort threshold on |q_d - q| [rad]
    double motionDuration = 0.0;   ///< T of the motion between the rests [s]
    /// The joints' position limits [rad or m] and speed limits [rad/s or m/s] (n each; +-inf
    /// where the robot has none); empty: no limits known (the paper's arm).
    Eigen::VectorXd positionLower;
    Eigen::VectorXd positionUpper;
    Eigen::VectorXd velocityLimit;

    int samples() const { return desired.samples(); }
};

enum class TrialStatus {
    Completed, ///< all samples recorded
    Aborted,   ///< stopped by a safety limit (tracking error, missing samples, bus errors)
    Faulted,   ///< the robot reported a fault
    Cancelled, ///< stopped on request
    Refused,   ///< not started: the pre-trial check failed
};

QString trialStatusName(TrialStatus status);

/// What stopped a trial that did not complete. Only a stop at the tracking-error limit leaves a
/// record that is sound up to the stop (the robot did what it was told, only worse than
/// allowed); every other cause may have corrupted the samples before it (a fault, an EMCY, a
/// lost heartbeat, missing samples) or says nothing about the robot (Stop), and is never
/// learned from.
enum class TrialStopCause {
    None,           ///< the trial completed, or was not started
    TrackingLimit,  ///< |q_d - q| exceeded the abort threshold: quick stop
    MissingSamples, ///< samples, SYNCs or frames went missing, or the bus failed
    RobotFault,     ///< a drive fault, an EMCY, a lost heartbeat, a restart
    Operator,       ///< Stop
    Other,          ///< anything else (a log that ended without saying why, a write error)
};

/// The cause a status implies when nothing more specific is known: a fault is the robot's, a
/// cancel the operator's, an abort not known to be the tracking limit is Other.
TrialStopCause defaultStopCause(TrialStatus status);

/// What a robot measured in one trial, sample k at t_k = k * samplePeriod: the joint angles
/// q [rad] and torques tau [N m], both (n x samples()). A trial that ended early keeps the
/// samples recorded up to then.
struct TrialRecord
{
    double samplePeriod = 0.0;
    Eigen::MatrixXd q;
    Eigen::MatrixXd tau;
    TrialStatus status = TrialStatus::Completed;
    QString message; ///< why the trial ended early, in words for the technician
    TrialStopCause stopCause = TrialStopCause::None; ///< what ended it early (None: completed)
    /// Samples at which a drive reported its set-point late (CiA 402 statusword bit 12 clear),
    /// summed over the joints: the drive held the previous one there, so the motion is not
    /// quite the plan's (0 for a simulated robot).
    int lateSetpoints = 0;

    int samples() const { return int(q.cols()); }
    bool completed() const { return status == TrialStatus::Completed; }
    /// Stopped by the tracking-error limit: the samples up to the stop may be learned from.
    bool stoppedAtTrackingLimit() const
    {
        return status == TrialStatus::Aborted && stopCause == TrialStopCause::TrackingLimit;
    }
};

/// Progress and cancel between a running trial and whoever started it. progress may be called
/// from the thread running the trial; cancel may be set from any thread.
struct TrialMonitor
{
    std::function<void(int done, int total)> progress;
    const std::atomic_bool *cancel = nullptr;

    bool cancelled() const { return cancel && cancel->load(std::memory_order_relaxed); }
};

} // namespace learnid
