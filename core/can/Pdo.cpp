#include "can/Pdo.h"

#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

using canopen::DataType;

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Pdo)
};

constexpr int maxPdoBits = 64;
constexpr quint32 pdoInvalidBit = 0x80000000u;

void checkPdoNumber(int pdo)
{
    if (pdo < 1 || pdo > 4)
        throw Error(Text::tr("PDO %1 does not exist; learnid uses PDO 1 to 4.").arg(pdo));
}

} // namespace

PdoMapping::PdoMapping(QList<PdoMappingEntry> entries)
    : m_entries(std::move(entries))
{
    const QString error = validationError(m_entries);
    if (!error.isEmpty())
        throw Error(error);
}

int PdoMapping::bitLength() const
{
    int bits = 0;
    for (const PdoMappingEntry &e : m_entries)
        bits += e.bitLength();
    return bits;
}

QString PdoMapping::validationError(const QList<PdoMappingEntry> &entries)
{
    int bits = 0;
    for (const PdoMappingEntry &e : entries) {
        if (!canopen::isNumeric(e.type)) {
            return Text::tr("Object %1 of type %2 cannot be mapped into a PDO.")
                .arg(canopen::objectAddress(e.index, e.subIndex), canopen::dataTypeName(e.type));
        }
        bits += e.bitLength();
    }
    if (bits > maxPdoBits) {
        return Text::tr("The mapped objects need %1 bits; a PDO holds at most %2 bits (8 bytes).")
            .arg(bits)
            .arg(maxPdoBits);
    }
    return {};
}

QByteArray PdoMapping::pack(const QList<double> &values) const
{
    if (values.size() != m_entries.size()) {
        throw Error(Text::tr("The PDO maps %1 objects but %2 values were given.")
                        .arg(m_entries.size())
                        .arg(values.size()));
    }
    QByteArray payload;
    payload.reserve(byteLength());
    for (int i = 0; i < m_entries.size(); ++i) {
        const PdoMappingEntry &e = m_entries[i];
        try {
            payload.append(canopen::encodeValue(e.type, values[i]));
        } catch (const Error &error) {
            throw Error(Text::tr("PDO object %1: %2")
                            .arg(canopen::objectAddress(e.index, e.subIndex), error.message()));
        }
    }
    return payload;
}

QList<double> PdoMapping::unpack(const QByteArray &payload) const
{
    if (payload.size() < byteLength()) {
        throw Error(Text::tr("The PDO carries %1 bytes; its mapping needs %2.")
                        .arg(payload.size())
                        .arg(byteLength()));
    }
    QList<double> values;
    values.reserve(m_entries.size());
    int offset = 0;
    for (const PdoMappingEntry &e : m_entries) {
        values.append(canopen::decodeValue(e.type, payload, offset));
        offset += canopen::dataTypeSize(e.type);
    }
    return values;
}

quint16 pdoCommunicationIndex(PdoDirection direction, int pdo)
{
    checkPdoNumber(pdo);
    return quint16((direction == PdoDirection::Receive ? 0x1400 : 0x1800) + pdo - 1);
}

quint16 pdoMappingIndex(PdoDirection direction, int pdo)
{
    checkPdoNumber(pdo);
    return quint16((direction == PdoDirection::Receive ? 0x1600 : 0x1A00) + pdo - 1);
}

quint32 pdoCobId(PdoDirection direction, int pdo, quint8 node)
{
    checkPdoNumber(pdo);
    return direction == PdoDirection::Receive ? canopen::rpdoCobId(pdo, node)
                                              : canopen::tpdoCobId(pdo, node);
}

SdoWriteSequence pdoConfigurationWrites(quint8 node, PdoDirection direction, int pdo,
                                        const PdoMapping &mapping, quint8 transmissionType)
{
    const quint16 comm = pdoCommunicationIndex(direction, pdo);
    const quint16 map = pdoMappingIndex(direction, pdo);
    const double cobId = pdoCobId(direction, pdo, node);
    SdoWriteSequence writes;
    writes << SdoWrite::make(node, comm, 1, DataType::Unsigned32, double(pdoInvalidBit) + cobId)
           << SdoWrite::make(node, comm, 2, DataType::Unsigned8, transmissionType)
           << SdoWrite::make(node, map, 0, DataType::Unsigned8, 0);
    quint8 sub = 1;
    for (const PdoMappingEntry &e : mapping.entries())
        writes << SdoWrite::make(node, map, sub++, DataType::Unsigned32, e.mappingValue());
    writes << SdoWrite::make(node, map, 0, DataType::Unsigned8, double(mapping.entries().size()))
           << SdoWrite::make(node, comm, 1, DataType::Unsigned32, cobId);
    return writes;
}

} // namespace learnid
