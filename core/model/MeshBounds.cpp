#include "model/MeshBounds.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QUrl>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/scene.h>
#include <cmath>
#include <mutex>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(MeshBounds)
};

constexpr qint64 maxMeshBytes = qint64(256) << 20;

bool isRegularFile(const QString &path)
{
    const QFileInfo info(path);
    return info.exists() && info.isFile();
}

// PKG/REST under a package root: an entry named PKG itself, or holding PKG.
QString inPackageRoot(const QDir &root, const QString &package, const QString &rest)
{
    if (root.dirName() == package && isRegularFile(root.filePath(rest)))
        return root.filePath(rest);
    const QString below = root.filePath(package + QLatin1Char('/') + rest);
    return isRegularFile(below) ? below : QString();
}

void extend(const aiScene &scene, const aiNode &node, const aiMatrix4x4 &parent,
            Eigen::AlignedBox3d &box)
{
    const aiMatrix4x4 transform = parent * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        if (node.mMeshes[i] >= scene.mNumMeshes)
            continue;
        const aiMesh &mesh = *scene.mMeshes[node.mMeshes[i]];
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D p = transform * mesh.mVertices[v];
            const Eigen::Vector3d x(p.x, p.y, p.z);
            if (x.allFinite())
                box.extend(x);
        }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        extend(scene, *node.mChildren[c], transform, box);
}

std::optional<Eigen::AlignedBox3d> readBounds(const QString &path, QString *problem)
{
    Assimp::Importer importer;
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    const aiScene *scene = importer.ReadFile(QFile::encodeName(path).toStdString(), 0);
    if (!scene || !scene->mRootNode) {
        *problem = Text::tr("not readable as a mesh (%1)")
                       .arg(QString::fromUtf8(importer.GetErrorString()).trimmed());
        return std::nullopt;
    }
    Eigen::AlignedBox3d box;
    extend(*scene, *scene->mRootNode, aiMatrix4x4(), box);
    if (box.isEmpty()) {
        *problem = Text::tr("has no vertices");
        return std::nullopt;
    }
    return box;
}

} // namespace

QStringList rosPackagePath()
{
    return QString::fromLocal8Bit(qgetenv("ROS_PACKAGE_PATH"))
        .split(QLatin1Char(':'), Qt::SkipEmptyParts);
}

MeshLocation locateMesh(const QString &filename, const QString &urdfDirectory,
                        const QStringList &packagePath)
{
    static const QString packageScheme = QStringLiteral("package://");
    static const QString fileScheme = QStringLiteral("file://");
    if (filename.startsWith(packageScheme)) {
        const QString rest = filename.mid(packageScheme.size());
        const int slash = int(rest.indexOf(QLatin1Char('/')));
        if (slash <= 0)
            return {{}, Text::tr("names no package")};
        const QString package = rest.left(slash), inside = rest.mid(slash + 1);
        for (const QString &root : packagePath) {
            const QString found = inPackageRoot(QDir(root), package, inside);
            if (!found.isEmpty())
                return {found, {}};
        }
        if (!urdfDirectory.isEmpty()) {
            QDir dir(urdfDirectory);
            for (int up = 0; up < 4; ++up) {
                const QString found = inPackageRoot(dir, package, inside);
                if (!found.isEmpty())
                    return {found, {}};
                if (!dir.cdUp())
                    break;
            }
        }
        return {{},
                Text::tr("package \"%1\" not found (ROS_PACKAGE_PATH, the URDF's folder)")
                    .arg(package)};
    }
    QString path = filename;
    if (filename.startsWith(fileScheme))
        path = QUrl(filename).toLocalFile();
    else if (QDir::isRelativePath(filename)) {
        if (urdfDirectory.isEmpty())
            return {{}, Text::tr("a relative name without the URDF's folder")};
        path = QDir(urdfDirectory).filePath(filename);
    }
    if (!isRegularFile(path))
        return {{}, Text::tr("no such file")};
    return {QDir::cleanPath(path), {}};
}

std::optional<Eigen::AlignedBox3d> meshBounds(const QString &path, QString *problem)
{
    QString ignored;
    if (!problem)
        problem = &ignored;
    const QFileInfo info(path);
    if (!info.isFile()) {
        *problem = Text::tr("no such file");
        return std::nullopt;
    }
    if (info.size() == 0) { // also what /proc's files say of themselves
        *problem = Text::tr("empty");
        return std::nullopt;
    }
    if (info.size() > maxMeshBytes) {
        *problem = Text::tr("larger than 256 MB, not read");
        return std::nullopt;
    }
    struct Cached
    {
        std::optional<Eigen::AlignedBox3d> box;
        QString problem;
    };
    static std::mutex cacheMutex;
    static QHash<QString, Cached> cache;
    const QString key = info.absoluteFilePath() + QLatin1Char('\n') + QString::number(info.size()) +
                        QLatin1Char('\n') +
                        QString::number(info.lastModified().toMSecsSinceEpoch());
    {
        const std::lock_guard<std::mutex> lock(cacheMutex);
        if (const auto found = cache.constFind(key); found != cache.constEnd()) {
            *problem = found->problem;
            return found->box;
        }
    }
    Cached read;
    read.box = readBounds(path, &read.problem);
    const std::lock_guard<std::mutex> lock(cacheMutex);
    cache.insert(key, read);
    *problem = read.problem;
    return read.box;
}

} // namespace learnid
