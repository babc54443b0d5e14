#include "can/PayloadObjects.h"

#include "can/CanOpen.h"
#include "model/Error.h"

#include <QCoreApplication>

namespace learnid::objects {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadObjects)
};

const char *const kNames[payloadParameterCount] = {"m",   "m cx", "m cy", "m cz", "Ixx",
                                                   "Ixy", "Iyy",  "Ixz",  "Iyz",  "Izz"};

} // namespace

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
