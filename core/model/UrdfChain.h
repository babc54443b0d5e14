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
/// planar joint on the chain, a mimic joint, a zero axis, a negative mass, or no moving joint.
SerialChain readUrdfChain(const QString &path, const QString &baseLink = {},
                          const QString &tipLink = {});

/// The same from the URDF text; source names it in messages (a file path or "built-in ...").
SerialChain parseUrdfChain(const QByteArray &xml, const QString &source,
                           const QString &baseLink = {}, const QString &tipLink = {});

} // namespace learnid
