#pragma once

#include "robot/SimulatedRobot.h"
#include "service/RobotRequest.h"
#include "service/SessionInfo.h"
#include "service/SessionState.h"
#include "service/TrackingErrorData.h"
#include "session/ConvergenceFigures.h"
#include "session/TrialResult.h"

#include <QObject>
#include <QThread>
#include <QVector>
#include <optional>

namespace learnid {

class SessionWorker;

/// The GUI thread's front of the session. It starts a SessionWorker in its own QThread, forwards
/// requests to it by queued calls, and keeps value copies of what the views show (the history
/// without its samples, see trialSummary(); estimates; the last pre-trial check). The samples
/// stay with the session in the worker: exportTrialCsv() writes them there. stop() reaches the
/// running trial directly: cancelling is thread-safe. It holds the workflow's state
/// (SessionState); what may be done next is allowedActions(state(), facts()).
///
/// runTrials(n) hands the worker one trial at a time: the next starts once this thread has
/// handled what the previous one's signals set off (the views' update, then their layout and
/// paint, 20-60 ms for 7 joints), so that work falls between two trials, while the robot
/// stands, and the window stays responsive while the robot moves.
class SessionController : public QObject
{
    Q_OBJECT

public:
    explicit SessionController(QObject *parent = nullptr);
    ~SessionController() override;

    SessionState state() const { return m_state; }
    /// What decides the allowed actions besides the state (scenarioValid left true).
    SessionFacts facts() const;
    AllowedActions allowedActions() const { return learnid::allowedActions(m_state, facts()); }
    bool isOpen() const { return isConnected(m_state); }
    /// True while something runs: connecting, a trial or its stop, an apply or revert.
    bool isBusy() const
    {
        return isOpen() ? m_state != SessionState::Idle : m_state == SessionState::Connecting;
    }
    const std::optional<SessionInfo> &info() const { return m_info; }
    const QVector<TrialResult> &history() const { return m_history; }
    /// estimates()[0] is phi_0, [k] the estimate after k learning steps.
    const QVector<Eigen::VectorXd> &estimates() const { return m_estimates; }
    /// Every estimate's path-torque figures on the newest trial's planned path.
    const EstimateFigures &estimateFigures() const { return m_figures; }
    const std::optional<PreTrialCheck> &lastCheck() const { return m_check; }
    std::optional<int> acceptedIndex() const { return m_accepted; }
    /// What the robot controller holds now (empty before the first apply).
    const Eigen::VectorXd &storedParameters() const { return m_stored; }
    int appliedCount() const { return m_appliedCount; }
    /// The estimate the robot holds through this session's applies, or -1.
    int appliedEstimateIndex() const { return m_appliedIndex; }

    bool canRun() const { return allowedActions().run; }

public slots:
    void open(const learnid::Scenario &scenario);
    /// The robot the next open() connects (default: the simulated robot).
    void setRobotRequest(const learnid::RobotRequest &request);
    void close();
    void setSimulatedFaults(const learnid::SimulatedFaults &faults);
    void runTrial();
    void runTrials(int count);
    void stop();
    void accept(int estimateIndex);
    void apply();
    void revert();
    void exportParameterFile(const QString &jsonPath, int estimateIndex);
    /// The robot's URDF with estimate k as real bodies (ExportRequest::urdfPath).
    void exportIdentifiedUrdf(const QString &path, int estimateIndex, const QString &comment);
    /// folder/trial-NNN.csv of every trial that moved; the result comes by trialCsvExported().
    void exportTrialCsv(const QString &folder);

signals:
    void opened();
    void openFailed(const QString &message);
    void closed();
    void stateChanged();
    void checkChanged();
    void trialStarted(int index, int samples);
    void progress(int index, int samplesDone, int samplesTotal);
    /// summary: the trial without its samples; curves: its tracking errors for the plot.
    void trialFinished(const learnid::TrialResult &summary,
                       const QList<learnid::TrackingErrorCurve> &curves);
    void historyChanged();
    void runFinished(bool allCompleted);
    void acceptedChanged(int estimateIndex);
    void applied(const Eigen::VectorXd &stored);
    void operationFailed(learnid::SessionOperation operation, const QString &message);
    void parameterFileExported(const QStringList &paths, const QString &error);
    /// exportIdentifiedUrdf() wrote these files, or nothing and error says why.
    void urdfExported(const QStringList &paths, const QString &error);
    void trialCsvExported(const QString &folder, int files, const QString &error);

protected:
    bool event(QEvent *event) override;

private:
    void setState(SessionState state);
    /// The series' next trial to the worker; the last one checks the trial after it.
    void postTrial();
    /// Idle, runFinished(allCompleted); checkNext: the worker checks the next trial (it does so
    /// itself after a series' last trial or a failed one).
    void endSeries(bool allCompleted, bool checkNext);
    /// Apply or revert in the worker; Applying until it answers.
    void writeParameters(SessionOperation operation);
    template <typename F> void post(F &&call);

    QThread m_thread;
    SessionWorker *m_worker = nullptr;
    std::optional<SessionInfo> m_info;
    QVector<TrialResult> m_history;
    QVector<Eigen::VectorXd> m_estimates;
    EstimateFigures m_figures;
    std::optional<PreTrialCheck> m_check;
    std::optional<int> m_accepted;
    Eigen::VectorXd m_stored;
    int m_appliedCount = 0;
    int m_appliedIndex = -1;
    SessionState m_state = SessionState::NotConnected;
    int m_seriesLeft = 0; ///< trials of the series not finished yet
    int m_series = 0;     ///< counts the series, so a late "next trial" of an ended one is dropped
    bool m_waitingForWindow = false;
};

} // namespace learnid
