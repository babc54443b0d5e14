#pragma once

// Test support: a KDL chain read from a URDF with urdfdom and converted the way ROS's
// kdl_parser converts it (a segment per URDF joint, fixed joints kept as KDL fixed joints),
// independently of learnid's own chain reader: Orocos KDL is the dynamics oracle.

#include <QByteArray>
#include <QFile>
#include <QString>
#include <kdl/chain.hpp>
#include <stdexcept>
#include <urdf_parser/urdf_parser.h>
#include <vector>

namespace learnid::test {

inline KDL::Frame kdlFrame(const urdf::Pose &pose)
{
    const urdf::Rotation &r = pose.rotation;
    return KDL::Frame(KDL::Rotation::Quaternion(r.x, r.y, r.z, r.w),
                      KDL::Vector(pose.position.x, pose.position.y, pose.position.z));
}

inline KDL::RigidBodyInertia kdlInertia(const urdf::Link &link)
{
    if (!link.inertial)
        return KDL::RigidBodyInertia::Zero();
    const urdf::Inertial &i = *link.inertial;
    const KDL::Frame origin = kdlFrame(i.origin);
    const KDL::RotationalInertia atComAxes(i.ixx, i.iyy, i.izz, i.ixy, i.ixz, i.iyz);
    // Rotate the inertia about the centre of mass into the link's axes.
    const KDL::RotationalInertia atCom =
        (origin.M * KDL::RigidBodyInertia(0.0, KDL::Vector::Zero(), atComAxes))
            .getRotationalInertia();
    return KDL::RigidBodyInertia(i.mass, origin.p, atCom);
}

inline KDL::Chain kdlChainFromUrdf(const QString &path, const std::string &base,
                                   const std::string &tip)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw std::runtime_error("cannot read " + path.toStdString());
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(file.readAll().toStdString());
    if (!model)
        throw std::runtime_error("urdfdom cannot parse " + path.toStdString());
    std::vector<urdf::LinkConstSharedPtr> links;
    for (urdf::LinkConstSharedPtr l = model->getLink(tip); l && l->name != base; l = l->getParent())
        links.insert(links.begin(), l);
    KDL::Chain chain;
    for (const urdf::LinkConstSharedPtr &link : links) {
        const urdf::Joint &j = *link->parent_joint;
        const KDL::Frame origin = kdlFrame(j.parent_to_joint_origin_transform);
        const KDL::Vector axis = origin.M * KDL::Vector(j.axis.x, j.axis.y, j.axis.z);
        KDL::Joint joint(j.name, KDL::Joint::Fixed);
        if (j.type == urdf::Joint::REVOLUTE || j.type == urdf::Joint::CONTINUOUS)
            joint = KDL::Joint(j.name, origin.p, axis, KDL::Joint::RotAxis);
        else if (j.type == urdf::Joint::PRISMATIC)
            joint = KDL::Joint(j.name, origin.p, axis, KDL::Joint::TransAxis);
        chain.addSegment(KDL::Segment(link->name, joint, origin, kdlInertia(*link)));
    }
    return chain;
}

} // namespace learnid::test
