// Fuzz target: the candump log reader (core/can CandumpLog). Any input is read as a log; bad input
// must end in a learnid::Error. The frames of an accepted log must write as a log that reads back
// to the same frames (compared by their written lines), and every line parseLine() accepts must
// have a timestamp and frame of ASCII characters only: the log format knows no other digits, and
// a digit the number conversions cannot read would silently become 0 (found this way, fixed).

#include "FuzzSupport.h"

#include "can/CandumpLog.h"
#include "model/Error.h"

#include <QBuffer>
#include <QStringList>

using namespace learnid;

namespace {

QByteArray written(const QList<CandumpEntry> &entries)
{
    QByteArray text;
    QBuffer buffer(&text);
    buffer.open(QIODevice::WriteOnly);
    candump::write(buffer, entries);
    return text;
}

void checkLinesOneByOne(const QByteArray &input)
{
    const QList<QByteArray> lines = input.split('\n');
    for (const QByteArray &line : lines) {
        CandumpEntry entry;
        QString reason;
        const QString text = QString::fromUtf8(line);
        if (!candump::parseLine(text, &entry, &reason))
            continue;
        const QStringList fields = text.simplified().split(QLatin1Char(' '));
        for (int i : {0, 2}) {
            for (const QChar c : fields.value(i)) {
                if (c.unicode() > 0x7F)
                    fuzz::fuzzFailure("a line with non-ASCII digits was accepted", text);
            }
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::quietMessages();
    QByteArray input = fuzz::bytes(data, size);
    checkLinesOneByOne(input);
    QBuffer device(&input);
    device.open(QIODevice::ReadOnly);
    QList<CandumpEntry> entries;
    try {
        entries = candump::read(device, QStringLiteral("fuzz.log"));
    } catch (const Error &) {
        return 0;
    }
    for (const CandumpEntry &e : entries) {
        if (e.frame.payload().size() > 8)
            fuzz::fuzzFailure("a classic CAN frame with more than 8 data bytes was accepted");
    }
    try {
        QByteArray log = written(entries);
        QBuffer again(&log);
        again.open(QIODevice::ReadOnly);
        const QList<CandumpEntry> reread = candump::read(again, QStringLiteral("written.log"));
        if (reread.size() != entries.size() || written(reread) != log)
            fuzz::fuzzFailure("a written candump log reads back different", QString::fromUtf8(log));
    } catch (const Error &e) {
        fuzz::fuzzFailure("a written candump log is refused", e.message());
    }
    return 0;
}
