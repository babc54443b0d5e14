#pragma once

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>

namespace learnid {

/// Writes data to path through QSaveFile: the data go to a temporary file in the same folder,
/// which replaces path only when everything was written. A failure never leaves a half-written
/// file and keeps an existing file as it was. Throws Error naming the path and the OS reason.
void writeFileAtomically(const QString &path, const QByteArray &data);

/// Writes several files all-or-nothing as far as the file system allows: every file is written
/// and flushed to its temporary file first; if any of that fails, nothing is committed and the
/// existing files stay as they were. Then the files are committed (renamed) in order; only a
/// failing rename, after everything was written, can leave the earlier files committed (the
/// error says which). The same path twice is an error. Throws Error naming the path and reason.
void writeFilesAtomically(const QList<QPair<QString, QByteArray>> &files);

/// The whole content of a file. Throws Error naming the path and the OS reason.
QByteArray readFile(const QString &path);

} // namespace learnid
