#include "model/UrdfChain.h"

#include "model/Error.h"
#include "model/MeshBounds.h"
#include "model/UrdfExtension.h"
#include "model/UrdfGeometry.h"
#include "model/UrdfJointTree.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <algorithm>
#include <console_bridge/console.h>
#include <mutex>
#include <urdf_parser/urdf_parser.h>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(UrdfChain)
};

QString qs(const std::string &s)
{
    return QString::fromStdString(s);
}

// urdfdom reports what is wrong through console_bridge, not through its return value; this
// collects those messages while it parses so the error can say what the parser said.
class ParserMessages : public console_bridge::OutputHandler
{
public:
    void log(const std::string &text, console_bridge::LogLevel level, const char *, int) override
    {
        if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR)
            messages << qs(text).trimmed();
    }
    QStringList messages;
};

urdf::ModelInterfaceSharedPtr parse(const QByteArray &xml, const QString &source)
{
    checkUrdfJointTree(xml, source);
    static std::mutex handlerMutex; // console_bridge's handler is process-wide
    const std::lock_guard<std::mutex> lock(handlerMutex);
    ParserMessages messages;
    console_bridge::useOutputHandler(&messages);
    urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml.toStdString());
    console_bridge::restorePreviousOutputHandler();
    if (!model) {
        throw Error(Text::tr("%1: not a valid URDF: %2")
                        .arg(source, messages.messages.isEmpty()
                                         ? Text::tr("the parser gave no reason")
                                         : messages.messages.join(QLatin1String("; "))));
    }
    return model;
}

Eigen::Isometry3d toIsometry(const urdf::Pose &pose)
{
    const urdf::Rotation &r = pose.rotation;
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
    t.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
    return t;
}

InertialParameters linkInertial(const urdf::Link &link, const QString &source)
{
    if (!link.inertial)
        return InertialParameters::Zero();
    const urdf::Inertial &in = *link.inertial;
    if (!(in.mass >= 0.0)) {
        throw Error(Text::tr("%1: link \"%2\" has a negative mass (%3 kg)")
                        .arg(source, qs(link.name))
                        .arg(in.mass));
    }
    Eigen::Matrix3d atCom;
    atCom << in.ixx, in.ixy, in.ixz, //
        in.ixy, in.iyy, in.iyz,      //
        in.ixz, in.iyz, in.izz;
    const Eigen::Isometry3d com = toIsometry(in.origin);
    return inertialParameters(in.mass, com.translation(),
                              com.linear() * atCom * com.linear().transpose());
}

// Merges `link`, fixed to the body that `joint` moves at `pose` (its frame in the body's), into
// that body: its inertia, its geometry, and its name in the body's fixedLinks.
void mergeFixedLink(const urdf::Link &link, const Eigen::Isometry3d &pose, const QString &source,
                    ChainJoint &joint, BodyGeometry &geometry)
{
    joint.inertial += transformedInertial(linkInertial(link, source), pose.inverse());
    joint.fixedLinks.push_back({qs(link.name), pose});
    geometry.addLink(link, pose);
}

// Adds the inertia and geometry of every link fixed (directly or through other fixed joints) to
// `link`, except the chain's next link, to the body that `joint` moves, and lists them in its
// fixedLinks; `pose` places link's frame in the body's frame.
void mergeFixedChildren(const urdf::Link &link, const Eigen::Isometry3d &pose,
                        const urdf::Link *nextOnChain, const QString &source, ChainJoint &joint,
                        BodyGeometry &geometry)
{
    for (const urdf::LinkSharedPtr &child : link.child_links) {
        if (child.get() == nextOnChain || !child->parent_joint ||
            child->parent_joint->type != urdf::Joint::FIXED) {
            continue;
        }
        const Eigen::Isometry3d childPose =
            pose * toIsometry(child->parent_joint->parent_to_joint_origin_transform);
        mergeFixedLink(*child, childPose, source, joint, geometry);
        mergeFixedChildren(*child, childPose, nullptr, source, joint, geometry);
    }
}

QString pickTip(const urdf::ModelInterface &model, const urdf::LinkConstSharedPtr &base,
                const QString &source)
{
    urdf::LinkConstSharedPtr link = base;
    while (!link->child_links.empty()) {
        if (link->child_links.size() > 1) {
            QStringList children;
            for (const urdf::LinkSharedPtr &child : link->child_links)
                children << qs(child->name);
            throw Error(Text::tr("%1: the robot branches at link \"%2\" (children %3): name the "
                                 "tip link of the chain")
                            .arg(source, qs(link->name), children.join(QLatin1String(", "))));
        }
        link = model.getLink(link->child_links.front()->name);
    }
    return qs(link->name);
}

