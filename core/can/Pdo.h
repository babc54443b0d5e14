#pragma once

#include "can/CanOpen.h"
#include "can/SdoWrite.h"

#include <QByteArray>
#include <QList>

namespace learnid {

/// One object mapped into a PDO. The data type (not only the bit length of the mapping
/// parameter) is kept because packing needs the signedness.
struct PdoMappingEntry
{
    quint16 index = 0;
    quint8 subIndex = 0;
    canopen::DataType type = canopen::DataType::Unsigned8;

    int bitLength() const { return 8 * canopen::dataTypeSize(type); }
    /// The UNSIGNED32 of a mapping parameter sub-entry (0x1600/0x1A00:n): index, sub, bits.
    quint32 mappingValue() const
    {
        return (quint32(index) << 16) | (quint32(subIndex) << 8) | quint32(bitLength());
    }
    friend bool operator==(const PdoMappingEntry &a, const PdoMappingEntry &b)
    {
        return a.index == b.index && a.subIndex == b.subIndex && a.type == b.type;
    }
};

/// The objects of one PDO in frame order, packed little-endian back to back (CiA 301 §7.2.2).
class PdoMapping
{
public:
    PdoMapping() = default;
    /// Throws learnid::Error when the mapping is invalid (see validationError()).
    explicit PdoMapping(QList<PdoMappingEntry> entries);

    const QList<PdoMappingEntry> &entries() const { return m_entries; }
    int bitLength() const;
    int byteLength() const { return (bitLength() + 7) / 8; }

    /// Why entries cannot form a PDO (a non-numeric type, more than 64 bits), or empty.
    static QString validationError(const QList<PdoMappingEntry> &entries);

    /// The PDO payload of one value per entry (in the entry's unit, e.g. encoder counts).
    /// Throws learnid::Error on a wrong count or a value outside its type.
    QByteArray pack(const QList<double> &values) const;
    /// The values in a payload; throws learnid::Error when the payload is shorter than the
    /// mapping (longer payloads are accepted, the rest ignored).
    QList<double> unpack(const QByteArray &payload) const;

private:
    QList<PdoMappingEntry> m_entries;
};

/// RPDO: master -> drive; TPDO: drive -> master.
enum class PdoDirection { Receive, Transmit };

/// 0x1400 + pdo - 1 (RPDO) or 0x1800 + pdo - 1 (TPDO); pdo is 1..4.
quint16 pdoCommunicationIndex(PdoDirection direction, int pdo);
/// 0x1600 + pdo - 1 (RPDO) or 0x1A00 + pdo - 1 (TPDO).
quint16 pdoMappingIndex(PdoDirection direction, int pdo);
/// The pre-defined COB-ID of the PDO (see canopen::rpdoCobId / tpdoCobId).
quint32 pdoCobId(PdoDirection direction, int pdo, quint8 node);

/// The SDO writes that configure PDO pdo (1..4) of node with mapping (CiA 301 §7.5.2.35):
/// disable the PDO (COB-ID bit 31 set), set the transmission type (1: every SYNC), clear the
/// mapping count, write each entry, set the count, enable the PDO with the pre-defined COB-ID.
/// Throws learnid::Error for an invalid node or pdo number.
SdoWriteSequence pdoConfigurationWrites(quint8 node, PdoDirection direction, int pdo,
                                        const PdoMapping &mapping, quint8 transmissionType = 1);

} // namespace learnid
