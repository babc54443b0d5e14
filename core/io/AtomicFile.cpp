#include "io/AtomicFile.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <memory>
#include <vector>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(AtomicFile)
};

[[noreturn]] void throwWriteError(const QString &path, const QString &reason)
{
    throw Error(Text::tr("cannot write %1: %2").arg(QDir::toNativeSeparators(path), reason));
}

// Opens, writes and flushes; the caller commits. The QSaveFile discards its temporary file when
// destroyed uncommitted.
std::unique_ptr<QSaveFile> writeUncommitted(const QString &path, const QByteArray &data)
{
    if (path.isEmpty())
        throwWriteError(path, Text::tr("no file name given"));
    auto file = std::make_unique<QSaveFile>(path);
    if (!file->open(QIODevice::WriteOnly))
        throwWriteError(path, file->errorString());
    if (file->write(data) != data.size() || !file->flush())
        throwWriteError(path, file->errorString());
    return file;
}

} // namespace

void writeFileAtomically(const QString &path, const QByteArray &data)
{
    const std::unique_ptr<QSaveFile> file = writeUncommitted(path, data);
    if (!file->commit())
        throwWriteError(path, file->errorString());
}

void writeFilesAtomically(const QList<QPair<QString, QByteArray>> &files)
{
    QStringList seen;
    for (const auto &f : files) {
        const QString absolute = QFileInfo(f.first).absoluteFilePath();
        if (seen.contains(absolute))
            throwWriteError(f.first, Text::tr("the same file is to be written twice"));
        seen.append(absolute);
    }
    std::vector<std::unique_ptr<QSaveFile>> pending;
    for (const auto &f : files)
        pending.push_back(writeUncommitted(f.first, f.second)); // throws: nothing committed
    for (size_t i = 0; i < pending.size(); ++i) {
        if (!pending[i]->commit()) {
            QStringList committed;
            for (size_t j = 0; j < i; ++j)
                committed.append(QDir::toNativeSeparators(files.at(qsizetype(j)).first));
            QString reason = pending[i]->errorString();
            if (!committed.isEmpty()) {
                reason = Text::tr("%1 (already written: %2)")
                             .arg(reason, committed.join(QStringLiteral(", ")));
            }
            throwWriteError(files.at(qsizetype(i)).first, reason);
        }
    }
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        const QString reason = file.errorString();
        throw Error(Text::tr("cannot read %1: %2").arg(QDir::toNativeSeparators(path), reason));
    }
    QByteArray data = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        const QString reason = file.errorString();
        throw Error(Text::tr("cannot read %1: %2").arg(QDir::toNativeSeparators(path), reason));
    }
    return data;
}

} // namespace learnid
