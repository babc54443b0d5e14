#include "can/SdoAbortCode.h"

#include <QCoreApplication>

namespace learnid::sdoabort {

namespace {

struct Entry
{
    quint32 code;
    const char *text;
};

// QT_TRANSLATE_NOOP so that lupdate finds the texts; translated in message().
const Entry table[] = {
    {toggleBitNotAlternated, QT_TRANSLATE_NOOP("SdoAbortCode", "Toggle bit not alternated.")},
    {protocolTimeout, QT_TRANSLATE_NOOP("SdoAbortCode", "SDO protocol timed out.")},
    {invalidCommandSpecifier,
     QT_TRANSLATE_NOOP("SdoAbortCode", "Client/server command specifier not valid or unknown.")},
    {invalidBlockSize, QT_TRANSLATE_NOOP("SdoAbortCode", "Invalid block size (block mode only).")},
    {invalidSequenceNumber,
     QT_TRANSLATE_NOOP("SdoAbortCode", "Invalid sequence number (block mode only).")},
    {crcError, QT_TRANSLATE_NOOP("SdoAbortCode", "CRC error (block mode only).")},
    {outOfMemory, QT_TRANSLATE_NOOP("SdoAbortCode", "Out of memory.")},
    {unsupportedAccess, QT_TRANSLATE_NOOP("SdoAbortCode", "Unsupported access to an object.")},
    {writeOnly, QT_TRANSLATE_NOOP("SdoAbortCode", "Attempt to read a write-only object.")},
    {readOnly, QT_TRANSLATE_NOOP("SdoAbortCode", "Attempt to write a read-only object.")},
    {objectDoesNotExist,
     QT_TRANSLATE_NOOP("SdoAbortCode", "Object does not exist in the object dictionary.")},
    {cannotBeMapped, QT_TRANSLATE_NOOP("SdoAbortCode", "Object cannot be mapped to the PDO.")},
    {pdoLengthExceeded,
     QT_TRANSLATE_NOOP("SdoAbortCode",
                       "The number and length of the objects to be mapped would exceed the PDO "
                       "length.")},
    {parameterIncompatibility,
     QT_TRANSLATE_NOOP("SdoAbortCode", "General parameter incompatibility.")},
    {internalIncompatibility,
     QT_TRANSLATE_NOOP("SdoAbortCode", "General internal incompatibility in the device.")},
    {hardwareError, QT_TRANSLATE_NOOP("SdoAbortCode", "Access failed due to a hardware error.")},
    {lengthMismatch,
     QT_TRANSLATE_NOOP("SdoAbortCode",
                       "Data type does not match: the length of the service parameter does not "
                       "match.")},
    {lengthTooHigh,
     QT_TRANSLATE_NOOP("SdoAbortCode",
                       "Data type does not match: the length of the service parameter is too "
                       "high.")},
    {lengthTooLow,
     QT_TRANSLATE_NOOP("SdoAbortCode",
                       "Data type does not match: the length of the service parameter is too "
                       "low.")},
    {subIndexDoesNotExist, QT_TRANSLATE_NOOP("SdoAbortCode", "Sub-index does not exist.")},
    {invalidValue,
     QT_TRANSLATE_NOOP("SdoAbortCode", "Invalid value for the parameter (download only).")},
    {valueTooHigh,
     QT_TRANSLATE_NOOP("SdoAbortCode", "Value of the parameter written too high (download only).")},
    {valueTooLow,
     QT_TRANSLATE_NOOP("SdoAbortCode", "Value of the parameter written too low (download only).")},
    {maxBelowMin, QT_TRANSLATE_NOOP("SdoAbortCode", "Maximum value is less than minimum value.")},
    {resourceNotAvailable,
     QT_TRANSLATE_NOOP("SdoAbortCode", "Resource not available: SDO connection.")},
    {generalError, QT_TRANSLATE_NOOP("SdoAbortCode", "General error.")},
    {cannotStore,
     QT_TRANSLATE_NOOP("SdoAbortCode", "Data cannot be transferred or stored to the application.")},
    {cannotStoreLocalControl,
     QT_TRANSLATE_NOOP("SdoAbortCode",
                       "Data cannot be transferred or stored to the application because of "
                       "local control.")},
    {cannotStoreDeviceState,
     QT_TRANSLATE_NOOP("SdoAbortCode",
                       "Data cannot be transferred or stored to the application because of the "
                       "present device state.")},
    {noObjectDictionary,
     QT_TRANSLATE_NOOP("SdoAbortCode",
                       "Object dictionary dynamic generation failed or no object dictionary is "
                       "present.")},
    {noDataAvailable, QT_TRANSLATE_NOOP("SdoAbortCode", "No data available.")},
};

} // namespace

QString message(quint32 code)
{
    for (const Entry &e : table) {
        if (e.code == code)
            return QCoreApplication::translate("SdoAbortCode", e.text);
    }
    return QCoreApplication::translate("SdoAbortCode", "Unknown abort code %1.")
        .arg(codeText(code));
}

QString codeText(quint32 code)
{
    return QStringLiteral("0x%1")
        .arg(code, 8, 16, QLatin1Char('0'))
        .toUpper()
        .replace(QLatin1String("0X"), QLatin1String("0x"));
}

} // namespace learnid::sdoabort
