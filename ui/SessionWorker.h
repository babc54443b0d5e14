#pragma once

#include "robot/SimulatedRobot.h"
#include "session/CommissioningSession.h"
#include "ui/RobotChoice.h"
#include "ui/SessionInfo.h"
#include "ui/TrackingErrorData.h"

#include <QMutex>
#include <QObject>
#include <QStringList>
#include <memory>

namespace learnid {

/// Owns the robot and the commissioning session in a worker thread. Its slots are called by
/// queued invocation from SessionController; everything it reports goes out as value types in
/// signals. All slots but requestCancel() must run in the worker's thread.
class SessionWorker : public QObject
{
    Q_OBJECT

public:
    explicit SessionWorker(QObject *parent = nullptr);
    ~SessionWorker() override;

    /// Stops a running trial (and series) at its next sample. Thread-safe.
    void requestCancel();

public slots:
    /// Builds the chosen robot (a CAN robot is connected here, which may take its connect
    /// timeout) and a new session of the scenario (history discarded).
    void open(const learnid::Scenario &scenario);
    /// The robot the next open() builds.
    void setRobotChoice(const learnid::RobotChoice &choice) { m_choice = choice; }
    void close();
    /// Faults the simulated robot injects from now on.
    void setFaults(const learnid::SimulatedFaults &faults);
    void check();
    void runTrial();
    void runTrials(int count);
    void accept(int estimateIndex);
    void apply();
    void revert();
    /// Writes the parameter file (JSON) of estimate k and its DCF fragment next to it
    /// (same base name, .dcf), all or nothing.
    void exportParameterFile(const QString &jsonPath, int estimateIndex);
    /// Writes folder/trial-NNN.csv for every trial that moved, all or nothing.
    void exportTrialCsv(const QString &folder);

signals:
    void opened(const learnid::SessionInfo &info);
    void openFailed(const QString &message);
    void closed();
    void checked(const learnid::PreTrialCheck &check);
    void trialStarted(int index, int samples);
    void progress(int index, int samplesDone, int samplesTotal);
    /// summary: the trial without its samples (trialSummary); curves: its tracking errors as the
    /// plot draws them (none for a refused trial).
    void trialFinished(const learnid::TrialResult &summary,
                       const QList<learnid::TrackingErrorCurve> &curves,
                       const QVector<Eigen::VectorXd> &estimates);
    /// A runTrial()/runTrials() call returned; allCompleted is false when one did not.
    void runFinished(bool allCompleted);
    void accepted(int estimateIndex);
    void applied(const Eigen::VectorXd &stored);
    /// operation: "accept", "apply", "revert", "run"; message says what failed and where.
    void operationFailed(const QString &operation, const QString &message);
    void parameterFileExported(const QStringList &paths, const QString &error);
    void trialCsvExported(const QString &folder, int files, const QString &error);

private:
    void connectSession();
    void emitCheck();

    QMutex m_sessionMutex; // guards m_session's lifetime against requestCancel() from the GUI
    RobotChoice m_choice;
    std::shared_ptr<SimulatedRobot> m_robot; ///< the simulated robot (null for a CAN robot)
    std::unique_ptr<CommissioningSession> m_session;
    SimulatedFaults m_faults;
    int m_lastProgressPercent = -1;
};

} // namespace learnid
