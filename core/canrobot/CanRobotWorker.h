#pragma once

#include "canrobot/CanRobotOptions.h"
#include "canrobot/SdoSequence.h"
#include "canrobot/TrialStreamer.h"
#include "model/RobotModel.h"
#include "types/Trial.h"

#include <QObject>
#include <functional>
#include <memory>

namespace learnid {

class CanConnection;
struct ConnectionUnits;
struct NodeConfigurationResult;

/// The CAN robot's work in its own thread: the connection, the CANopen units on it, the
/// trial (configure, stream, log) and apply. Everything asynchronous; the results go to the
/// callbacks, called in this object's thread. CanRobot marshals its blocking calls here.
class CanRobotWorker : public QObject
{
    Q_OBJECT

public:
    CanRobotWorker(std::shared_ptr<const RobotModel> model, CanRobotOptions options,
                   CanDeviceFactory factory, QObject *parent = nullptr);
    ~CanRobotWorker() override;

    void connectBus(std::function<void(const QString &error)> done);
    void runTrial(const TrialPlan &plan, const TrialMonitor &monitor,
                  std::function<void(const TrialRecord &)> done);
    /// done(error): empty when every node stored phi.
    void apply(const Eigen::VectorXd &phi, std::function<void(const QString &)> done);
    /// done(error): empty when every node stored the payload (payloadApplySteps()).
    void applyPayload(int joint, const Eigen::VectorXd &body,
                      std::function<void(const QString &)> done);
    void shutdown();

    const TrialStreamStatistics &lastStatistics() const { return m_stats; }
    /// The drives' 0x1018 per joint, as read before the last trial or apply (empty before).
    const QList<DriveIdentity> &driveIdentities() const { return m_drives; }
    int trialsRun() const { return m_trials; }

private:
    void ensureUnits();
    void onLost(const QString &reason);
    void configure(const TrialPlan &plan, const TrialMonitor &monitor);
    /// Reads every node's identity and calls next(error, unread): error empty when each node is
    /// the drive of its joint (JointIdentityCheck.h); unread when a read failed.
    void checkIdentity(std::function<void(const QString &error, bool unread)> next);
    quint32 robotIdentity() const;
    /// Connects, checks the drives' identity, then runs the steps of an apply (writes,
    /// read-backs, stores); `written` names the objects for "nothing was stored (... not
    /// written)".
    void runApply(const QList<SdoStep> &steps, const QString &written,
                  std::function<void(const QString &)> done);
    void endTrial(TrialRecord record);
    QString connectionName() const;

    std::shared_ptr<const RobotModel> m_model;
    CanRobotOptions m_options;
    CanConnection *m_connection = nullptr;
    /// The protocol units of the current connection, built and destroyed as a whole: they hold
    /// the connection's link, so none may outlive it (null while there is no connection).
    std::unique_ptr<ConnectionUnits> m_units;

    std::function<void(const TrialRecord &)> m_trialDone;
    std::shared_ptr<NodeConfigurationResult> m_configuration;
    double m_samplePeriod = 0;
    TrialStreamStatistics m_stats;
    int m_trials = 0;
    QList<DriveIdentity> m_drives;
};

} // namespace learnid
