#include "can/JointIdentity.h"

#include "can/CanOpen.h"

namespace learnid::objects {

quint32 robotIdentityOf(const QString &modelId)
{
    quint32 crc = 0xFFFFFFFFu;
    for (const char byte : modelId.toUtf8()) {
        crc ^= quint8(byte);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    crc = ~crc;
    return crc == 0 ? 1 : crc;
}

QList<SdoWrite> jointIdentityWrites(const QList<int> &nodes, quint32 robot)
{
    QList<SdoWrite> writes;
    for (int j = 0; j < nodes.size(); ++j) {
        const auto node = quint8(nodes[j]);
        writes << SdoWrite::make(node, jointIdentity, jointIdentityRobot,
                                 canopen::DataType::Unsigned32, robot)
               << SdoWrite::make(node, jointIdentity, jointIdentityJoint,
                                 canopen::DataType::Unsigned8, j + 1);
    }
    return writes;
}

} // namespace learnid::objects
