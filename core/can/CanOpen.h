#pragma once

#include <QByteArray>
#include <QString>
#include <QtGlobal>

/// CANopen (CiA 301) basics: the pre-defined connection set of COB-IDs and the little-endian
/// encoding of the basic data types.
namespace learnid::canopen {

constexpr int minNodeId = 1;
constexpr int maxNodeId = 127;
constexpr bool isValidNodeId(int node)
{
    return node >= minNodeId && node <= maxNodeId;
}

// Pre-defined connection set (CiA 301 §7.3.5). Node ids are 1..127.
constexpr quint32 nmtCobId = 0x000;
constexpr quint32 syncCobId = 0x080;
constexpr quint32 emcyCobId(quint8 node)
{
    return 0x080u + node;
}
/// TPDO1..4 (drive -> master): 0x180, 0x280, 0x380, 0x480 + node.
constexpr quint32 tpdoCobId(int pdo, quint8 node)
{
    return 0x080u + 0x100u * quint32(pdo) + node;
}
/// RPDO1..4 (master -> drive): 0x200, 0x300, 0x400, 0x500 + node.
constexpr quint32 rpdoCobId(int pdo, quint8 node)
{
    return 0x100u + 0x100u * quint32(pdo) + node;
}
/// SDO server -> client (the drive's answers).
constexpr quint32 sdoTxCobId(quint8 node)
{
    return 0x580u + node;
}
/// SDO client -> server (the master's requests).
constexpr quint32 sdoRxCobId(quint8 node)
{
    return 0x600u + node;
}
constexpr quint32 heartbeatCobId(quint8 node)
{
    return 0x700u + node;
}

/// The node id in a pre-defined COB-ID (the low 7 bits; 0 for NMT and SYNC).
constexpr quint8 nodeOfCobId(quint32 cobId)
{
    return quint8(cobId & 0x7Fu);
}
/// The function code of a pre-defined COB-ID (the high 4 of the 11 bits, shifted down).
constexpr int functionCodeOfCobId(quint32 cobId)
{
    return int((cobId >> 7) & 0xFu);
}

/// The basic data types of CiA 301 §7.1.6 that learnid uses; values are the data type indices.
enum class DataType : quint16 {
    Integer8 = 0x0002,
    Integer16 = 0x0003,
    Integer32 = 0x0004,
    Unsigned8 = 0x0005,
    Unsigned16 = 0x0006,
    Unsigned32 = 0x0007,
    Real32 = 0x0008,
    VisibleString = 0x0009,
    OctetString = 0x000A,
    Domain = 0x000F,
};

/// Size in bytes of a fixed-size type; 0 for the variable-size ones (strings, domain).
int dataTypeSize(DataType type);
bool isNumeric(DataType type);
/// The CiA 301 name, e.g. "UNSIGNED16", "REAL32" (used in parameter files and DCF).
QString dataTypeName(DataType type);
/// Inverse of dataTypeName; throws learnid::Error for an unknown name.
DataType dataTypeFromName(const QString &name);

/// Little-endian bytes of a numeric value. Throws learnid::Error when the value is not finite,
/// not an integer for an integer type, or outside the type's range (REAL32: beyond float).
QByteArray encodeValue(DataType type, double value);
/// The numeric value at offset in little-endian bytes. Throws learnid::Error when the bytes are
/// too short or the type is not numeric.
double decodeValue(DataType type, const QByteArray &bytes, int offset = 0);
/// Whether value fits the numeric type as encodeValue would accept it.
bool fitsType(DataType type, double value);

// Raw little-endian helpers; the caller guarantees offset + size <= bytes.size().
quint16 readU16(const QByteArray &bytes, int offset);
quint32 readU32(const QByteArray &bytes, int offset);
void writeU16(QByteArray &bytes, int offset, quint16 value);
void writeU32(QByteArray &bytes, int offset, quint32 value);

/// "0x2200:01": the way objects are named in messages.
QString objectAddress(quint16 index, quint8 subIndex);
/// "DE AD BE EF": bytes as shown to technicians.
QString hexBytes(const QByteArray &bytes);

} // namespace learnid::canopen
