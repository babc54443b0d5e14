#include "can/CandumpLog.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QFile>
#include <QStringList>
#include <QTextStream>

namespace learnid::candump {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CandumpLog)
};

constexpr quint32 errorFlag = 0x20000000u; // CAN_ERR_FLAG of linux/can.h
constexpr quint32 extendedMask = 0x1FFFFFFFu;

// ASCII only: QChar::isDigit() also accepts other scripts' digits (U+0663), which the number
// conversions then read as 0 or skip, so a malformed line would become a wrong frame.
bool isAsciiDigit(QChar c)
{
    return c >= QLatin1Char('0') && c <= QLatin1Char('9');
}

bool isHex(const QString &s)
{
    for (const QChar c : s) {
        if (!isAsciiDigit(c) && !(c >= QLatin1Char('a') && c <= QLatin1Char('f')) &&
            !(c >= QLatin1Char('A') && c <= QLatin1Char('F')))
            return false;
    }
    return !s.isEmpty();
}

bool allDigits(const QString &s)
{
    for (const QChar c : s) {
        if (!isAsciiDigit(c))
            return false;
    }
    return !s.isEmpty();
}

bool parseTimestamp(const QString &field, QCanBusFrame::TimeStamp *stamp, QString *reason)
{
    if (field.size() < 3 || !field.startsWith(QLatin1Char('(')) ||
        !field.endsWith(QLatin1Char(')'))) {
        *reason = Text::tr(
            "the line must start with a timestamp in parentheses, e.g. (1700000000.123456)");
        return false;
    }
    const QStringList parts = field.mid(1, field.size() - 2).split(QLatin1Char('.'));
    const QString fraction = parts.value(1);
    bool okSeconds = false;
    const qint64 seconds = parts.value(0).toLongLong(&okSeconds);
    if (parts.size() != 2 || !allDigits(parts[0]) || !okSeconds || !allDigits(fraction) ||
        fraction.size() > 9) {
        *reason =
            Text::tr("\"%1\" is not a timestamp of the form (seconds.microseconds)").arg(field);
        return false;
    }
    const qint64 micro = fraction.left(6).leftJustified(6, QLatin1Char('0')).toLongLong();
    *stamp = QCanBusFrame::TimeStamp(seconds, micro);
    return true;
}

bool parseFrame(const QString &text, QCanBusFrame *frame, QString *reason)
{
    const qsizetype hash = text.indexOf(QLatin1Char('#'));
    if (hash < 0) {
        *reason = Text::tr("\"%1\" has no '#' between identifier and data").arg(text);
        return false;
    }
    const QString idText = text.left(hash);
    QString data = text.mid(hash + 1);
    if (data.startsWith(QLatin1Char('#'))) {
        *reason = Text::tr("CAN FD frames are not supported");
        return false;
    }
    if ((idText.size() != 3 && idText.size() != 8) || !isHex(idText)) {
        *reason = Text::tr("\"%1\" is not an identifier of 3 (standard) or 8 (extended) hex digits")
                      .arg(idText);
        return false;
    }
    quint32 id = idText.toUInt(nullptr, 16);
    const bool extended = idText.size() == 8;
    const bool error = extended && (id & errorFlag);
    if (!extended && id > 0x7FF) {
        *reason = Text::tr("the standard identifier %1 exceeds 7FF").arg(idText);
        return false;
    }
    if (extended && !error && id > extendedMask) {
        *reason = Text::tr("the extended identifier %1 exceeds 1FFFFFFF").arg(idText);
        return false;
    }
    QCanBusFrame f;
    if (data.startsWith(QLatin1Char('R')) || data.startsWith(QLatin1Char('r'))) {
        const QString length = data.mid(1);
        if (length.size() > 1 || (length.size() == 1 &&
                                  (length[0] < QLatin1Char('0') || length[0] > QLatin1Char('8')))) {
            *reason =
                Text::tr("\"%1\" is not a remote request (R, optionally with a length 0 to 8)")
                    .arg(data);
            return false;
        }
        f.setFrameType(QCanBusFrame::RemoteRequestFrame);
        f.setPayload(QByteArray(length.isEmpty() ? 0 : length.toInt(), '\0'));
    } else {
        data.remove(QLatin1Char('.')); // can-utils accepts dots between data bytes
        if (data.size() % 2 != 0 || (!data.isEmpty() && !isHex(data))) {
            *reason =
                Text::tr("\"%1\" is not data of whole bytes in hex digits").arg(text.mid(hash + 1));
            return false;
        }
        if (data.size() > 16) {
            *reason = Text::tr("%1 data bytes; a classic CAN frame carries at most 8")
                          .arg(data.size() / 2);
            return false;
        }
        f.setFrameType(error ? QCanBusFrame::ErrorFrame : QCanBusFrame::DataFrame);
        f.setPayload(QByteArray::fromHex(data.toLatin1()));
    }
    if (error) {
        f.setError(QCanBusFrame::FrameErrors(QFlag(int(id & extendedMask))));
    } else {
        f.setExtendedFrameFormat(extended);
        f.setFrameId(id);
    }
    *frame = f;
    return true;
}

} // namespace

