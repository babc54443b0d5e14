#include "io/OutputPath.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(OutputPath)
};

} // namespace

QString resolveOutputPath(const QString &baseDir, const QString &path, const QString &what)
{
    if (path.isEmpty())
        throw Error(Text::tr("%1: no path given").arg(what));
    const QString given = QDir::fromNativeSeparators(path);
    // "." and "//" go; ".." stays for the OS to walk: lexically "link/.." is not link's parent.
    const auto tidy = [](const QString &p) {
        return p.split(QLatin1Char('/')).contains(QLatin1String("..")) ? p : QDir::cleanPath(p);
    };
    if (QDir::isAbsolutePath(given))
        return tidy(given);
    const QFileInfo base(baseDir);
    if (!base.isDir()) {
        throw Error(
            Text::tr("%1: %2 is relative, and the folder it is taken from, %3, does not exist "
                     "or is not a folder")
                .arg(what, QDir::toNativeSeparators(path), QDir::toNativeSeparators(baseDir)));
    }
    return tidy(base.absoluteFilePath() + QLatin1Char('/') + given);
}

} // namespace learnid
