#include "cansim/DriveDictionary.h"

#include "can/JointIdentity.h"
#include "can/ManufacturerObjects.h"
#include "can/PayloadObjects.h"
#include "can/Pdo.h"
#include "can/SdoAbortCode.h"

#include <cmath>

namespace learnid {

using canopen::DataType;
using Access = ObjectDictionary::Access;

namespace {

constexpr quint32 pdoInvalid = 0x80000000u;
constexpr quint32 pdoNoRtr = 0x40000000u;
constexpr quint8 synchronousEverySync = 1;

// PDO communication (0x1400 / 0x1800) and mapping (0x1600 / 0x1A00) of PDO 1 (CiA 301
// §7.5.2.35-38): only the pre-defined COB-ID, transmission type 1 and the trial mapping;
// the mapping changes only while the PDO is invalid and its count is 0.
void addPdoObjects(ObjectDictionary &od, quint8 node, PdoDirection direction)
{
    const quint16 comm = pdoCommunicationIndex(direction, 1);
    const quint16 map = pdoMappingIndex(direction, 1);
    const quint32 cobId = pdoCobId(direction, 1, node);
    const PdoMapping mapping = direction == PdoDirection::Receive ? objects::trialRpdoMapping()
                                                                  : objects::trialTpdoMapping();
    const ObjectDictionary *dictionary = &od;
    const auto pdoValid = [dictionary, comm] {
        return !(quint32(dictionary->value(comm, 1)) & pdoInvalid);
    };
    od.add(comm, 0, DataType::Unsigned8, Access::ReadOnly, 2);
    od.add(comm, 1, DataType::Unsigned32, Access::ReadWrite, cobId,
           [cobId](const QByteArray &raw) -> quint32 {
               const quint32 v = canopen::readU32(raw, 0);
               return (v & ~(pdoInvalid | pdoNoRtr)) == cobId ? 0 : sdoabort::invalidValue;
           });
    od.add(comm, 2, DataType::Unsigned8, Access::ReadWrite, synchronousEverySync,
           [](const QByteArray &raw) -> quint32 {
               return quint8(raw.at(0)) == synchronousEverySync ? 0 : sdoabort::invalidValue;
           });
    const int count = int(mapping.entries().size());
    od.add(map, 0, DataType::Unsigned8, Access::ReadWrite, count,
           [dictionary, map, mapping, count, pdoValid](const QByteArray &raw) -> quint32 {
               if (pdoValid())
                   return sdoabort::cannotStoreDeviceState;
               const int n = quint8(raw.at(0));
               if (n > count)
                   return sdoabort::pdoLengthExceeded;
               if (n == 0)
                   return 0;
               // Only the whole trial mapping can be activated.
               if (n != count)
                   return sdoabort::parameterIncompatibility;
               for (int i = 0; i < count; ++i) {
                   if (quint32(dictionary->value(map, quint8(i + 1))) !=
                       mapping.entries()[i].mappingValue())
                       return sdoabort::parameterIncompatibility;
               }
               return 0;
           });
    for (int i = 0; i < count; ++i) {
        const quint32 expected = mapping.entries()[i].mappingValue();
        od.add(map, quint8(i + 1), DataType::Unsigned32, Access::ReadWrite, expected,
               [dictionary, map, expected, pdoValid](const QByteArray &raw) -> quint32 {
                   if (pdoValid() || dictionary->value(map, 0) != 0)
                       return sdoabort::cannotStoreDeviceState;
                   return canopen::readU32(raw, 0) == expected ? 0 : sdoabort::cannotBeMapped;
               });
    }
}

} // namespace

namespace cansim {
quint32 ratedTorqueFor(double torqueLimit)
{
    // The small margin keeps REAL32 limits such as 0.1f (0.10000000149) at 4 mN m.
    return quint32(std::max(1.0, std::ceil(torqueLimit * ratedTorquePerLimit * 1000.0 - 1e-6)));
}
} // namespace cansim

QPair<quint8, qint8> interpolationPeriodFor(quint32 periodUs)
{
    for (int exponent = -3; exponent >= -6; --exponent) {
        const qint64 scale = qint64(std::llround(std::pow(10.0, 6 + exponent)));
        if (periodUs % scale == 0 && periodUs / scale <= 255)
            return {quint8(periodUs / scale), qint8(exponent)};
    }
    return {255, -6};
}

double interpolationPeriod(const ObjectDictionary &od)
{
    return od.value(objects::interpolationTimePeriod, 1) *
           std::pow(10.0, od.value(objects::interpolationTimePeriod, 2));
}

objects::ManufacturerDefaults manufacturerDefaults(const DriveNodeSettings &s)
{
    return {s.kp, s.ki, s.kd, s.lambda, s.torqueLimit, s.parameterCount};
}

void addDriveObjects(ObjectDictionary &od, const DriveNodeSettings &s)
{
    using namespace objects;
    const quint8 node = s.node;
    od.add(cansim::deviceType, 0, DataType::Unsigned32, Access::ReadOnly, cansim::deviceTypeServo);
    od.add(errorRegister, 0, DataType::Unsigned8, Access::ReadOnly, 0);
    od.add(cobIdSync, 0, DataType::Unsigned32, Access::ReadOnly, canopen::syncCobId);
    od.add(communicationCyclePeriod, 0, DataType::Unsigned32, Access::ReadOnly, s.syncPeriodUs);
    od.addBytes(deviceName, 0, DataType::VisibleString, Access::ReadOnly,
                QStringLiteral("learnid-robot-sim joint %1").arg(s.joint).toLatin1());
    od.add(storeParameters, 0, DataType::Unsigned8, Access::ReadOnly, storeAll);
    od.add(storeParameters, storeAll, DataType::Unsigned32, Access::WriteOnly, 0,
           [](const QByteArray &raw) -> quint32 {
               return canopen::readU32(raw, 0) == saveSignature ? 0 : sdoabort::cannotStore;
           });
    od.add(producerHeartbeatTime, 0, DataType::Unsigned16, Access::ReadWrite, 0);
    od.add(cansim::syncCounterOverflow, 0, DataType::Unsigned8, Access::ReadOnly,
           cansim::syncCounterMax);
    addPdoObjects(od, node, PdoDirection::Receive);
    addPdoObjects(od, node, PdoDirection::Transmit);
    od.add(identityObject, 0, DataType::Unsigned8, Access::ReadOnly, 4);
    od.add(identityObject, 1, DataType::Unsigned32, Access::ReadOnly, s.identity.vendorId);
    od.add(identityObject, 2, DataType::Unsigned32, Access::ReadOnly, s.identity.productCode);
    od.add(identityObject, 3, DataType::Unsigned32, Access::ReadOnly, s.identity.revision);
    od.add(identityObject, 4, DataType::Unsigned32, Access::ReadOnly, s.identity.serialNumber);
    od.add(jointIdentity, 0, DataType::Unsigned8, Access::ReadOnly, 2);
    od.add(jointIdentity, jointIdentityRobot, DataType::Unsigned32, Access::ReadWrite,
           s.robotIdentity);
    od.add(jointIdentity, jointIdentityJoint, DataType::Unsigned8, Access::ReadWrite,
           s.commissionedJoint, ObjectDictionary::rangeValidator(DataType::Unsigned8, 0, 127));
    // The payload (0x2500): none until a payload session's apply writes one.
    for (const ObjectDescription &o : payloadObjectDescriptions()) {
        od.add(o.index, o.subIndex, o.type, o.access, o.defaultValue, [o](const QByteArray &raw) {
            return writeAbortCode(o, canopen::decodeValue(o.type, raw));
        });
    }

    // The manufacturer objects as the one table describes them (the DCF and the docs follow it).
    for (const ObjectDescription &o : manufacturerObjects(manufacturerDefaults(s))) {
        od.add(o.index, o.subIndex, o.type, o.access, o.defaultValue, [o](const QByteArray &raw) {
            return writeAbortCode(o, canopen::decodeValue(o.type, raw));
        });
    }

    od.add(controlword, 0, DataType::Unsigned16, Access::ReadWrite, 0);
    od.add(statusword, 0, DataType::Unsigned16, Access::ReadOnly, 0);
    od.add(modesOfOperation, 0, DataType::Integer8, Access::ReadWrite, cyclicSynchronousPosition,
           [](const QByteArray &raw) -> quint32 {
               return qint8(raw.at(0)) == cyclicSynchronousPosition ? 0 : sdoabort::invalidValue;
           });
    od.add(modesOfOperationDisplay, 0, DataType::Integer8, Access::ReadOnly,
           cyclicSynchronousPosition);
    od.add(positionActual, 0, DataType::Integer32, Access::ReadOnly, 0);
    od.add(torqueActual, 0, DataType::Integer16, Access::ReadOnly, 0);
    od.add(targetPosition, 0, DataType::Integer32, Access::ReadWrite, 0);
    od.add(torqueOffset, 0, DataType::Integer16, Access::ReadWrite, 0);
    od.add(cansim::motorRatedTorque, 0, DataType::Unsigned32, Access::ReadOnly,
           cansim::ratedTorqueFor(double(float(s.torqueLimit))));
    od.add(cansim::positionEncoderResolution, 0, DataType::Unsigned8, Access::ReadOnly, 2);
    od.add(cansim::positionEncoderResolution, 1, DataType::Unsigned32, Access::ReadOnly,
           double(s.increments));
    od.add(cansim::positionEncoderResolution, 2, DataType::Unsigned32, Access::ReadOnly, 1);
    const auto [value, exponent] = interpolationPeriodFor(s.syncPeriodUs);
    od.add(interpolationTimePeriod, 0, DataType::Unsigned8, Access::ReadOnly, 2);
    od.add(interpolationTimePeriod, 1, DataType::Unsigned8, Access::ReadWrite, value,
           ObjectDictionary::rangeValidator(DataType::Unsigned8, 1, 255));
    od.add(interpolationTimePeriod, 2, DataType::Integer8, Access::ReadWrite, exponent,
           ObjectDictionary::rangeValidator(DataType::Integer8, -6, -1));
}

void resetCommunicationObjects(ObjectDictionary &od, quint8 node)
{
    od.setValue(objects::producerHeartbeatTime, 0, 0);
    for (const PdoDirection direction : {PdoDirection::Receive, PdoDirection::Transmit}) {
        const quint16 comm = pdoCommunicationIndex(direction, 1);
        const quint16 map = pdoMappingIndex(direction, 1);
        const PdoMapping mapping = direction == PdoDirection::Receive ? objects::trialRpdoMapping()
                                                                      : objects::trialTpdoMapping();
        od.setValue(comm, 1, pdoCobId(direction, 1, node));
        od.setValue(comm, 2, synchronousEverySync);
        for (int i = 0; i < mapping.entries().size(); ++i)
            od.setValue(map, quint8(i + 1), mapping.entries()[i].mappingValue());
        od.setValue(map, 0, double(mapping.entries().size()));
    }
}

bool trialPdoActive(const ObjectDictionary &od, bool receive)
{
    const PdoDirection direction = receive ? PdoDirection::Receive : PdoDirection::Transmit;
    const quint32 cobId = quint32(od.value(pdoCommunicationIndex(direction, 1), 1));
    return !(cobId & pdoInvalid) && od.value(pdoMappingIndex(direction, 1), 0) == 3;
}

} // namespace learnid