QString formatLine(const QCanBusFrame &frame, const QString &interface)
{
    const QCanBusFrame::TimeStamp t = frame.timeStamp();
    QString id;
    if (frame.frameType() == QCanBusFrame::ErrorFrame)
        id = QStringLiteral("%1").arg(errorFlag | quint32(frame.error().toInt()), 8, 16,
                                      QLatin1Char('0'));
    else if (frame.hasExtendedFrameFormat())
        id = QStringLiteral("%1").arg(frame.frameId(), 8, 16, QLatin1Char('0'));
    else
        id = QStringLiteral("%1").arg(frame.frameId(), 3, 16, QLatin1Char('0'));
    QString data;
    if (frame.frameType() == QCanBusFrame::RemoteRequestFrame) {
        data = QStringLiteral("R");
        if (!frame.payload().isEmpty())
            data += QString::number(frame.payload().size());
    } else {
        data = QString::fromLatin1(frame.payload().toHex());
    }
    return QStringLiteral("(%1.%2) %3 %4#%5")
        .arg(t.seconds(), 10, 10, QLatin1Char('0'))
        .arg(t.microSeconds(), 6, 10, QLatin1Char('0'))
        .arg(interface, id.toUpper(), data.toUpper());
}

bool parseLine(const QString &line, CandumpEntry *entry, QString *reason)
{
    const QStringList fields = line.simplified().split(QLatin1Char(' '), Qt::SkipEmptyParts);
    // Newer can-utils may append the direction of the frame (R received, T transmitted).
    const bool direction =
        fields.size() == 4 && (fields[3] == QLatin1String("R") || fields[3] == QLatin1String("T"));
    if (fields.size() != 3 && !direction) {
        *reason =
            fields.size() < 3
                ? Text::tr("expected \"(timestamp) interface id#data\", found %1 fields")
                      .arg(fields.size())
                : Text::tr("unexpected text after the frame: \"%1\"").arg(fields.mid(3).join(' '));
        return false;
    }
    QCanBusFrame::TimeStamp stamp;
    QCanBusFrame frame;
    if (!parseTimestamp(fields[0], &stamp, reason) || !parseFrame(fields[2], &frame, reason))
        return false;
    frame.setTimeStamp(stamp);
    entry->interface = fields[1];
    entry->frame = frame;
    return true;
}

QList<CandumpEntry> read(QIODevice &device, const QString &fileName)
{
    QList<CandumpEntry> entries;
    QTextStream in(&device);
    int lineNumber = 0;
    while (!in.atEnd()) {
        const QString line = in.readLine();
        ++lineNumber;
        if (line.trimmed().isEmpty())
            continue;
        CandumpEntry entry;
        QString reason;
        if (!parseLine(line, &entry, &reason))
            throw Error(QStringLiteral("%1:%2: %3").arg(fileName).arg(lineNumber).arg(reason));
        entries.append(entry);
    }
    return entries;
}

QList<CandumpEntry> readFile(const QString &fileName)
{
    QFile file(fileName);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        throw Error(
            Text::tr("Cannot open the candump log %1: %2").arg(fileName, file.errorString()));
    return read(file, fileName);
}

void write(QIODevice &device, const QList<CandumpEntry> &entries)
{
    QTextStream out(&device);
    for (const CandumpEntry &e : entries)
        out << formatLine(e.frame, e.interface) << '\n';
    out.flush();
    if (out.status() != QTextStream::Ok)
        throw Error(Text::tr("Writing the candump log failed: %1").arg(device.errorString()));
}

void writeFile(const QString &fileName, const QList<CandumpEntry> &entries)
{
    QFile file(fileName);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text | QIODevice::Truncate))
        throw Error(
            Text::tr("Cannot write the candump log %1: %2").arg(fileName, file.errorString()));
    write(file, entries);
}

} // namespace learnid::candump
