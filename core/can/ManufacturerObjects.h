#pragma once

#include "can/CanOpen.h"
#include "can/ObjectDictionary.h"
#include "can/Pdo.h"
#include "can/SdoWrite.h"

#include <Eigen/Core>
#include <QList>

/// The objects learnid reads and writes on a drive (one CANopen node per joint): our
/// manufacturer objects and the CiA 301 / CiA 402 standard objects a trial uses.
/// docs/ describes them for drive vendors; the DCF fragment of a parameter file uses them.
namespace learnid::objects {

// --- Manufacturer objects --------------------------------------------------------------
/// Joint controller gains, REAL32 each, SI units.
constexpr quint16 gains = 0x2100;
constexpr quint8 gainKp = 1;     ///< [N m/rad]
constexpr quint8 gainKi = 2;     ///< [N m/(rad s)]
constexpr quint8 gainKd = 3;     ///< [N m s/rad]
constexpr quint8 gainLambda = 4; ///< derivative filter lambda [1/s]
/// Identified dynamic parameters: sub 0 the count (UNSIGNED8), sub i = phi_i (REAL32, SI units).
constexpr quint16 identifiedParameters = 0x2200;
constexpr int maxIdentifiedParameters = 254;
/// Torque limit of the joint, REAL32 [N m], sub 0.
constexpr quint16 torqueLimit = 0x2300;

// --- CiA 301 communication objects ------------------------------------------------------
constexpr quint16 errorRegister = 0x1001;            ///< UNSIGNED8
constexpr quint16 cobIdSync = 0x1005;                ///< UNSIGNED32
constexpr quint16 communicationCyclePeriod = 0x1006; ///< SYNC period, UNSIGNED32 [us]
constexpr quint16 deviceName = 0x1008;               ///< VISIBLE_STRING
constexpr quint16 storeParameters = 0x1010;          ///< sub 1: save all, UNSIGNED32
constexpr quint8 storeAll = 1;
constexpr quint32 saveSignature = 0x65766173;     ///< "save" in ASCII, little-endian
constexpr quint16 producerHeartbeatTime = 0x1017; ///< UNSIGNED16 [ms]

// --- CiA 402 drive objects -----------------------------------------------------------------
constexpr quint16 controlword = 0x6040;             ///< UNSIGNED16
constexpr quint16 statusword = 0x6041;              ///< UNSIGNED16
constexpr quint16 modesOfOperation = 0x6060;        ///< INTEGER8
constexpr quint16 modesOfOperationDisplay = 0x6061; ///< INTEGER8
constexpr qint8 cyclicSynchronousPosition = 8;      ///< mode of operation of a trial
constexpr quint16 positionActual = 0x6064;          ///< INTEGER32 [encoder counts]
constexpr quint16 torqueActual = 0x6077;            ///< INTEGER16 [per mille of rated torque]
constexpr quint16 targetPosition = 0x607A;          ///< INTEGER32 [encoder counts]
constexpr quint16 torqueOffset = 0x60B2;            ///< INTEGER16 [per mille of rated torque]
/// Interpolation time period: sub 1 the value (UNSIGNED8), sub 2 the exponent (INTEGER8),
/// period = value * 10^exponent s (2 ms: 2, -3).
constexpr quint16 interpolationTimePeriod = 0x60C2;

/// What a drive holds before anything is written: its own joint's gains and torque limit (the
/// controller's configuration) and room for parameterCount identified parameters.
struct ManufacturerDefaults
{
    double kp = 0.0;          ///< [N m/rad]
    double ki = 0.0;          ///< [N m/(rad s)]
    double kd = 0.0;          ///< [N m s/rad]
    double lambda = 0.0;      ///< derivative filter bandwidth [rad/s]
    double torqueLimit = 0.0; ///< [N m]
    int parameterCount = 0;   ///< entries 0x2200:01..m (at most maxIdentifiedParameters)
};

/// The values a write may take: finite, above min (or equal to it when minIncluded), at most max.
struct ValueRange
{
    double min;
    bool minIncluded;
    double max;
};

/// One manufacturer object entry of a drive: the one description that the simulated drive's
/// dictionary, the DCF fragment and docs/can-protocol.md §2.2 follow.
struct ObjectDescription
{
    quint16 index;
    quint8 subIndex;
    canopen::DataType type;
    ObjectDictionary::Access access;
    double defaultValue; ///< what the drive holds after power-on without a stored set
    ValueRange range;    ///< of a write (writeAbortCode); meaningless for read-only entries
    QString name;        ///< parameter name as in a DCF, e.g. "Gain kp" (untranslated)
    QString unit;        ///< SI unit, empty when none
};

/// CiA 301 object code of a manufacturer object: 0x7 VAR, 0x8 ARRAY, 0x9 RECORD.
int objectCode(quint16 index);

/// The manufacturer objects of a drive, in index and sub-index order: 0x2100:00..04 (gains, a
/// RECORD), 0x2200:00..m (the count, read-write, and the identified parameters, an ARRAY),
/// 0x2300:00 (torque limit, a VAR).
QList<ObjectDescription> manufacturerObjects(const ManufacturerDefaults &defaults);

/// The abort code a drive answers to an SDO write of value to o: 0 to accept; 0x06090030 not
/// finite, 0x06090032 below the range, 0x06090031 above it.
quint32 writeAbortCode(const ObjectDescription &o, double value);

/// The mapping of a trial's RPDO1: target position, torque offset, controlword (8 bytes).
PdoMapping trialRpdoMapping();
/// The mapping of a trial's TPDO1: position actual, torque actual, statusword (8 bytes).
PdoMapping trialTpdoMapping();

/// The exact SDO writes "apply" performs (docs/can-protocol.md §8, Apply): for each node the
/// count then each parameter to 0x2200; after every node holds them (and the caller has read
/// them back), 0x1010:01 = "save" on each node, so that no drive stores a half-written set.
/// phi: identified parameters in SI units (n). With a robot identity (not 0) the joint identity
/// of every node (JointIdentity.h, 0x2400:01..02) follows the parameters, before the stores.
/// Throws learnid::Error for an empty or non-finite phi, more than 254 parameters, invalid or
/// repeated node ids.
SdoWriteSequence parameterWriteSequence(const QList<int> &nodes, const Eigen::VectorXd &phi,
                                        quint32 robotIdentity = 0);

} // namespace learnid::objects
