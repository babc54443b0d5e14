#include "can/SdoProtocol.h"

#include "can/CanOpen.h"

namespace learnid::sdo {

QByteArray normalised(const QByteArray &payload)
{
    QByteArray p = payload.left(frameSize);
    if (p.size() < frameSize)
        p.append(QByteArray(frameSize - p.size(), '\0'));
    return p;
}

quint16 index(const QByteArray &p)
{
    return canopen::readU16(p, 1);
}

quint32 abortCode(const QByteArray &p)
{
    return canopen::readU32(p, 4);
}

QByteArray initiate(quint8 byte0, quint16 index, quint8 subIndex, const QByteArray &data)
{
    QByteArray p(frameSize, '\0');
    p[0] = char(byte0);
    canopen::writeU16(p, 1, index);
    p[3] = char(subIndex);
    for (int i = 0; i < qMin<qsizetype>(4, data.size()); ++i)
        p[4 + i] = data[i];
    return p;
}

QByteArray segment(quint8 byte0, const QByteArray &data)
{
    QByteArray p(frameSize, '\0');
    p[0] = char(byte0);
    for (int i = 0; i < qMin<qsizetype>(segmentDataSize, data.size()); ++i)
        p[1 + i] = data[i];
    return p;
}

QByteArray abort(quint16 index, quint8 subIndex, quint32 code)
{
    QByteArray p = initiate(quint8(csAbort << 5), index, subIndex);
    canopen::writeU32(p, 4, code);
    return p;
}

quint8 expeditedByte0(int commandSpecifier, int size)
{
    return quint8((commandSpecifier << 5) | ((expeditedMaxSize - size) << 2) | expeditedBit |
                  sizeIndicatedBit);
}

int expeditedSize(const QByteArray &p)
{
    const quint8 b = quint8(p.at(0));
    if (!(b & sizeIndicatedBit))
        return expeditedMaxSize;
    return expeditedMaxSize - ((b >> 2) & 0x3);
}

quint8 segmentByte0(int commandSpecifier, bool toggle, int size, bool last)
{
    return quint8((commandSpecifier << 5) | (toggle ? toggleBit : 0) |
                  ((segmentDataSize - size) << 1) | (last ? lastSegmentBit : 0));
}

QCanBusFrame makeFrame(quint32 cobId, const QByteArray &payload)
{
    return QCanBusFrame(cobId, normalised(payload));
}

} // namespace learnid::sdo
