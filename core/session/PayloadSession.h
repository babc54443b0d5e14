#pragma once

#include "identify/LogSignals.h"
#include "identify/PayloadFit.h"
#include "model/ChainModel.h"
#include "model/Payload.h"
#include "model/PayloadPrior.h"
#include "robot/Robot.h"
#include "session/PayloadPathChange.h"
#include "session/TrialPlanner.h"
#include "session/TrialResult.h"
#include "types/Scenario.h"

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

namespace learnid {

/// One trial of a payload session: what ran with which payload estimate, and what was learned.
struct PayloadTrial
{
    int index = 0;
    /// A baseline trial (payload.baselineTrials): the same timed path without the payload, the
    /// arm's feedforward alone; its log is taken out of every payload trial, nothing is fitted.
    bool baseline = false;
    bool baselineKept = false; ///< a baseline trial that completed and whose log is kept
    /// Stopped at the tracking limit, and learned from the record before the stop.
    bool partial = false;
    /// The second payload trial in a row stopped at the limit: learned from, but the series ends
    /// (the gains do not hold the payload; learning from the records did not bring the error
    /// under the limit).
    bool seriesStop = false;
    InertialParameters payloadUsed = InertialParameters::Zero(); ///< the feedforward's payload
    PreTrialCheck check; ///< plan (arm + payloadUsed) and verdict before the motion
    TrialRecord record;
    Eigen::VectorXd maxTrackingErrorDeg; ///< per joint [deg] (n)
    Eigen::VectorXd rmsTrackingErrorDeg; ///< per joint [deg] (n)
    /// The payload fitted to every completed trial so far, this one included; none when this
    /// trial was not learned from.
    std::optional<PayloadFit> fit;
    /// What the planned paths of those trials observe: the fit learns only these directions.
    PayloadObservability planned;
    double updateCpuSeconds = 0.0; ///< CPU time of that fit [s]
    QString message;               ///< why it was refused, ended early or not learned from

    bool learned() const { return fit.has_value(); }
    /// The session may go on: a learned trial that does not end the series, or a baseline trial
    /// that was kept.
    bool usable() const { return (learned() && !seriesStop) || baselineKept; }
    const TrialPlan &plan() const { return check.plan; }
};

/// The learning loop with a payload mounted (docs/payload.md, "The learning loop"): the arm's
/// model is held fixed at the scenario's initial parameters (an identified arm); each trial's
/// feedforward is that arm plus the current payload estimate; after each completed trial the
/// payload is fitted to all completed trials so far as logs are (filterLog, fitPayload: both
/// sides filtered alike, the nearest real body inside the bound), restricted to the directions
/// their planned paths observe (payloadPathObservability): the others keep the prior and are
/// reported as not identified, even where a tracking error let the measured motion see them. Trials
/// that did not complete are kept but not learned from. With payload.baselineTrials, the first
/// trials run the path without the payload and every trial keeps their timing (docs/payload.md,
/// "A wrong arm model and the baseline trial"). A payload trial stopped at the tracking limit is
/// learned from up to the stop (its record and its planned path cut there), as the arm's session
/// learns from one (docs/method.md §2.4); a stop too early to filter teaches nothing. Calls are
/// synchronous and belong to one thread; requestCancel() may come from any thread.
class PayloadSession
{
public:
    /// scenario: withRobotDefaults() applied, its payload section enabled. bareRobot: the robot
    /// without its payload, for the baseline trials (the simulated robot); none: they run on
    /// `robot`, whose payload the caller has the technician mount only after them
    /// (nextTrialIsBaseline()). Throws Error when the model is not a URDF robot's, the scenario
    /// does not fit it, the prior is refused or the link is unknown (naming the payload key).
    PayloadSession(const Scenario &scenario, std::shared_ptr<const RobotModel> model,
                   std::shared_ptr<Robot> robot, std::shared_ptr<Robot> bareRobot = {});

    const Scenario &scenario() const { return m_scenario; }
    const PayloadModel &payloadModel() const { return *m_payload; }
    const PayloadPrior &prior() const { return m_prior; }
    Robot &robot() { return *m_robot; }
    const Robot &robot() const { return *m_robot; }
    const std::vector<PayloadTrial> &history() const { return m_history; }
    /// The payload the next trial's feedforward uses: the prior, then the latest fit's.
    const InertialParameters &currentPayload() const { return m_current; }
    /// The base parameters of the arm carrying `payload` (what the feedforward is built with).
    Eigen::VectorXd feedforwardParameters(const InertialParameters &payload) const;
    /// The next trial planned with the arm and the current payload (a baseline: the arm alone
    /// on the baseline's timing), and checked.
    PreTrialCheck checkNextTrial() const;
    /// The next trial is a baseline trial: the robot must not carry the payload.
    bool nextTrialIsBaseline() const;
    /// What the next trial's path lets the fit see of the payload (PayloadObservability.h);
    /// rank 0 when it cannot be planned.
    PayloadObservability observability() const;
    /// The smallest change of the path's waypoints that lets the next trial see what
    /// `observability()` says it misses (PayloadPathChange.h); not valid when none is needed or
    /// found.
    PayloadPathChange pathChange() const;

    /// Checks, runs and learns from one trial; see the class comment.
    const PayloadTrial &runTrial();
    /// Runs the baseline trials still due, then `count` payload trials; stops early (false) when
    /// one is not usable (PayloadTrial::usable: also the second stop at the limit in a row) or
    /// on Stop.
    bool runTrials(int count);
    void requestCancel() { m_cancel.store(true); }

private:
    /// How the next trial is timed: the parameters of the torque rule, and whether it is gentle.
    struct NextTiming
    {
        Eigen::VectorXd phi;
        bool gentle = false;
    };
    NextTiming nextTiming() const;

    Scenario m_scenario;
    std::shared_ptr<const ChainModel> m_model;
    std::shared_ptr<Robot> m_robot;
    std::shared_ptr<Robot> m_bareRobot;
    std::unique_ptr<PayloadModel> m_payload;
    PayloadPrior m_prior;
    TrialPlanner m_planner;
    LogFilterSettings m_filter;
    std::vector<FilteredLog> m_baselines; ///< the completed baseline trials, filtered
    std::vector<FilteredLog> m_logs;      ///< the completed payload trials, filtered, less them
    std::vector<JointTrajectory> m_paths; ///< their planned paths
    std::vector<PayloadTrial> m_history;
    InertialParameters m_current = InertialParameters::Zero();
    std::atomic_bool m_cancel{false};
};

} // namespace learnid
