#include "can/EmcyConsumer.h"

#include "can/CanLink.h"
#include "can/CanLogging.h"
#include "can/CanOpen.h"

#include <QCoreApplication>
#include <QStringList>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(EmcyConsumer)
};

struct CodeText
{
    quint16 code;
    const char *text;
};

const CodeText codeTable[] = {
    {0x0000, QT_TRANSLATE_NOOP("EmcyConsumer", "error reset or no error")},
    {0x1000, QT_TRANSLATE_NOOP("EmcyConsumer", "generic error")},
    {0x2000, QT_TRANSLATE_NOOP("EmcyConsumer", "current")},
    {0x2100, QT_TRANSLATE_NOOP("EmcyConsumer", "current, device input side")},
    {0x2200, QT_TRANSLATE_NOOP("EmcyConsumer", "current inside the device")},
    {0x2300, QT_TRANSLATE_NOOP("EmcyConsumer", "current, device output side")},
    {0x2310, QT_TRANSLATE_NOOP("EmcyConsumer", "continuous over-current")},
    {0x2320, QT_TRANSLATE_NOOP("EmcyConsumer", "short circuit or earth leakage")},
    {0x3000, QT_TRANSLATE_NOOP("EmcyConsumer", "voltage")},
    {0x3100, QT_TRANSLATE_NOOP("EmcyConsumer", "mains voltage")},
    {0x3200, QT_TRANSLATE_NOOP("EmcyConsumer", "voltage inside the device")},
    {0x3210, QT_TRANSLATE_NOOP("EmcyConsumer", "DC link over-voltage")},
    {0x3220, QT_TRANSLATE_NOOP("EmcyConsumer", "DC link under-voltage")},
    {0x3300, QT_TRANSLATE_NOOP("EmcyConsumer", "output voltage")},
    {0x4000, QT_TRANSLATE_NOOP("EmcyConsumer", "temperature")},
    {0x4100, QT_TRANSLATE_NOOP("EmcyConsumer", "ambient temperature")},
    {0x4200, QT_TRANSLATE_NOOP("EmcyConsumer", "device temperature")},
    {0x4310, QT_TRANSLATE_NOOP("EmcyConsumer", "drive excess temperature")},
    {0x5000, QT_TRANSLATE_NOOP("EmcyConsumer", "device hardware")},
    {0x6000, QT_TRANSLATE_NOOP("EmcyConsumer", "device software")},
    {0x6100, QT_TRANSLATE_NOOP("EmcyConsumer", "internal software")},
    {0x6200, QT_TRANSLATE_NOOP("EmcyConsumer", "user software")},
    {0x6300, QT_TRANSLATE_NOOP("EmcyConsumer", "data set")},
    {0x7000, QT_TRANSLATE_NOOP("EmcyConsumer", "additional modules")},
    {0x7300, QT_TRANSLATE_NOOP("EmcyConsumer", "sensor")},
    {0x7305, QT_TRANSLATE_NOOP("EmcyConsumer", "incremental sensor 1 fault")},
    {0x8000, QT_TRANSLATE_NOOP("EmcyConsumer", "monitoring")},
    {0x8100, QT_TRANSLATE_NOOP("EmcyConsumer", "communication")},
    {0x8110, QT_TRANSLATE_NOOP("EmcyConsumer", "CAN overrun (objects lost)")},
    {0x8120, QT_TRANSLATE_NOOP("EmcyConsumer", "CAN in error passive mode")},
    {0x8130, QT_TRANSLATE_NOOP("EmcyConsumer", "life guard or heartbeat error")},
    {0x8140, QT_TRANSLATE_NOOP("EmcyConsumer", "recovered from bus off")},
    {0x8150, QT_TRANSLATE_NOOP("EmcyConsumer", "CAN-ID collision")},
    {0x8200, QT_TRANSLATE_NOOP("EmcyConsumer", "protocol error")},
    {0x8210, QT_TRANSLATE_NOOP("EmcyConsumer", "PDO not processed due to length error")},
    {0x8220, QT_TRANSLATE_NOOP("EmcyConsumer", "PDO length exceeded")},
    {0x8240, QT_TRANSLATE_NOOP("EmcyConsumer", "unexpected SYNC data length")},
    {0x8250, QT_TRANSLATE_NOOP("EmcyConsumer", "RPDO timeout")},
    {0x8600, QT_TRANSLATE_NOOP("EmcyConsumer", "positioning controller")},
    {0x8611, QT_TRANSLATE_NOOP("EmcyConsumer", "following error")},
    {0x9000, QT_TRANSLATE_NOOP("EmcyConsumer", "external error")},
    {0xF000, QT_TRANSLATE_NOOP("EmcyConsumer", "additional functions")},
    {0xFF00, QT_TRANSLATE_NOOP("EmcyConsumer", "device specific")},
};

