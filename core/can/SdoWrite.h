#pragma once

#include "can/CanOpen.h"

#include <QByteArray>
#include <QList>
#include <QMetaType>
#include <QString>

namespace learnid {

/// One SDO write as plain data: what "apply" and PDO configuration send, and what parameter
/// files record (canWrites, docs/file-formats.md#parameter-file).
struct SdoWrite
{
    quint8 node = 0;
    quint16 index = 0;
    quint8 subIndex = 0;
    QString dataType; ///< CiA 301 name, e.g. "REAL32" (canopen::dataTypeName)
    double value = 0; ///< the value in the object's unit
    QByteArray raw;   ///< the little-endian bytes sent

    /// Encodes value; throws learnid::Error when it does not fit the type or node is invalid.
    static SdoWrite make(quint8 node, quint16 index, quint8 subIndex, canopen::DataType type,
                         double value);
    /// "node 2: 0x2200:01 REAL32 = 20 (00 00 A0 41)"
    QString toString() const;

    friend bool operator==(const SdoWrite &a, const SdoWrite &b)
    {
        return a.node == b.node && a.index == b.index && a.subIndex == b.subIndex &&
               a.dataType == b.dataType && a.raw == b.raw;
    }
    friend bool operator!=(const SdoWrite &a, const SdoWrite &b) { return !(a == b); }
};

using SdoWriteSequence = QList<SdoWrite>;

} // namespace learnid

Q_DECLARE_METATYPE(learnid::SdoWrite)
