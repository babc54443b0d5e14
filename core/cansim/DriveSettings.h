#pragma once

#include "types/DriveIdentity.h"

#include <QString>
#include <QtGlobal>

namespace learnid {

/// The objects of a simulated drive that learnid's protocol uses besides those in
/// can/ManufacturerObjects.h, and the drive's fixed behaviour (docs/can-protocol.md).
namespace cansim {
constexpr quint16 deviceType = 0x1000;                ///< UNSIGNED32
constexpr quint32 deviceTypeServo = 0x00020192;       ///< CiA 402, servo drive
constexpr quint16 syncCounterOverflow = 0x1019;       ///< UNSIGNED8
constexpr quint8 syncCounterMax = 240;                ///< SYNC counters run 1..240
constexpr quint16 motorRatedTorque = 0x6076;          ///< UNSIGNED32 [mN m]
constexpr quint16 positionEncoderResolution = 0x608F; ///< sub 1 increments, sub 2 revolutions
constexpr double ratedTorquePerLimit = 1.0 / 25.0;    ///< rated torque = limit / 25
constexpr quint16 statusFollowsCommand = 0x1000;      ///< statusword bit 12 in csp mode
constexpr quint16 emcyCommunication = 0x8100;         ///< missed set-points
constexpr quint16 emcyFollowingError = 0x8611;        ///< injected fault
constexpr quint8 errorRegisterGeneric = 0x01;
constexpr quint8 errorRegisterCommunication = 0x10;
constexpr quint8 errorRegisterDeviceProfile = 0x20;
constexpr int missedSetPointLimit = 3; ///< consecutive SYNCs without a set-point -> fault
constexpr int quickStopSyncs = 10;     ///< SYNCs of holding in Quick stop active
constexpr qint64 idealIncrements = qint64(1) << 24; ///< encoder increments for an ideal encoder
constexpr quint32 vendorId = 0x4C4E4944;            ///< 0x1018:01 of the simulated drives ("LNID")
constexpr quint32 productCode = 0x00000402;         ///< 0x1018:02
constexpr quint32 revision = 0x00010000;            ///< 0x1018:03
constexpr quint32 firstSerial = 1000;               ///< 0x1018:04 of joint j's drive: 1000 + j

/// The identity of the simulated drive that moves joint (1-based).
inline DriveIdentity driveIdentityOfJoint(int joint)
{
    return {vendorId, productCode, revision, firstSerial + quint32(joint)};
}

/// Motor rated torque [mN m] of a torque limit [N m]: limit / 25 rounded up to 1 mN m, so that
/// the limit is about 25,000 per mille and INTEGER16 torques reach 1.3 times the limit.
quint32 ratedTorqueFor(double torqueLimit);
} // namespace cansim

/// What a simulated drive node starts with; SDO writes change the dictionary afterwards.
struct DriveNodeSettings
{
    quint8 node = 1;
    int joint = 1;                               ///< 1-based joint number, for the device name
    double kp = 4500.0;                          ///< [N m/rad]
    double ki = 30.0;                            ///< [N m/(rad s)]
    double kd = 600.0;                           ///< [N m s/rad]
    double lambda = 200.0;                       ///< derivative filter [rad/s]
    double torqueLimit = 8.0;                    ///< [N m]
    qint64 increments = cansim::idealIncrements; ///< encoder increments per revolution
    int parameterCount = 3;                      ///< entries 0x2200:1..m
    quint32 syncPeriodUs = 2000; ///< 0x1006 and the default interpolation period 0x60C2
    int setPointTimeoutSyncs = cansim::missedSetPointLimit; ///< SYNCs without one -> fault
    DriveIdentity identity;    ///< 0x1018: the drive itself, whatever node id it answers to
    quint32 robotIdentity = 0; ///< 0x2400:01 at power on (0: never commissioned)
    int commissionedJoint = 0; ///< 0x2400:02 at power on (0: never commissioned)
};

} // namespace learnid
