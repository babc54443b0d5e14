#include "model/UrdfGeometry.h"

#include "model/Error.h"
#include "model/MeshBounds.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <urdf_model/link.h>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(UrdfGeometry)
};

Eigen::Isometry3d toIsometry(const urdf::Pose &pose)
{
    const urdf::Rotation &r = pose.rotation;
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
    t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
    return t;
}

Eigen::Vector3d vector(const urdf::Vector3 &v)
{
    return {v.x, v.y, v.z};
}

bool validSize(double v)
{
    return std::isfinite(v) && v >= 0.0;
}

} // namespace

Eigen::AlignedBox3d placedBox(const Eigen::AlignedBox3d &own, const Eigen::Isometry3d &pose)
{
    Eigen::AlignedBox3d out;
    for (int corner = 0; corner < 8; ++corner)
        out.extend(pose * own.corner(Eigen::AlignedBox3d::CornerType(corner)));
    return out;
}

Eigen::AlignedBox3d placedCylinder(double radius, double length, const Eigen::Isometry3d &pose)
{
    const Eigen::Vector3d d = pose.linear().col(2);
    const Eigen::Vector3d reach =
        d.cwiseAbs() * (0.5 * length) +
        radius * (Eigen::Vector3d::Ones() - d.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
    return {pose.translation() - reach, pose.translation() + reach};
}

Eigen::AlignedBox3d placedSphere(double radius, const Eigen::Isometry3d &pose)
{
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(radius);
    return {pose.translation() - r, pose.translation() + r};
}

BodyGeometry::BodyGeometry(const QString &urdfDirectory, const QStringList &packagePath,
                           const QString &source)
    : m_directory(urdfDirectory)
    , m_packagePath(packagePath)
    , m_source(source)
{}

template <typename Shapes>
int BodyGeometry::addShapes(const Shapes &shapes, const QString &link,
                            const Eigen::Isometry3d &pose, const char *kind)
{
    int used = 0;
    int index = 0;
    for (const auto &shape : shapes) {
        ++index;
        if (!shape || !shape->geometry)
            continue;
        const urdf::Geometry &g = *shape->geometry;
        const Eigen::Isometry3d placed = pose * toIsometry(shape->origin);
        const auto refuse = [&](const QString &what) {
            throw Error(
                Text::tr("%1: link \"%2\", <%3> %4: %5")
                    .arg(m_source, link, QLatin1String(kind), QString::number(index), what));
        };
        switch (g.type) {
        case urdf::Geometry::BOX: {
            const Eigen::Vector3d size = vector(static_cast<const urdf::Box &>(g).dim);
            if (!validSize(size.minCoeff()) || !size.allFinite())
                refuse(Text::tr("the box's size is negative or not a number"));
            m_box.extend(placedBox({-0.5 * size, 0.5 * size}, placed));
            ++m_boxes;
            break;
        }
        case urdf::Geometry::CYLINDER: {
            const auto &c = static_cast<const urdf::Cylinder &>(g);
            if (!validSize(c.radius) || !validSize(c.length))
                refuse(Text::tr("the cylinder's radius or length is negative or not a number"));
            m_box.extend(placedCylinder(c.radius, c.length, placed));
            ++m_cylinders;
            break;
        }
        case urdf::Geometry::SPHERE: {
            const double r = static_cast<const urdf::Sphere &>(g).radius;
            if (!validSize(r))
                refuse(Text::tr("the sphere's radius is negative or not a number"));
            m_box.extend(placedSphere(r, placed));
            ++m_spheres;
            break;
        }
        case urdf::Geometry::MESH: {
            const auto &mesh = static_cast<const urdf::Mesh &>(g);
            const Eigen::Vector3d scale = vector(mesh.scale);
            if (!scale.allFinite())
                refuse(Text::tr("the mesh's scale is not a number"));
            const QString name = QString::fromStdString(mesh.filename);
            const MeshLocation where = locateMesh(name, m_directory, m_packagePath);
            QString problem = where.problem;
            std::optional<Eigen::AlignedBox3d> own;
            if (!where.path.isEmpty())
                own = meshBounds(where.path, &problem);
            if (!own) {
                m_skipped
                    << Text::tr("mesh \"%1\" of link \"%2\" skipped: %3").arg(name, link, problem);
                continue;
            }
            // A negative scale mirrors the mesh: its box's corners swap.
            const Eigen::Vector3d a = own->min().cwiseProduct(scale);
            const Eigen::Vector3d b = own->max().cwiseProduct(scale);
            m_box.extend(placedBox({a.cwiseMin(b), a.cwiseMax(b)}, placed));
            ++m_meshes;
            break;
        }
        }
        ++used;
    }
    return used;
}

void BodyGeometry::addLink(const urdf::Link &link, const Eigen::Isometry3d &pose)
{
    const QString name = QString::fromStdString(link.name);
    std::vector<urdf::CollisionSharedPtr> collisions = link.collision_array;
    if (collisions.empty() && link.collision)
        collisions.push_back(link.collision);
    if (addShapes(collisions, name, pose, "collision") > 0)
        return;
    std::vector<urdf::VisualSharedPtr> visuals = link.visual_array;
    if (visuals.empty() && link.visual)
        visuals.push_back(link.visual);
    if (addShapes(visuals, name, pose, "visual") > 0)
        m_visualLinks << name;
}

QString BodyGeometry::description() const
{
    QStringList parts;
    // Singular and plural spelled out: English needs no translation file to read well.
    if (m_boxes > 0)
        parts << (m_boxes == 1 ? Text::tr("1 box") : Text::tr("%1 boxes").arg(m_boxes));
    if (m_cylinders > 0)
        parts << (m_cylinders == 1 ? Text::tr("1 cylinder")
                                   : Text::tr("%1 cylinders").arg(m_cylinders));
    if (m_spheres > 0)
        parts << (m_spheres == 1 ? Text::tr("1 sphere") : Text::tr("%1 spheres").arg(m_spheres));
    if (m_meshes > 0)
        parts << (m_meshes == 1 ? Text::tr("1 mesh") : Text::tr("%1 meshes").arg(m_meshes));
    QStringList out;
    if (!parts.isEmpty())
        out << parts.join(QLatin1String(", "));
    if (!m_visualLinks.isEmpty())
        out << Text::tr("visual shapes of %1 (no collision shape)")
                   .arg(m_visualLinks.join(QLatin1String(", ")));
    out += m_skipped;
    return out.join(QLatin1String("; "));
}

} // namespace learnid
