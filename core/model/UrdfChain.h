#pragma once

#include "model/SerialChain.h"

#include <QByteArray>
#include <QString>

namespace learnid {

/// The serial chain from baseLink to tipLink of the URDF file at path, parsed by Debian's
/// urdfdom. Empty baseLink: the URDF's root link; empty tipLink: the one leaf below the base
/// (refused, naming the link, when the tree branches there). Revolute and continuous joints
/// become revolute, prismatic stay prismatic; links on fixed joints are merged into the moving
/// body they hang on (also fixed links off the chain, such as a tool); moving joints off the
/// chain are not part of it. Links fixed to the base do not move and are dropped.
/// Throws Error naming the file and, where the fault is, the link or joint: unreadable file,
/// invalid URDF (with urdfdom's message), unknown link, tip not below base, a floating or
/// planar joint on the chain, a mimic joint, a zero axis, a negative mass, a shape of negative
/// size (UrdfGeometry.h), a bad learnid extension element (UrdfExtension.h; naming line and
/// column), or no moving joint.
///
/// Each joint also gets its body's geometry box (ChainJoint::geometryBox: the collision shapes,
/// else the visual ones, of the links merged into it; meshes by their file's bounding box, found
/// relative to the URDF's folder or through ROS_PACKAGE_PATH, skipped when they cannot be read)
/// and its armature and torque offset from learnid's extension element (0 without one).
SerialChain readUrdfChain(const QString &path, const QString &baseLink = {},
                          const QString &tipLink = {});

/// The same from the URDF text; source names it in messages (a file path or "built-in ...").
/// urdfDirectory: the folder relative mesh names (and package:// names, after
/// ROS_PACKAGE_PATH) are looked for from; empty: relative mesh names are skipped.
SerialChain parseUrdfChain(const QByteArray &xml, const QString &source,
                           const QString &baseLink = {}, const QString &tipLink = {},
                           const QString &urdfDirectory = {});

} // namespace learnid