ChainJoint movingJoint(const urdf::Joint &joint, const urdf::Link &child,
                       const Eigen::Isometry3d &origin, const QString &source)
{
    ChainJoint j;
    j.name = qs(joint.name);
    j.link = qs(child.name);
    j.type = joint.type == urdf::Joint::PRISMATIC ? JointType::Prismatic : JointType::Revolute;
    j.origin = origin;
    const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (!(axis.norm() > 1e-9)) {
        throw Error(
            Text::tr("%1: joint \"%2\" has no axis (zero vector)").arg(source, qs(joint.name)));
    }
    j.axis = axis.normalized();
    // urdfdom reads a <limit> without lower and upper as 0 and 0: no position limits then.
    if (joint.limits && joint.type != urdf::Joint::CONTINUOUS &&
        joint.limits->lower < joint.limits->upper) {
        j.lower = joint.limits->lower;
        j.upper = joint.limits->upper;
    }
    if (joint.limits && joint.limits->velocity > 0.0)
        j.velocityLimit = joint.limits->velocity;
    if (joint.limits && joint.limits->effort > 0.0)
        j.effortLimit = joint.limits->effort;
    if (joint.dynamics) {
        j.damping = joint.dynamics->damping;
        j.friction = joint.dynamics->friction;
    }
    j.inertial = linkInertial(child, source);
    return j;
}

} // namespace

SerialChain parseUrdfChain(const QByteArray &xml, const QString &source, const QString &baseLink,
                           const QString &tipLink, const QString &urdfDirectory)
{
    const urdf::ModelInterfaceSharedPtr model = parse(xml, source);
    const QHash<QString, JointExtension> extensions = readJointExtensions(xml, source);
    const QStringList packagePath = rosPackagePath();
    const urdf::LinkConstSharedPtr base =
        baseLink.isEmpty() ? model->getRoot() : model->getLink(baseLink.toStdString());
    if (!base)
        throw Error(Text::tr("%1: no link \"%2\"").arg(source, baseLink));
    const QString tipName = tipLink.isEmpty() ? pickTip(*model, base, source) : tipLink;
    urdf::LinkConstSharedPtr tip = model->getLink(tipName.toStdString());
    if (!tip)
        throw Error(Text::tr("%1: no link \"%2\"").arg(source, tipName));

    // The links from the tip up to the base, then walked down from the base.
    std::vector<urdf::LinkConstSharedPtr> path;
    for (urdf::LinkConstSharedPtr link = tip; link != base; link = link->getParent()) {
        if (!link->getParent()) {
            throw Error(Text::tr("%1: link \"%2\" is not below link \"%3\"")
                            .arg(source, tipName, qs(base->name)));
        }
        path.push_back(link);
    }
    std::reverse(path.begin(), path.end());

    SerialChain chain;
    chain.name = qs(model->getName());
    chain.baseLink = qs(base->name);
    chain.tipLink = tipName;
    Eigen::Isometry3d pending = Eigen::Isometry3d::Identity(); // link frame in the body's frame
    std::vector<BodyGeometry> geometry;                        // per moving joint
    for (size_t i = 0; i < path.size(); ++i) {
        const urdf::Link &link = *path[i];
        const urdf::Joint &joint = *link.parent_joint;
        const Eigen::Isometry3d origin =
            pending * toIsometry(joint.parent_to_joint_origin_transform);
        if (joint.mimic) {
            throw Error(Text::tr("%1: joint \"%2\" mimics another joint: mimic joints are not "
                                 "supported")
                            .arg(source, qs(joint.name)));
        }
        switch (joint.type) {
        case urdf::Joint::FIXED:
            pending = origin;
            if (!chain.joints.empty()) // links fixed to the base do not move
                mergeFixedLink(link, pending, source, chain.joints.back(), geometry.back());
            break;
        case urdf::Joint::REVOLUTE:
        case urdf::Joint::CONTINUOUS:
        case urdf::Joint::PRISMATIC:
            chain.joints.push_back(movingJoint(joint, link, origin, source));
            pending = Eigen::Isometry3d::Identity();
            geometry.emplace_back(urdfDirectory, packagePath, source);
            geometry.back().addLink(link, pending);
            if (const auto e = extensions.constFind(chain.joints.back().name);
                e != extensions.constEnd()) {
                chain.joints.back().armature = e->armature;
                chain.joints.back().offset = e->offset;
            }
            break;
        default:
            throw Error(Text::tr("%1: joint \"%2\" is floating or planar: only revolute, "
                                 "continuous, prismatic and fixed joints form a serial arm")
                            .arg(source, qs(joint.name)));
        }
        if (!chain.joints.empty()) {
            const urdf::Link *next = i + 1 < path.size() ? path[i + 1].get() : nullptr;
            mergeFixedChildren(link, pending, next, source, chain.joints.back(), geometry.back());
        }
    }
    for (size_t j = 0; j < geometry.size(); ++j) {
        chain.joints[j].geometryBox = geometry[j].box();
        chain.joints[j].geometryDescription = geometry[j].description();
    }
    if (chain.joints.empty()) {
        throw Error(Text::tr("%1: no moving joint between link \"%2\" and link \"%3\"")
                        .arg(source, qs(base->name), tipName));
    }
    return chain;
}

SerialChain readUrdfChain(const QString &path, const QString &baseLink, const QString &tipLink)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw Error(Text::tr("%1: cannot read the URDF: %2").arg(path, file.errorString()));
    return parseUrdfChain(file.readAll(), path, baseLink, tipLink, QFileInfo(path).absolutePath());
}

} // namespace learnid
