#pragma once

#include <Eigen/Geometry>
#include <QString>
#include <QStringList>

namespace urdf {
class Link;
}

namespace learnid {

/// The axis-aligned box, in a body's frame, around the box `own` (given in a shape's frame) once
/// `pose` places the shape (x_body = pose * x_shape): the box around its eight corners.
Eigen::AlignedBox3d placedBox(const Eigen::AlignedBox3d &own, const Eigen::Isometry3d &pose);
/// The same, exact, for a solid cylinder of radius r and length l along the shape's z axis,
/// centred: along body axis i it reaches |d_i| l / 2 + r sqrt(1 - d_i^2) from its centre,
/// d the cylinder's axis in the body frame.
Eigen::AlignedBox3d placedCylinder(double radius, double length, const Eigen::Isometry3d &pose);
/// The same for a sphere of radius r centred at the shape's origin.
Eigen::AlignedBox3d placedSphere(double radius, const Eigen::Isometry3d &pose);

/// The geometry of one moving body of a chain as its links are merged into it (UrdfChain.cpp):
/// the axis-aligned box in the body's (joint's) frame around each merged link's collision
/// shapes, or around its visual shapes when none of its collision shapes could be used. Boxes,
/// cylinders and spheres are taken with their <origin>; a mesh by its file's bounding box
/// (MeshBounds.h) scaled by its scale and placed like a box; a mesh that cannot be found or read
/// is skipped and named in description().
class BodyGeometry
{
public:
    /// urdfDirectory: where the URDF is (relative mesh names; empty: none); packagePath: the
    /// folders package:// names are looked for in; source names the URDF in messages.
    BodyGeometry(const QString &urdfDirectory, const QStringList &packagePath,
                 const QString &source);

    /// Adds link's shapes, the link's frame placed in the body's by `pose` (x_body = pose *
    /// x_link). Throws Error naming the source, the link and the shape when a box, cylinder or
    /// sphere has a negative or non-finite size or a mesh a non-finite scale.
    void addLink(const urdf::Link &link, const Eigen::Isometry3d &pose);

    /// Empty when no shape could be used.
    const Eigen::AlignedBox3d &box() const { return m_box; }
    /// What the box was made of, e.g. "2 cylinders, 1 sphere"; which links gave visual shapes;
    /// each skipped mesh and why. Empty when nothing was found.
    QString description() const;

private:
    template <typename Shapes>
    int addShapes(const Shapes &shapes, const QString &link, const Eigen::Isometry3d &pose,
                  const char *kind);

    QString m_directory;
    QStringList m_packagePath;
    QString m_source;
    Eigen::AlignedBox3d m_box;
    int m_boxes = 0;
    int m_cylinders = 0;
    int m_spheres = 0;
    int m_meshes = 0;
    QStringList m_visualLinks;
    QStringList m_skipped;
};

} // namespace learnid
