#pragma once

#include "identify/LearningLaw.h"
#include "model/RobotModel.h"
#include "robot/Robot.h"
#include "session/EstimateConsistency.h"
#include "session/PathIdentifiability.h"
#include "session/TrialPlanner.h"
#include "session/TrialResult.h"
#include "types/Scenario.h"

#include <QObject>
#include <QVector>
#include <atomic>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace learnid {

/// A commissioning session: runs trials of one scenario on one robot, learns after each, keeps
/// the whole history, and applies an accepted estimate to the robot. It does not know whether
/// the robot is simulated or on a bus.
///
/// Calls are synchronous and belong to one thread (a worker thread in the GUI, the main thread
/// in the CLI); requestCancel() may be called from any thread. Signals carry value types.
/// Samples a trial stopped by the tracking limit must keep after the filter's settling to be
/// learned from (below that, nothing is learned and the trial is no progress).
constexpr int minimumPartialSamples = 16;

class CommissioningSession : public QObject
{
    Q_OBJECT

public:
    /// Throws Error when the scenario does not fit the model (sizes, unknown law).
    CommissioningSession(const Scenario &scenario, std::shared_ptr<const RobotModel> model,
                         std::shared_ptr<Robot> robot, QObject *parent = nullptr);
    ~CommissioningSession() override;

    const Scenario &scenario() const { return m_scenario; }
    const RobotModel &model() const { return *m_model; }
    Robot &robot() { return *m_robot; }
    const Robot &robot() const { return *m_robot; }
    const LearningLaw &law() const { return *m_law; }

    /// Trials run so far, in order (refused and failed ones included).
    const QVector<TrialResult> &history() const { return m_history; }
    /// estimates()[0] is phi_0; estimates()[k] the estimate after k learning steps.
    const QVector<Eigen::VectorXd> &estimates() const { return m_estimates; }
    const Eigen::VectorXd &currentEstimate() const { return m_estimates.constLast(); }
    /// The latest trial run with estimate k (its feedforward), or nullptr if none ran with it.
    const TrialResult *trialRunWith(int estimateIndex) const;

    /// Plans the next trial with the current estimate and checks it, without moving the robot.
    PreTrialCheck checkNextTrial() const;
    /// What the next trial's path lets the learning see (PathIdentifiability.h), at the current
    /// estimate and the scenario's rank tolerance; empty (0 parameters) when it cannot be
    /// planned.
    PathIdentifiability identifiability() const;

    /// Checks, runs and learns from one trial. A refused, faulted, cancelled trial, or one
    /// aborted for another reason than the tracking limit, is kept in the history, marked, and
    /// leaves the estimate unchanged. A trial stopped by the tracking limit is learned from as
    /// far as it ran, less the filter's settling (TrialResult::learnedFromPartial()), unless
    /// that leaves fewer than minimumPartialSamples samples or observes nothing.
    const TrialResult &runTrial();
    /// Runs trials until `count` more have been learned from, or one was not, or one stopped
    /// by the tracking limit ends the series (TrialResult::seriesStop, TrialSeries.h); returns
    /// whether the series ran to its end.
    /// A Stop requested before the series starts is forgotten, unless keepEarlierStop: a caller
    /// that clears it when the run is requested (clearCancel) passes true, so that a Stop sent
    /// between the request and the start is not lost.
    bool runTrials(int count, bool keepEarlierStop = false);
    /// Asks a running trial (and series) to stop at the next sample; thread-safe.
    void requestCancel();
    /// Forgets a Stop requested earlier; thread-safe.
    void clearCancel() { m_cancel.store(false); }

    /// Accepts estimate k (1 .. estimates().size()-1) for apply, or with nearestConsistent the
    /// nearest plausible estimate to it (consistency() with NearestEstimate::Always). Returns an
    /// error or empty.
    QString accept(int estimateIndex, bool nearestConsistent = false);
    /// What apply writes: the accepted estimate, or its nearest consistent one; empty when
    /// nothing is accepted.
    Eigen::VectorXd acceptedParameters() const;
    /// Whether estimate k describes real bodies, and (as `when` asks) its nearest plausible
    /// estimate, weighted by the torques on the path of the trial run with it (URDF robots; see
    /// EstimateConsistency.h). Not applicable for other models or a k that does not exist.
    EstimateConsistency consistency(int estimateIndex,
                                    NearestEstimate when = NearestEstimate::WhenInconsistent) const;
    std::optional<int> acceptedIndex() const { return m_accepted; }
    /// Writes the accepted estimate to the robot (all or nothing). Returns an error or empty.
    QString apply();
    /// Restores the set the robot held before the last apply. Returns an error or empty.
    QString revert();
    /// Parameter sets applied so far, oldest first.
    const QVector<Eigen::VectorXd> &appliedHistory() const { return m_applied; }
    /// The estimate the robot holds because of this session's applies: the accepted index of
    /// the last apply not reverted, or -1 (nothing applied, or everything reverted).
    int appliedEstimateIndex() const
    {
        return m_appliedIndices.isEmpty() ? -1 : m_appliedIndices.constLast();
    }

signals:
    void trialStarted(int index, int samples);
    void progress(int index, int samplesDone, int samplesTotal);
    void trialFinished(const learnid::TrialResult &result);
    void estimateAccepted(int estimateIndex);
    void parametersApplied(const Eigen::VectorXd &phi);

private:
    const TrialResult &runNextTrial();
    TrialRecord runRepetitions(const TrialPlan &plan, int index, QString *message);
    void learnFrom(TrialResult &result);
    void learnFromPartial(TrialResult &result);
    TrialData trialData(const TrialResult &t, std::shared_ptr<LawCache> *cache) const;

    Scenario m_scenario;
    std::shared_ptr<const RobotModel> m_model;
    std::shared_ptr<Robot> m_robot;
    std::unique_ptr<LearningLaw> m_law;
    TrialPlanner m_planner;
    QVector<TrialResult> m_history;
    QVector<Eigen::VectorXd> m_estimates;
    std::optional<int> m_accepted;
    Eigen::VectorXd m_acceptedParameters; ///< the accepted estimate or its nearest consistent one
    QVector<Eigen::VectorXd> m_applied;
    QVector<Eigen::VectorXd> m_storedBeforeApply;
    QVector<int> m_appliedIndices; ///< estimate index of each apply not reverted, oldest first
    /// The law's per-trial work (LawCache), by trial index: kept with the algorithm's caller,
    /// not in the trials the session hands out.
    std::vector<std::shared_ptr<LawCache>> m_lawCaches;
    /// The plans of trials learned from partially, cut at their stop (what their records ran
    /// against), by trial index.
    std::map<int, TrialPlan> m_partialPlans;
    std::atomic_bool m_cancel{false};
};

} // namespace learnid
