#include "can/PayloadObjects.h"

#include "can/CanOpen.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <limits>

namespace learnid::objects {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadObjects)
};

const char *const kNames[payloadParameterCount] = {"m",   "m cx", "m cy", "m cz", "Ixx",
                                                   "Ixy", "Iyy",  "Ixz",  "Iyz",  "Izz"};
const char *const kUnits[payloadParameterCount] = {
    "kg", "kg m", "kg m", "kg m", "kg m^2", "kg m^2", "kg m^2", "kg m^2", "kg m^2", "kg m^2"};

} // namespace

QList<ObjectDescription> payloadObjectDescriptions()
{
    using Access = ObjectDictionary::Access;
    using canopen::DataType;
    constexpr double inf = std::numeric_limits<double>::infinity();
    constexpr double highest = payloadHighestSubIndex;
    // Names are not translated: DCF files are read by machines and drive vendors.
    QList<ObjectDescription> list = {
        {payload,
         0,
         DataType::Unsigned8,
         Access::ReadOnly,
         highest,
         {highest, true, highest},
         QStringLiteral("Highest sub-index supported"),
         {}},
        {payload,
         payloadJoint,
         DataType::Unsigned8,
         Access::ReadWrite,
         0,
         {0, true, 127},
         QStringLiteral("Payload joint"),
         {}},
    };
    for (int i = 0; i < payloadParameterCount; ++i) {
        list.append({payload,
                     quint8(payloadFirstParameter + i),
                     DataType::Real32,
                     Access::ReadWrite,
                     0,
                     {-inf, true, inf},
                     QStringLiteral("Payload %1").arg(QLatin1String(kNames[i])),
                     QLatin1String(kUnits[i])});
    }
    return list;
}

QList<SdoWrite> payloadWrites(const QList<int> &nodes, int joint, const Eigen::VectorXd &body)
{
    if (joint < 1 || joint > nodes.size()) {
        throw Error(Text::tr("The payload's joint %1 is not one of the robot's joints 1 to %2.")
                        .arg(joint)
                        .arg(nodes.size()));
    }
    if (body.size() != payloadParameterCount)
        throw Error(Text::tr("A payload has 10 parameters, not %1.").arg(body.size()));
    for (int i = 0; i < payloadParameterCount; ++i) {
        if (!canopen::fitsType(canopen::DataType::Real32, body[i])) {
            throw Error(Text::tr("Payload parameter %1 (%2) cannot be sent as REAL32.")
                            .arg(QLatin1String(kNames[i]))
                            .arg(body[i]));
        }
    }
    QList<SdoWrite> writes;
    for (const int node : nodes) {
        const auto id = quint8(node);
        writes << SdoWrite::make(id, payload, payloadJoint, canopen::DataType::Unsigned8, joint);
        for (int i = 0; i < payloadParameterCount; ++i)
            writes << SdoWrite::make(id, payload, quint8(payloadFirstParameter + i),
                                     canopen::DataType::Real32, body[i]);
    }
    return writes;
}

} // namespace learnid::objects
