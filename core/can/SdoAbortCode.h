#pragma once

#include <QString>
#include <QtGlobal>

/// The SDO abort codes of CiA 301 §7.2.4.3.17 and their meaning in plain English.
namespace learnid::sdoabort {

constexpr quint32 toggleBitNotAlternated = 0x05030000;
constexpr quint32 protocolTimeout = 0x05040000;
constexpr quint32 invalidCommandSpecifier = 0x05040001;
constexpr quint32 invalidBlockSize = 0x05040002;
constexpr quint32 invalidSequenceNumber = 0x05040003;
constexpr quint32 crcError = 0x05040004;
constexpr quint32 outOfMemory = 0x05040005;
constexpr quint32 unsupportedAccess = 0x06010000;
constexpr quint32 writeOnly = 0x06010001;
constexpr quint32 readOnly = 0x06010002;
constexpr quint32 objectDoesNotExist = 0x06020000;
constexpr quint32 cannotBeMapped = 0x06040041;
constexpr quint32 pdoLengthExceeded = 0x06040042;
constexpr quint32 parameterIncompatibility = 0x06040043;
constexpr quint32 internalIncompatibility = 0x06040047;
constexpr quint32 hardwareError = 0x06060000;
constexpr quint32 lengthMismatch = 0x06070010;
constexpr quint32 lengthTooHigh = 0x06070012;
constexpr quint32 lengthTooLow = 0x06070013;
constexpr quint32 subIndexDoesNotExist = 0x06090011;
constexpr quint32 invalidValue = 0x06090030;
constexpr quint32 valueTooHigh = 0x06090031;
constexpr quint32 valueTooLow = 0x06090032;
constexpr quint32 maxBelowMin = 0x06090036;
constexpr quint32 resourceNotAvailable = 0x060A0023;
constexpr quint32 generalError = 0x08000000;
constexpr quint32 cannotStore = 0x08000020;
constexpr quint32 cannotStoreLocalControl = 0x08000021;
constexpr quint32 cannotStoreDeviceState = 0x08000022;
constexpr quint32 noObjectDictionary = 0x08000023;
constexpr quint32 noDataAvailable = 0x08000024;

/// The meaning of an abort code in plain English, translated; an unknown code says so and
/// names the code. The code itself is not part of the text (callers add it as "(0x...)").
QString message(quint32 code);

/// "0x06020000": the way codes are shown next to their message.
QString codeText(quint32 code);

} // namespace learnid::sdoabort
