#include "can/SdoWrite.h"

#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

SdoWrite SdoWrite::make(quint8 node, quint16 index, quint8 subIndex, canopen::DataType type,
                        double value)
{
    if (!canopen::isValidNodeId(node)) {
        throw Error(
            QCoreApplication::translate("SdoWrite", "%1 is not a valid CANopen node id (1 to 127).")
                .arg(node));
    }
    SdoWrite w;
    w.node = node;
    w.index = index;
    w.subIndex = subIndex;
    w.dataType = canopen::dataTypeName(type);
    try {
        w.raw = canopen::encodeValue(type, value);
    } catch (const Error &e) {
        throw Error(QCoreApplication::translate("SdoWrite", "Node %1, object %2: %3")
                        .arg(node)
                        .arg(canopen::objectAddress(index, subIndex), e.message()));
    }
    w.value = canopen::decodeValue(type, w.raw); // what the node will hold (REAL32 rounding)
    return w;
}

QString SdoWrite::toString() const
{
    // 9 significant digits round-trip a float; integers up to 32 bits print exactly.
    const QString number = dataType == canopen::dataTypeName(canopen::DataType::Real32)
                               ? QString::number(value, 'g', 9)
                               : QString::number(qint64(value));
    return QStringLiteral("node %1: %2 %3 = %4 (%5)")
        .arg(node)
        .arg(canopen::objectAddress(index, subIndex), dataType, number, canopen::hexBytes(raw));
}

} // namespace learnid
