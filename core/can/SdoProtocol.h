#pragma once

#include <QByteArray>
#include <QCanBusFrame>
#include <QtGlobal>

/// The SDO frame layout of CiA 301 §7.2.4.3, shared by SdoClient and SdoServer.
/// Every SDO frame has 8 data bytes; byte 0 holds the command specifier in bits 7..5.
namespace learnid::sdo {

// Client command specifiers (requests on 0x600 + node).
constexpr int ccsDownloadSegment = 0;
constexpr int ccsInitiateDownload = 1;
constexpr int ccsInitiateUpload = 2;
constexpr int ccsUploadSegment = 3;
constexpr int csAbort = 4;
constexpr int ccsBlockUpload = 5;
constexpr int ccsBlockDownload = 6;
// Server command specifiers (responses on 0x580 + node).
constexpr int scsUploadSegment = 0;
constexpr int scsDownloadSegment = 1;
constexpr int scsInitiateUpload = 2;
constexpr int scsInitiateDownload = 3;

constexpr int frameSize = 8;
constexpr int expeditedMaxSize = 4;
constexpr int segmentDataSize = 7;

// Bits of byte 0.
constexpr quint8 toggleBit = 0x10;
constexpr quint8 expeditedBit = 0x02;
constexpr quint8 sizeIndicatedBit = 0x01;
constexpr quint8 lastSegmentBit = 0x01;

/// The payload padded (or cut) to the 8 bytes of an SDO frame.
QByteArray normalised(const QByteArray &payload);
inline int commandSpecifier(const QByteArray &p)
{
    return (quint8(p.at(0)) >> 5) & 0x7;
}
inline bool toggle(const QByteArray &p)
{
    return (quint8(p.at(0)) & toggleBit) != 0;
}
quint16 index(const QByteArray &p);
inline quint8 subIndex(const QByteArray &p)
{
    return quint8(p.at(3));
}
/// The abort code of an abort frame (bytes 4..7).
quint32 abortCode(const QByteArray &p);

/// An initiate frame: byte 0, index, sub-index, then the 4 bytes of data or size.
QByteArray initiate(quint8 byte0, quint16 index, quint8 subIndex, const QByteArray &data = {});
/// A segment frame: byte 0 then up to 7 bytes of data, zero padded.
QByteArray segment(quint8 byte0, const QByteArray &data = {});
QByteArray abort(quint16 index, quint8 subIndex, quint32 code);

/// Byte 0 of an expedited transfer of size 1..4 bytes (e = 1, s = 1, n = 4 - size).
quint8 expeditedByte0(int commandSpecifier, int size);
/// The data size of an expedited initiate frame (4 when the size is not indicated).
int expeditedSize(const QByteArray &p);
/// Byte 0 of a segment: toggle, n = 7 - size in bits 3..1, c = last.
quint8 segmentByte0(int commandSpecifier, bool toggle, int size, bool last);
/// The data size of a segment frame (7 - n).
inline int segmentSize(const QByteArray &p)
{
    return 7 - ((quint8(p.at(0)) >> 1) & 0x7);
}
inline bool isLastSegment(const QByteArray &p)
{
    return (quint8(p.at(0)) & lastSegmentBit) != 0;
}

QCanBusFrame makeFrame(quint32 cobId, const QByteArray &payload);

} // namespace learnid::sdo
