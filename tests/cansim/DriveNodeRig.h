#pragma once
// One simulated CiA 402 drive (DriveNode) on the memory bus, seen from a master: the rig of
// tst_drivenode and tst_drivenodestates. The SYNC cycle is driven by the test (sync() +
// sendAfterSync()), so no real time passes.
#include "CanSimTestBus.h"
#include "can/Cia402.h"
#include "cansim/DriveNode.h"

#include <cmath>

namespace learnid::test::drive {

inline constexpr quint8 node = 5;
inline constexpr double increments = 1 << 20;
inline constexpr double countAngle = 2.0 * M_PI / increments;

struct Drive
{
    test::CanSimTestBus net;
    DriveNode drive{&net.slaveLink, settings()};

    static DriveNodeSettings settings()
    {
        DriveNodeSettings s;
        s.node = node;
        s.joint = 2;
        s.torqueLimit = 8.0;
        s.increments = qint64(increments);
        return s;
    }
    /// One SYNC at the measured angle q [rad]; the TPDO carries the torque without noise.
    DriveSyncOutput sync(double q)
    {
        const DriveSyncOutput out = drive.sync(q);
        drive.sendAfterSync(out.torque);
        net.flush();
        return out;
    }
    /// NMT start and the enable walk through RPDO controlwords, target = q.
    void enable(double q)
    {
        net.nmt(NmtCommand::Start, node);
        for (const quint16 cw : {0x0006, 0x0007, 0x000F}) {
            net.rpdo(node, std::round(q / countAngle), 0, cw);
            sync(q);
        }
    }
    cia402::State tpdoState() const
    {
        return cia402::stateFromStatusword(quint16(net.lastTpdo(node).value(2)));
    }
};

// The first output of the Tustin-discretised PID from rest: its feedthrough, the continuous
// controller evaluated at s = 2/T (Tustin maps z = infinity there).
inline double pidFeedthrough(double kp, double ki, double kd, double lambda, double ts)
{
    const double s = 2.0 / ts;
    return kp + ki / s + kd * lambda * lambda * s / ((s + lambda) * (s + lambda));
}

} // namespace learnid::test::drive