const char *const registerBits[8] = {
    QT_TRANSLATE_NOOP("EmcyConsumer", "generic"),
    QT_TRANSLATE_NOOP("EmcyConsumer", "current"),
    QT_TRANSLATE_NOOP("EmcyConsumer", "voltage"),
    QT_TRANSLATE_NOOP("EmcyConsumer", "temperature"),
    QT_TRANSLATE_NOOP("EmcyConsumer", "communication"),
    QT_TRANSLATE_NOOP("EmcyConsumer", "device profile"),
    QT_TRANSLATE_NOOP("EmcyConsumer", "reserved"),
    QT_TRANSLATE_NOOP("EmcyConsumer", "manufacturer"),
};

const char *lookup(quint16 code)
{
    for (const CodeText &c : codeTable) {
        if (c.code == code)
            return c.text;
    }
    return nullptr;
}

QString hex(quint32 value, int digits)
{
    return QStringLiteral("0x") +
           QStringLiteral("%1").arg(value, digits, 16, QLatin1Char('0')).toUpper();
}

} // namespace

QString emcyErrorCodeText(quint16 errorCode)
{
    // The exact code, else its sub-class (0xXX00), else its class (0xX000).
    for (const quint16 code :
         {errorCode, quint16(errorCode & 0xFF00), quint16(errorCode & 0xF000)}) {
        if (const char *text = lookup(code); text && (code != 0 || errorCode == 0))
            return Text::tr(text);
    }
    return Text::tr("unknown error code");
}

QString errorRegisterText(quint8 errorRegister)
{
    QStringList names;
    for (int bit = 0; bit < 8; ++bit) {
        if (errorRegister & (1u << bit))
            names.append(Text::tr(registerBits[bit]));
    }
    return names.isEmpty() ? Text::tr("no error") : names.join(QLatin1String(", "));
}

QString EmcyMessage::text() const
{
    return Text::tr("Node %1 emergency %2: %3; error register %4: %5; manufacturer data %6")
        .arg(node)
        .arg(hex(errorCode, 4), emcyErrorCodeText(errorCode), hex(errorRegister, 2),
             errorRegisterText(errorRegister), canopen::hexBytes(manufacturerData));
}

std::optional<EmcyMessage> decodeEmcy(const QCanBusFrame &frame)
{
    const quint32 id = frame.frameId();
    const QByteArray p = frame.payload();
    if (frame.frameType() != QCanBusFrame::DataFrame || frame.hasExtendedFrameFormat() ||
        id <= canopen::emcyCobId(0) || id > canopen::emcyCobId(127) || p.size() < 3)
        return std::nullopt;
    EmcyMessage m;
    m.node = canopen::nodeOfCobId(id);
    m.errorCode = canopen::readU16(p, 0);
    m.errorRegister = quint8(p.at(2));
    m.manufacturerData = p.mid(3, 5).leftJustified(5, '\0');
    return m;
}

QCanBusFrame encodeEmcy(const EmcyMessage &message)
{
    QByteArray p(8, '\0');
    canopen::writeU16(p, 0, message.errorCode);
    p[2] = char(message.errorRegister);
    const QByteArray m = message.manufacturerData.left(5);
    for (int i = 0; i < m.size(); ++i)
        p[3 + i] = m[i];
    return QCanBusFrame(canopen::emcyCobId(message.node), p);
}

EmcyConsumer::EmcyConsumer(CanLink *link, QObject *parent)
    : QObject(parent)
{
    Q_ASSERT(link);
    connect(link, &CanLink::frameReceived, this, [this](const QCanBusFrame &frame) {
        if (const std::optional<EmcyMessage> m = decodeEmcy(frame)) {
            qCWarning(lcCan) << m->text();
            emit emergency(*m);
        }
    });
}

} // namespace learnid
