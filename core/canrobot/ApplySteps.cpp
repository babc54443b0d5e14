#include "canrobot/ApplySteps.h"

#include "can/CanOpen.h"
#include "can/ManufacturerObjects.h"

#include <QCoreApplication>

namespace learnid {

QList<SdoStep> applySteps(const QList<int> &nodes, const Eigen::VectorXd &phi,
                          quint32 robotIdentity)
{
    const SdoWriteSequence sequence = objects::parameterWriteSequence(nodes, phi, robotIdentity);
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

} // namespace learnid
