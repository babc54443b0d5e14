#pragma once

#include <Eigen/Geometry>
#include <QString>
#include <QStringList>
#include <optional>

namespace learnid {

/// Where a URDF's mesh file is, or why it was not found.
struct MeshLocation
{
    QString path;    ///< an existing regular file; empty when not found
    QString problem; ///< why not (in words, for the geometry's description); empty when found
};

/// The file a URDF <mesh filename> names (docs/robots.md §6):
///  - "package://PKG/REST": PKG's folder is looked for under each entry of packagePath (the
///    ROS_PACKAGE_PATH convention: an entry is a package named PKG or holds one as a direct
///    subfolder), then from urdfDirectory and up to three of its parents (a URDF usually sits in
///    PKG/urdf/, its meshes in PKG/meshes/);
///  - "file:///ABS" and absolute paths as they are;
///  - any other name relative to urdfDirectory (not found when that is empty).
/// Only regular files are found (a device or a pipe is not a mesh).
MeshLocation locateMesh(const QString &filename, const QString &urdfDirectory,
                        const QStringList &packagePath);

/// ROS_PACKAGE_PATH split at ':' (empty entries dropped).
QStringList rosPackagePath();

/// The axis-aligned box around the vertices of a mesh file (STL, COLLADA, OBJ and whatever else
/// Debian's Open Asset Import Library reads), in the file's own frame and units: every node's
/// transform applied (COLLADA's <unit> included, its <up_axis> ignored: URDF tools take a mesh's
/// axes as written). nullopt with `problem` set when the file cannot be read or has no vertex.
/// Files over 256 MB are not read. Results are cached by path, size and modification time.
std::optional<Eigen::AlignedBox3d> meshBounds(const QString &path, QString *problem);

} // namespace learnid
