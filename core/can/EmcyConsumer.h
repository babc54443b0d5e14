#pragma once

#include <QByteArray>
#include <QCanBusFrame>
#include <QMetaType>
#include <QObject>
#include <optional>

namespace learnid {

class CanLink;

/// One emergency message (CiA 301 §7.2.7): 0x080 + node, error code (2 bytes), error register
/// (object 0x1001), 5 manufacturer-specific bytes.
struct EmcyMessage
{
    quint8 node = 0;
    quint16 errorCode = 0;
    quint8 errorRegister = 0;
    QByteArray manufacturerData; ///< 5 bytes

    /// Error code 0x0000: the node's errors are gone.
    bool isErrorReset() const { return errorCode == 0; }
    /// For the technician, e.g. "Node 2 emergency 0x8611: following error; error register
    /// 0x21: generic, device profile; manufacturer data 01 02 03 04 05" (translated).
    QString text() const;
};

/// The meaning of an emergency error code (CiA 301 table 21, CiA 402 additions): the exact
/// code when known, else its class (0xXX00, then 0xX000).
QString emcyErrorCodeText(quint16 errorCode);
/// The set bits of an error register, named: "generic, current, voltage, ...".
QString errorRegisterText(quint8 errorRegister);
/// The message in frame, nullopt when frame is not an EMCY (SYNC shares function code 1).
/// Frames shorter than 8 bytes are accepted when they hold code and register.
std::optional<EmcyMessage> decodeEmcy(const QCanBusFrame &frame);
/// Slave side: the EMCY frame of a message (manufacturer data zero padded / cut to 5 bytes).
QCanBusFrame encodeEmcy(const EmcyMessage &message);

/// Decodes the emergencies on a link and reports each.
class EmcyConsumer : public QObject
{
    Q_OBJECT

public:
    explicit EmcyConsumer(CanLink *link, QObject *parent = nullptr);

signals:
    void emergency(const learnid::EmcyMessage &message);
};

} // namespace learnid

Q_DECLARE_METATYPE(learnid::EmcyMessage)
