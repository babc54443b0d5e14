#pragma once

#include "service/PayloadRun.h"

#include <QMutex>
#include <QObject>
#include <QThread>
#include <QWaitCondition>
#include <atomic>
#include <memory>

namespace learnid {

/// Runs the window's payload step (PayloadRun.h) in a thread of its own, so that the window stays
/// responsive. check() plans the scenario's first trial and reports what its path lets the trials
/// see (checked() or checkFailed()); start() runs the baseline trials and then the payload trials
/// on a new simulated robot, or on the CAN robot of its request (connected for the run),
/// reporting trialStarted() and trialFinished() per trial, then one of succeeded(), failed() or
/// cancelled(). applyResult() writes the last successful run's payload to its robot (applied()).
/// Everything comes back queued, in the thread the job lives in. One run or apply at a time.
/// On the CAN robot a run with baseline trials waits before the first of them for the payload to
/// be taken off, and before the first payload trial for it to be mounted: mountingRequested(),
/// then confirmMounting() (or cancel()) lets it go on.
/// cancel() stops the running trial at its next sample (PayloadSession::requestCancel()); a
/// cancelled or failed run has no result, so nothing of it can be accepted, applied or exported,
/// but when it ran a trial its record comes first (endedEarlyRecord(): the report, marked as
/// ended early and why, and the trial CSVs); a check superseded by a newer one is dropped. The
/// robot of the last successful run stays connected until the next run or the job's end, for its
/// apply.
class PayloadRunJob : public QObject
{
    Q_OBJECT

public:
    explicit PayloadRunJob(QObject *parent = nullptr);
    /// Cancels a run and waits for it to end (at its next sample).
    ~PayloadRunJob() override;

    bool isRunning() const { return m_running; }

public slots:
    /// Plans the scenario's first trial in the job's thread; ignored (false) while a run runs.
    bool check(const learnid::Scenario &scenario);
    /// Starts a run of the scenario on the requested robot (the simulated one, or a CAN robot:
    /// makeCanPayloadSession()); ignored (false) while one runs.
    bool start(const learnid::Scenario &scenario,
               const learnid::RobotRequest &robot = learnid::RobotRequest());
    /// Writes the last successful run's payload to its robot and stores it (applyRunPayload());
    /// ignored (false) while a run runs or without a result.
    bool applyResult();
    /// Asks the running trial to stop at its next sample; cancelled() follows.
    void cancel();
    /// The technician has done what mountingRequested() asked: the run goes on.
    void confirmMounting();

signals:
    void checked(const learnid::PayloadPreview &preview);
    /// message: the core's, naming the scenario key.
    void checkFailed(const QString &message);
    /// index counts from 0 over all trials (the baseline trials first), of `total`.
    void trialStarted(int index, int total, bool baseline);
    void trialFinished(const learnid::PayloadTrialRow &row);
    /// The run waits for the technician (CAN robot): to take the payload off `link` for the
    /// `baselineTrials` baseline trials (mount false), or to mount it after them (mount true).
    void mountingRequested(bool mount, const QString &link, int baselineTrials);
    void succeeded(std::shared_ptr<const learnid::PayloadRunResult> result);
    /// The record of a run that ended before its last trial (failed or cancelled, which follow),
    /// when it ran at least one trial: record.endedEarly says why.
    void endedEarlyRecord(std::shared_ptr<const learnid::PayloadRunRecord> record);
    /// A trial was refused or not usable, or the session could not be made: message says why.
    void failed(const QString &message);
    void cancelled();
    /// error: empty when the robot stored the payload, else what failed and where.
    void applied(const QString &error);

private:
    void runInThread(const Scenario &scenario, const RobotRequest &robot, int run,
                     std::shared_ptr<std::atomic<bool>> cancel);
    void checkInThread(const Scenario &scenario, int check);
    /// In m_thread: waits for confirmMounting(); false when the run was cancelled.
    bool waitForMounting(const std::atomic<bool> &cancel);

    QThread m_thread;
    QObject *m_context; ///< lives in m_thread: the queued calls run there
    QMutex m_sessionMutex;
    PayloadSession *m_session = nullptr; ///< the running run's, for cancel(); under the mutex
    std::shared_ptr<std::atomic<bool>> m_cancel;
    int m_run = 0;
    std::atomic<int> m_check{0}; ///< the newest check; older ones are dropped
    QMutex m_mountMutex;
    QWaitCondition m_mountWake;
    bool m_mountConfirmed = false; ///< under m_mountMutex
    bool m_running = false;
    /// The last successful run's session and robot (used in m_thread only) and its result.
    std::shared_ptr<PayloadRunSession> m_last;
    std::shared_ptr<const PayloadRunResult> m_lastResult;
};

} // namespace learnid
