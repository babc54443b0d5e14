#pragma once

#include <QByteArray>
#include <QString>

namespace learnid::csv {

// Where a CSV reader's error is, worded alike by every reader (path, robot log, plan,
// controller log, trial CSV). Used by the io library only.

/// "<source>: line L, column C (name)"; without the name when it is empty.
QString fieldPlace(const QString &source, int line, int column, const QByteArray &name);
/// Throws Error("<fieldPlace>: what").
[[noreturn]] void throwAtField(const QString &source, int line, int column, const QByteArray &name,
                               const QString &what);
/// Throws Error("<source>: line L: what").
[[noreturn]] void throwAtLine(const QString &source, int line, const QString &what);
/// The field in double quotes for a message, spaces around it dropped, at most 40 bytes.
QString quoted(const QByteArray &field);

} // namespace learnid::csv
