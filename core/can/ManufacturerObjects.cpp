#include "can/ManufacturerObjects.h"

#include "can/JointIdentity.h"
#include "can/PayloadObjects.h"
#include "can/SdoAbortCode.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QSet>
#include <cmath>
#include <limits>

namespace learnid::objects {

using canopen::DataType;

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ManufacturerObjects)
};

} // namespace

int objectCode(quint16 index)
{
    switch (index) {
    case gains:
    case payload:
        return 0x9;
    case identifiedParameters:
        return 0x8;
    default:
        return 0x7;
    }
}

QList<ObjectDescription> manufacturerObjects(const ManufacturerDefaults &d)
{
    using Access = ObjectDictionary::Access;
    constexpr double inf = std::numeric_limits<double>::infinity();
    constexpr ValueRange positive{0.0, false, inf};
    constexpr ValueRange nonNegative{0.0, true, inf};
    constexpr ValueRange anyFinite{-inf, true, inf};
    const int m = qBound(0, d.parameterCount, maxIdentifiedParameters);
    // Names are not translated: DCF files are read by machines and drive vendors.
    const auto s = [](const char *text) {
        return QString::fromLatin1(text);
    };
    QList<ObjectDescription> list = {
        {gains,
         0,
         DataType::Unsigned8,
         Access::ReadOnly,
         4,
         {4, true, 4},
         s("Highest sub-index supported"),
         {}},
        {gains, gainKp, DataType::Real32, Access::ReadWrite, d.kp, positive, s("Gain kp"),
         s("N m/rad")},
        {gains, gainKi, DataType::Real32, Access::ReadWrite, d.ki, nonNegative, s("Gain ki"),
         s("N m/(rad s)")},
        {gains, gainKd, DataType::Real32, Access::ReadWrite, d.kd, nonNegative, s("Gain kd"),
         s("N m s/rad")},
        {gains, gainLambda, DataType::Real32, Access::ReadWrite, d.lambda, positive,
         s("Derivative filter lambda"), s("rad/s")},
        {identifiedParameters,
         0,
         DataType::Unsigned8,
         Access::ReadWrite,
         0,
         {0, true, double(m)},
         s("Number of identified parameters"),
         {}},
    };
    for (int i = 1; i <= m; ++i) {
        list.append({identifiedParameters, quint8(i), DataType::Real32, Access::ReadWrite, 0,
                     anyFinite, s("Identified parameter %1").arg(i), s("SI")});
    }
    list.append({torqueLimit,
                 0,
                 DataType::Real32,
                 Access::ReadWrite,
                 d.torqueLimit,
                 {0.0, false, 1e6},
                 s("Torque limit"),
                 s("N m")});
    return list;
}

quint32 writeAbortCode(const ObjectDescription &o, double value)
{
    if (!std::isfinite(value))
        return sdoabort::invalidValue;
    if (value < o.range.min || (!o.range.minIncluded && value == o.range.min))
        return sdoabort::valueTooLow;
    if (value > o.range.max)
        return sdoabort::valueTooHigh;
    return 0;
}

PdoMapping trialRpdoMapping()
{
    return PdoMapping({{targetPosition, 0, DataType::Integer32},
                       {torqueOffset, 0, DataType::Integer16},
                       {controlword, 0, DataType::Unsigned16}});
}

PdoMapping trialTpdoMapping()
{
    return PdoMapping({{positionActual, 0, DataType::Integer32},
                       {torqueActual, 0, DataType::Integer16},
                       {statusword, 0, DataType::Unsigned16}});
}

SdoWriteSequence parameterWriteSequence(const QList<int> &nodes, const Eigen::VectorXd &phi,
                                        quint32 robotIdentity)
{
    if (nodes.isEmpty())
        throw Error(Text::tr("No node to write the parameters to."));
    if (phi.size() == 0 || phi.size() > maxIdentifiedParameters) {
        throw Error(Text::tr("A parameter set holds 1 to %1 parameters, not %2.")
                        .arg(maxIdentifiedParameters)
                        .arg(phi.size()));
    }
    QSet<int> seen;
    for (const int node : nodes) {
        if (!canopen::isValidNodeId(node))
            throw Error(Text::tr("%1 is not a valid CANopen node id (1 to 127).").arg(node));
        if (seen.contains(node))
            throw Error(Text::tr("Node %1 is listed twice.").arg(node));
        seen.insert(node);
    }
    for (Eigen::Index i = 0; i < phi.size(); ++i) {
        if (!canopen::fitsType(DataType::Real32, phi[i])) {
            throw Error(
                Text::tr("Parameter %1 (%2) cannot be sent as REAL32.").arg(i + 1).arg(phi[i]));
        }
    }
    SdoWriteSequence writes;
    for (const int node : nodes) {
        const quint8 id = quint8(node);
        writes << SdoWrite::make(id, identifiedParameters, 0, DataType::Unsigned8,
                                 double(phi.size()));
        for (Eigen::Index i = 0; i < phi.size(); ++i)
            writes << SdoWrite::make(id, identifiedParameters, quint8(i + 1), DataType::Real32,
                                     phi[i]);
    }
    if (robotIdentity != 0) // the joint identity, stored with the parameters
        writes << jointIdentityWrites(nodes, robotIdentity);
    for (const int node : nodes) {
        writes << SdoWrite::make(quint8(node), storeParameters, storeAll, DataType::Unsigned32,
                                 double(saveSignature));
    }
    return writes;
}

} // namespace learnid::objects
