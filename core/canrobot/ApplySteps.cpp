#include "canrobot/ApplySteps.h"

#include "can/CanOpen.h"
#include "can/ManufacturerObjects.h"
#include "can/PayloadObjects.h"

#include <QCoreApplication>

namespace learnid {

namespace {

// The writes of a sequence, then each written object read back and compared bit for bit, then
// its stores.
QList<SdoStep> verifiedSteps(const SdoWriteSequence &sequence)
{
    QList<SdoStep> writes, readBacks, stores;
    for (const SdoWrite &w : sequence) {
        if (w.index == objects::storeParameters) {
            stores << SdoStep::write(w);
            continue;
        }
        writes << SdoStep::write(w);
        readBacks << SdoStep::read(w.node, w.index, w.subIndex, [w](const QByteArray &data) {
            if (data == w.raw)
                return QString();
            return QCoreApplication::translate("CanRobot",
                                               "node %1, object %2: read back %3 after writing %4 "
                                               "(%5 %6): nothing was stored")
                .arg(w.node)
                .arg(canopen::objectAddress(w.index, w.subIndex), canopen::hexBytes(data),
                     canopen::hexBytes(w.raw), w.dataType)
                .arg(w.value, 0, 'g', 9);
        });
    }
    return writes + readBacks + stores;
}

} // namespace

QList<SdoStep> applySteps(const QList<int> &nodes, const Eigen::VectorXd &phi,
                          quint32 robotIdentity)
{
    return verifiedSteps(objects::parameterWriteSequence(nodes, phi, robotIdentity));
}

QList<SdoStep> payloadApplySteps(const QList<int> &nodes, int joint, const Eigen::VectorXd &body)
{
    SdoWriteSequence sequence = objects::payloadWrites(nodes, joint, body);
    for (const int node : nodes) {
        sequence << SdoWrite::make(quint8(node), objects::storeParameters, objects::storeAll,
                                   canopen::DataType::Unsigned32, double(objects::saveSignature));
    }
    return verifiedSteps(sequence);
}

} // namespace learnid
