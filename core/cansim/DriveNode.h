#pragma once

#include "can/Cia402Drive.h"
#include "can/EmcyConsumer.h"
#include "can/HeartbeatProducer.h"
#include "can/Nmt.h"
#include "can/ObjectDictionary.h"
#include "can/SdoServer.h"
#include "cansim/DriveSettings.h"
#include "cansim/StoredParameterSet.h"
#include "control/PidController.h"

#include <Eigen/Core>
#include <QCanBusFrame>
#include <QList>
#include <QObject>
#include <optional>

namespace learnid {

class CanLink;

/// What a drive does from one SYNC to the next: the torque it applies and whether its brake is
/// released (powered) or holds the joint.
struct DriveSyncOutput
{
    double torque = 0.0; ///< [N m], saturated at the torque limit 0x2300
    bool powered = false;
};

/// One simulated CiA 402 drive on the bus, a CANopen slave (docs/can-protocol.md): its object
/// dictionary served over SDO, the slave NMT state machine with boot-up and heartbeat, the
/// device control state machine, RPDO1 (set-point, controlword) and TPDO1 (position, torque,
/// statusword), and the joint's position loop in cyclic synchronous position mode: at each SYNC
/// tau = sat(torque offset + PID(target - q)). The robot (CanArmSimulator) calls sync() and then
/// sendAfterSync() once per SYNC; the drive never integrates the arm itself.
class DriveNode : public QObject
{
    Q_OBJECT

public:
    DriveNode(CanLink *link, const DriveNodeSettings &settings, QObject *parent = nullptr);

    quint8 node() const { return m_settings.node; }
    ObjectDictionary &dictionary() { return m_dictionary; }
    const ObjectDictionary &dictionary() const { return m_dictionary; }
    SdoServer &sdoServer() { return m_sdo; }
    NmtState nmtState() const { return m_nmt; }
    cia402::State driveState() const { return m_drive.state(); }
    quint16 statusword() const;

    /// Sends the boot-up message; the node is pre-operational afterwards.
    void bootUp();

    /// SYNC, first half: applies the newest RPDO received since the previous SYNC, runs the
    /// device control and the position loop on the measured angle q [rad] (on the encoder grid).
    DriveSyncOutput sync(double q);
    /// SYNC, second half (after the robot sent the SYNC frame): this SYNC's emergencies, then
    /// TPDO1 with the measured torque [N m] (tau plus noise) unless dropTpdo.
    void sendAfterSync(double measuredTorque, bool dropTpdo = false);

    /// Radians of one encoder increment (2 pi / 0x608F:1).
    double countAngle() const;
    /// N m of one per mille of rated torque (0x6076 / 1e6).
    double torqueUnit() const;
    /// 0x2300 [N m].
    double torqueLimit() const;

    /// The identified parameters of the stored set (0x2200:1..count at the last "save"); empty
    /// before any.
    Eigen::VectorXd storedParameters() const;
    /// The whole stored set (its payload among it).
    const StoredParameterSet &storedSet() const { return m_stored; }

    /// Fault injection: the node sends nothing and ignores SDO requests.
    void setSilent(bool silent);
    /// Fault injection: at the k-th SYNC in Operation enabled since the drive was enabled, the
    /// drive faults with EMCY code (k >= 1; 0 disables).
    void setFaultAtEnabledSync(int k, quint16 code);

signals:
    /// 0x1010:1 "save" stored the set.
    void parametersStored(quint8 node);
    /// An emergency was sent (or would have been, when silent).
    void emergencySent(const learnid::EmcyMessage &message);

private:
    void handleFrame(const QCanBusFrame &frame);
    void handleNmt(NmtCommand command);
    void setNmtState(NmtState state);
    void receiveRpdo(const QByteArray &payload);
    void onWritten(quint16 index, quint8 subIndex);
    void applyControlword(quint16 controlword);
    void enterOperation(double q);
    void fault(quint16 code, quint8 errorBits);
    void queueEmcy(quint16 code);
    void flushEmcy();
    void store();
    void updateRatedTorque();
    double pidStep(double e);

    CanLink *m_link;
    DriveNodeSettings m_settings;
    ObjectDictionary m_dictionary;
    SdoServer m_sdo;
    HeartbeatProducer m_heartbeat;
    Cia402Drive m_drive;
    NmtState m_nmt = NmtState::PreOperational;
    bool m_silent = false;

    struct SetPoint
    {
        double target = 0.0; ///< [rad]
        double offset = 0.0; ///< [N m]
        quint16 controlword = 0;
    };
    SetPoint m_received; ///< newest RPDO since the previous SYNC
    bool m_fresh = false;
    SetPoint m_command; ///< what the position loop follows
    bool m_followed = false;
    cia402::State m_stateAtLastSync = cia402::State::SwitchOnDisabled;
    int m_missed = 0;
    int m_enabledSyncs = 0;
    int m_quickStopSyncs = 0;
    double m_holdTarget = 0.0;
    double m_q = 0.0;
    int m_faultAtEnabledSync = 0;
    quint16 m_injectedCode = 0;
    QList<EmcyMessage> m_pendingEmcy;

    std::optional<PidController> m_pid;
    Eigen::VectorXd m_e = Eigen::VectorXd::Zero(1);
    Eigen::VectorXd m_u = Eigen::VectorXd::Zero(1);
    StoredParameterSet m_stored;
};

} // namespace learnid
