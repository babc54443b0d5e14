#pragma once

#include "canrobot/CanRobotOptions.h"
#include "canrobot/TrialStreamer.h"
#include "model/RobotModel.h"
#include "robot/Robot.h"

#include <QThread>
#include <memory>

namespace learnid {

class CanRobotWorker;

/// A robot of CiA 402 drives on a CAN bus, one CANopen node per joint (docs/can-protocol.md).
/// The session cannot tell it from SimulatedRobot. The device and every protocol unit live in
/// a thread of their own; the blocking calls of Robot are marshalled there and wait.
class CanRobot final : public Robot
{
public:
    /// model: the robot's model (for the gravity torque of the return move and its size).
    /// factory: creates the device in the CAN thread; default: QCanBus by plugin and interface.
    CanRobot(std::shared_ptr<const RobotModel> model, CanRobotOptions options,
             CanDeviceFactory factory = {});
    ~CanRobot() override;

    /// Connects now (it otherwise happens at the first trial or apply); returns the error
    /// (timeout, refused device, bus load above the limit) or empty.
    QString connectBus();

    QString description() const override;
    TrialRecord runTrial(const TrialPlan &plan, const TrialMonitor &monitor) override;
    QString applyParameters(const Eigen::VectorXd &phi) override;
    /// 0x2500 on every node, read back, then stored (docs/can-protocol.md §2.5).
    QString applyPayload(int joint, const Eigen::VectorXd &body) override;
    Eigen::VectorXd storedParameters() const override { return m_stored; }
    QList<DriveIdentity> driveIdentities() const override;

    const CanRobotOptions &options() const { return m_options; }
    /// Figures of the last trial streamed (late set-points, SYNC to RPDO latency).
    TrialStreamStatistics lastTrialStatistics() const;

private:
    template <typename F> void runInCanThread(F &&f) const;

    CanRobotOptions m_options;
    QThread m_thread;
    CanRobotWorker *m_worker = nullptr;
    Eigen::VectorXd m_stored;
};

} // namespace learnid
