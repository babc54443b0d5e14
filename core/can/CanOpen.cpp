#include "can/CanOpen.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QtEndian>
#include <cmath>
#include <cstring>
#include <limits>

namespace learnid::canopen {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CanOpen)
};

struct TypeInfo
{
    DataType type;
    const char *name;
    int size;
    double min;
    double max;
};

constexpr double floatMax = double(std::numeric_limits<float>::max());

const TypeInfo typeTable[] = {
    {DataType::Integer8, "INTEGER8", 1, -128.0, 127.0},
    {DataType::Integer16, "INTEGER16", 2, -32768.0, 32767.0},
    {DataType::Integer32, "INTEGER32", 4, -2147483648.0, 2147483647.0},
    {DataType::Unsigned8, "UNSIGNED8", 1, 0.0, 255.0},
    {DataType::Unsigned16, "UNSIGNED16", 2, 0.0, 65535.0},
    {DataType::Unsigned32, "UNSIGNED32", 4, 0.0, 4294967295.0},
    {DataType::Real32, "REAL32", 4, -floatMax, floatMax},
    {DataType::VisibleString, "VISIBLE_STRING", 0, 0.0, 0.0},
    {DataType::OctetString, "OCTET_STRING", 0, 0.0, 0.0},
    {DataType::Domain, "DOMAIN", 0, 0.0, 0.0},
};

const TypeInfo &info(DataType type)
{
    for (const TypeInfo &t : typeTable) {
        if (t.type == type)
            return t;
    }
    throw Error(
        Text::tr("Unknown CANopen data type 0x%1.").arg(quint16(type), 4, 16, QLatin1Char('0')));
}

} // namespace

int dataTypeSize(DataType type)
{
    return info(type).size;
}

bool isNumeric(DataType type)
{
    return info(type).size > 0;
}

QString dataTypeName(DataType type)
{
    return QString::fromLatin1(info(type).name);
}

DataType dataTypeFromName(const QString &name)
{
    for (const TypeInfo &t : typeTable) {
        if (name == QLatin1String(t.name))
            return t.type;
    }
    throw Error(Text::tr("Unknown CANopen data type \"%1\".").arg(name));
}

bool fitsType(DataType type, double value)
{
    const TypeInfo &t = info(type);
    if (t.size == 0 || !std::isfinite(value))
        return false;
    if (type != DataType::Real32 && std::trunc(value) != value)
        return false;
    return value >= t.min && value <= t.max;
}

QByteArray encodeValue(DataType type, double value)
{
    const TypeInfo &t = info(type);
    if (t.size == 0)
        throw Error(Text::tr("%1 is not a numeric type.").arg(dataTypeName(type)));
    if (!fitsType(type, value)) {
        throw Error(Text::tr("The value %1 does not fit the type %2 (range %3 to %4%5).")
                        .arg(value)
                        .arg(dataTypeName(type))
                        .arg(t.min)
                        .arg(t.max)
                        .arg(type == DataType::Real32 ? QString() : Text::tr(", integers only")));
    }
    QByteArray bytes(t.size, '\0');
    switch (type) {
    case DataType::Integer8:
    case DataType::Unsigned8:
        bytes[0] = char(quint8(qint64(value)));
        break;
    case DataType::Integer16:
    case DataType::Unsigned16:
        writeU16(bytes, 0, quint16(qint64(value)));
        break;
    case DataType::Integer32:
    case DataType::Unsigned32:
        writeU32(bytes, 0, quint32(qint64(value)));
        break;
    case DataType::Real32: {
        const float f = float(value);
        quint32 raw = 0;
        std::memcpy(&raw, &f, sizeof raw);
        writeU32(bytes, 0, raw);
        break;
    }
    default:
        break;
    }
    return bytes;
}

double decodeValue(DataType type, const QByteArray &bytes, int offset)
{
    const TypeInfo &t = info(type);
    if (t.size == 0)
        throw Error(Text::tr("%1 is not a numeric type.").arg(dataTypeName(type)));
    if (offset < 0 || offset + t.size > bytes.size()) {
        throw Error(Text::tr("%1 needs %2 bytes at offset %3, but only %4 bytes are present.")
                        .arg(dataTypeName(type))
                        .arg(t.size)
                        .arg(offset)
                        .arg(bytes.size()));
    }
    switch (type) {
    case DataType::Integer8:
        return double(qint8(bytes[offset]));
    case DataType::Unsigned8:
        return double(quint8(bytes[offset]));
    case DataType::Integer16:
        return double(qint16(readU16(bytes, offset)));
    case DataType::Unsigned16:
        return double(readU16(bytes, offset));
    case DataType::Integer32:
        return double(qint32(readU32(bytes, offset)));
    case DataType::Unsigned32:
        return double(readU32(bytes, offset));
    case DataType::Real32: {
        const quint32 raw = readU32(bytes, offset);
        float f = 0;
        std::memcpy(&f, &raw, sizeof f);
        return double(f);
    }
    default:
        return 0.0;
    }
}

quint16 readU16(const QByteArray &bytes, int offset)
{
    return qFromLittleEndian<quint16>(bytes.constData() + offset);
}

quint32 readU32(const QByteArray &bytes, int offset)
{
    return qFromLittleEndian<quint32>(bytes.constData() + offset);
}

void writeU16(QByteArray &bytes, int offset, quint16 value)
{
    qToLittleEndian<quint16>(value, bytes.data() + offset);
}

void writeU32(QByteArray &bytes, int offset, quint32 value)
{
    qToLittleEndian<quint32>(value, bytes.data() + offset);
}

QString objectAddress(quint16 index, quint8 subIndex)
{
    return QStringLiteral("0x%1:%2")
        .arg(index, 4, 16, QLatin1Char('0'))
        .arg(subIndex, 2, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

QString hexBytes(const QByteArray &bytes)
{
    return QString::fromLatin1(bytes.toHex(' ').toUpper());
}

} // namespace learnid::canopen
