#include "io/Workspace.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStringList>

#ifdef Q_OS_UNIX
#include <climits>
#include <unistd.h>
#endif

namespace learnid {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Workspace", text);
}

QString parentOf(const QString &absolute)
{
    const qsizetype slash = absolute.lastIndexOf(QLatin1Char('/'));
    return slash <= 0 ? QStringLiteral("/") : absolute.left(slash);
}

QString child(const QString &dir, const QString &name)
{
    return dir == QLatin1String("/") ? dir + name : dir + QLatin1Char('/') + name;
}

// The target of a symbolic link as stored, relative or absolute. QFileInfo::symLinkTarget()
// cleans "a/../b" lexically, which is wrong when "a" is itself a link.
QString rawLinkTarget(const QString &link, const QFileInfo &info)
{
#ifdef Q_OS_UNIX
    char buffer[PATH_MAX];
    const ssize_t size = ::readlink(QFile::encodeName(link).constData(), buffer, sizeof buffer);
    if (size >= 0)
        return QFile::decodeName(QByteArray(buffer, int(size)));
#else
    Q_UNUSED(link);
#endif
    return info.symLinkTarget();
}

// The absolute path with every existing symbolic link replaced by its target, component by
// component, so that "link/.." leaves the link's target and not the link. what and given name
// the user's option in errors.
QString resolvePath(const QString &absolute, const QString &what, const QString &given)
{
    QStringList todo =
        QDir::fromNativeSeparators(absolute).split(QLatin1Char('/'), Qt::SkipEmptyParts);
    QString current = QStringLiteral("/");
    int links = 0;
    while (!todo.isEmpty()) {
        const QString name = todo.takeFirst();
        if (name == QLatin1String("."))
            continue;
        if (name == QLatin1String("..")) {
            current = parentOf(current);
            continue;
        }
        const QString next = child(current, name);
        const QFileInfo info(next);
        if (!info.isSymLink()) {
            current = next;
            continue;
        }
        if (++links > 40) {
            throw Error(tr("%1: %2: too many levels of symbolic links")
                            .arg(what, QDir::toNativeSeparators(given)));
        }
        // The target may itself contain links and "..": walk it, from the link's folder when
        // it is relative.
        const QString target = QDir::fromNativeSeparators(rawLinkTarget(next, info));
        todo = target.split(QLatin1Char('/'), Qt::SkipEmptyParts) + todo;
        if (QDir::isAbsolutePath(target))
            current = QStringLiteral("/");
    }
    return current;
}

} // namespace

QString resolveInWorkspace(const QString &workspaceDir, const QString &path, const QString &what)
{
    if (path.isEmpty())
        throw Error(tr("%1: no path given").arg(what));
    const QFileInfo workspaceInfo(workspaceDir);
    const QString workspace = workspaceInfo.canonicalFilePath();
    if (workspace.isEmpty() || !workspaceInfo.isDir()) {
        throw Error(tr("%1: the workspace %2 does not exist or is not a folder")
                        .arg(what, QDir::toNativeSeparators(workspaceDir)));
    }
    const QString absolute =
        QDir::isAbsolutePath(path) ? path : child(workspace, QDir::fromNativeSeparators(path));
    const QString resolved = resolvePath(absolute, what, path);
    const bool inside = workspace == QLatin1String("/") || resolved == workspace ||
                        resolved.startsWith(workspace + QLatin1Char('/'));
    if (!inside) {
        throw Error(tr("%1: %2 is outside the workspace %3 (resolved to %4)")
                        .arg(what, QDir::toNativeSeparators(path),
                             QDir::toNativeSeparators(workspace),
                             QDir::toNativeSeparators(resolved)));
    }
    return resolved;
}

} // namespace learnid
