#pragma once

#include <QCanBusFrame>
#include <QList>
#include <QString>

class QIODevice;

namespace learnid {

/// One line of a candump log: the frame (with its timestamp) and the interface it was on.
struct CandumpEntry
{
    QString interface;
    QCanBusFrame frame;
};

/// The can-utils "candump -l" log format (classic CAN), one frame per line:
///   (1700000000.123456) can0 123#DEADBEEF
/// 3 hex digits for standard ids, 8 for extended ones, "R" for a remote request (optionally
/// followed by its length digit), nothing after '#' for an empty frame; error frames as
/// 8 hex digits with the CAN_ERR_FLAG 0x20000000 set. CAN FD lines ("##") are not supported.
namespace candump {

/// The log line of a frame (no line break), timestamp from frame.timeStamp().
QString formatLine(const QCanBusFrame &frame, const QString &interface);

/// Parses one line; on failure returns false and sets reason (translated).
bool parseLine(const QString &line, CandumpEntry *entry, QString *reason);

/// Reads a whole log; empty lines are skipped. Throws learnid::Error "fileName:line: reason"
/// at the first malformed line.
QList<CandumpEntry> read(QIODevice &device, const QString &fileName);
/// Reads a log file; throws learnid::Error when it cannot be opened or is malformed.
QList<CandumpEntry> readFile(const QString &fileName);

/// Writes one line per frame; throws learnid::Error when the device fails.
void write(QIODevice &device, const QList<CandumpEntry> &entries);
void writeFile(const QString &fileName, const QList<CandumpEntry> &entries);

} // namespace candump

} // namespace learnid
