#pragma once

#include "robot/SimulatedRobot.h"
#include "service/RobotRequest.h"
#include "service/SessionExport.h"
#include "service/SessionInfo.h"
#include "service/SessionState.h"
#include "service/TrackingErrorData.h"
#include "session/CommissioningSession.h"
#include "session/ConvergenceFigures.h"

#include <QMutex>
#include <QObject>
#include <QStringList>
#include <memory>

namespace learnid {

/// Owns the robot and the commissioning session. In the window it lives in a worker thread and
/// SessionController calls its slots by queued invocation; learnid-cli calls them directly, in
/// its own thread. Everything it reports goes out as value types in signals. All slots but
/// requestCancel() must run in the worker's thread.
class SessionWorker : public QObject
{
    Q_OBJECT

public:
    explicit SessionWorker(QObject *parent = nullptr);
    ~SessionWorker() override;

    /// Stops a running trial (and series) at its next sample. Thread-safe.
    void requestCancel();
    /// Forgets an earlier Stop; called when a run is requested, so that a Stop that arrives
    /// after the request, even before the worker starts the run, stops it. Thread-safe.
    void clearCancel();
    /// The session, for a caller in the worker's own thread (learnid-cli); null before open().
    CommissioningSession *session() { return m_session.get(); }

public slots:
    /// Builds the requested robot (makeRobot: a CAN robot is connected here, which may take its
    /// connect timeout) and a new session of the scenario (history discarded).
    void open(const learnid::Scenario &scenario);
    /// The robot the next open() builds.
    void setRobotRequest(const learnid::RobotRequest &request) { m_request = request; }
    void close();
    /// Faults the simulated robot injects from now on.
    void setFaults(const learnid::SimulatedFaults &faults);
    void check();
    void runTrial();
    /// Runs `count` trials; the next trial's check follows runFinished() unless checkAfter is
    /// false and all of them learned (the controller runs a series one trial at a time).
    void runTrials(int count, bool checkAfter = true);
    void accept(int estimateIndex, bool nearestConsistent = false);
    void apply() { writeParameters(SessionOperation::Apply); }
    void revert() { writeParameters(SessionOperation::Revert); }
    /// Apply or revert, always answered by applied() or operationFailed().
    void writeParameters(learnid::SessionOperation operation);
    /// Writes the parameter file (JSON) of estimate k and its DCF fragment next to it
    /// (same base name, .dcf), all or nothing.
    void exportParameterFile(const QString &jsonPath, int estimateIndex);
    /// Writes folder/trial-NNN.csv for every trial that moved, all or nothing.
    void exportTrialCsv(const QString &folder);
    /// Writes every output of the request, all or none (writeExport); exported() says which.
    void exportOutputs(const learnid::ExportRequest &request);

signals:
    void opened(const learnid::SessionInfo &info);
    /// unreachable: the robot could not be connected (else the input could not be used).
    void openFailed(const QString &message, bool unreachable);
    void closed();
    void checked(const learnid::PreTrialCheck &check);
    void trialStarted(int index, int samples);
    void progress(int index, int samplesDone, int samplesTotal);
    /// summary: the trial without its samples (trialSummary); curves: its tracking errors as the
    /// plot draws them (none for a refused trial); figures: every estimate's path-torque
    /// figures on the newest planned path.
    void trialFinished(const learnid::TrialResult &summary,
                       const QList<learnid::TrackingErrorCurve> &curves,
                       const QVector<Eigen::VectorXd> &estimates,
                       const learnid::EstimateFigures &figures);
    /// A runTrial()/runTrials() call returned; allCompleted is false when one did not.
    void runFinished(bool allCompleted);
    void accepted(int estimateIndex);
    /// After apply or revert: what the robot holds now, and which estimate that is (-1: none
    /// of the session's, e.g. the set the robot held before the first apply).
    void applied(const Eigen::VectorXd &stored, int estimateIndex);
    /// message says what failed and where.
    void operationFailed(learnid::SessionOperation operation, const QString &message);
    void parameterFileExported(const QStringList &paths, const QString &error);
    void trialCsvExported(const QString &folder, int files, const QString &error);
    /// exportOutputs() wrote these files (all of them), or nothing and error says why.
    void exported(const QStringList &paths, const QString &error);

private:
    void connectSession();
    void emitCheck();
    EstimateFigures newestEstimateFigures() const;
    /// Writes the request's files (writeExport); the error, or empty with *written set.
    QString writeOutputs(const ExportRequest &request, QStringList *written);

    QMutex m_sessionMutex; // guards m_session's lifetime against requestCancel() from the GUI
    RobotRequest m_request;
    SimulatedFaults m_faults;                ///< injected into the simulated robot of every open()
    std::shared_ptr<SimulatedRobot> m_robot; ///< the simulated robot (null for a CAN robot)
    std::unique_ptr<CommissioningSession> m_session;
    int m_lastProgressPercent = -1;
};

} // namespace learnid

Q_DECLARE_METATYPE(learnid::ExportRequest)
