#pragma once

#include "cansim/DriveNode.h"
#include "cansim/SyncProducer.h"
#include "robot/ArmSimulation.h"
#include "types/ControllerSettings.h"

#include <Eigen/Core>
#include <QList>
#include <QObject>
#include <QPair>
#include <memory>
#include <optional>
#include <random>

namespace learnid {

class CanLink;

/// The arm behind the bus and its drives' defaults.
struct CanArmSettings
{
    std::shared_ptr<const RobotModel> model;
    Eigen::VectorXd trueParameters; ///< phi of the simulated arm (m)
    /// phi of the same arm without the payload it carries (a scenario's payload section), for
    /// setPayloadMounted(); empty: it carries none.
    Eigen::VectorXd bareParameters;
    MeasurementOptions measurement; ///< encoderCounts 0 means 2^24 increments on the bus
    ControllerSettings controller;  ///< default gains; samplePeriod is the SYNC period
    Eigen::VectorXd torqueLimits;   ///< default 0x2300 [N m] (n)
    Eigen::VectorXd initialPose;    ///< the arm at rest at start [rad] (n)
    QList<int> nodes = {1, 2};      ///< node id of joint 1, 2, ...
    /// Consecutive SYNCs in Operation enabled without a fresh set-point before a drive faults
    /// (EMCY 0x8100). Real drives allow 1-3; a loaded test machine may need more.
    int setPointTimeoutSyncs = cansim::missedSetPointLimit;
    /// 0x2400:01 of every drive at power on: 0, never commissioned; else joint j's drive holds
    /// (robotIdentity, j) as a robot commissioned by its maker (docs/can-protocol.md §2.4).
    quint32 robotIdentity = 0;
};

/// Faults the simulator injects on request (learnid-robot-sim's options).
struct CanSimFaults
{
    double dropFraction = 0.0;     ///< fraction of TPDOs lost, drawn from the scenario seed
    qint64 silentAfterFrames = -1; ///< after this many sent frames nothing more is sent
    int emcyAtSample = -1; ///< the first node faults (0x8611) at this SYNC in Operation enabled
    std::optional<QPair<quint16, quint8>> refusedWrite; ///< SDO writes here abort 0x08000020
};

/// The robot on the bus (learnid-robot-sim without the process around it): one DriveNode per
/// joint on a shared CanLink, one ArmSimulation they move, and the SYNC cycle of
/// docs/can-protocol.md. start() sends the boot-ups and runs syncCycle() every SYNC period;
/// tests call bootUp() and syncCycle() themselves to step the simulated time.
class CanArmSimulator : public QObject
{
    Q_OBJECT

public:
    /// Throws learnid::Error for settings that do not fit (node count, ids, vector sizes).
    CanArmSimulator(CanLink *link, const CanArmSettings &settings, const CanSimFaults &faults = {},
                    QObject *parent = nullptr);

    int dof() const { return int(m_nodes.size()); }
    /// Joint j's drive (0-based).
    DriveNode *node(int joint) const { return m_nodes.at(joint); }
    const ArmSimulation<> &arm() const { return *m_arm; }
    /// The SYNC period [us] (0x1006).
    quint32 syncPeriodUs() const { return m_syncPeriodUs; }

    /// Boot-up message of every node.
    void bootUp();
    /// bootUp(), then syncCycle() every SYNC period of real time.
    void start();
    void stop();

    /// One SYNC: drives decide (measure, set-point, torque), SYNC frame, emergencies and TPDOs,
    /// then the arm moves one period with the torques held.
    void syncCycle();
    /// SYNCs sent so far and the counter of the last one.
    qint64 syncCount() const { return m_syncCount; }
    quint8 syncCounter() const { return m_sync.counter(); }

    /// Mounts the payload (trueParameters) or takes it off (bareParameters), with the arm at
    /// rest between trials; false when the arm carries no payload.
    bool setPayloadMounted(bool mounted);
    bool hasPayload() const { return m_bare.size() > 0; }

    qint64 framesSent() const { return m_framesSent; }
    bool isSilent() const { return m_silent; }

signals:
    /// A node stored its parameters (0x1010:1 "save").
    void parametersStored(quint8 node);
    /// The silentAfterFrames fault took effect.
    void silenced();

private:
    void countSentFrame();
    void silence();

    CanLink *m_link;
    CanSimFaults m_faults;
    quint32 m_syncPeriodUs = 2000;
    std::unique_ptr<ArmSimulation<>> m_arm;
    QList<DriveNode *> m_nodes;
    SyncProducer m_sync;
    std::mt19937_64 m_dropRng;
    std::uniform_real_distribution<double> m_uniform{0.0, 1.0};
    Eigen::VectorXd m_qMeasured, m_tau, m_tauMeasured, m_limits;
    Eigen::VectorXd m_withPayload, m_bare; ///< the arm with and without its payload
    qint64 m_syncCount = 0;
    qint64 m_framesSent = 0;
    bool m_silent = false;
};

} // namespace learnid
