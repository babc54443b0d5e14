#pragma once

#include <QByteArray>
#include <QString>

namespace learnid {

/// Checks, before urdfdom reads the text, that it is well-formed XML and that the <joint>
/// elements directly below <robot> join their links into a tree: no joint connects a link to
/// itself, no link is the child of two joints, and following parents never comes back to a
/// link. Throws Error naming source and, for XML, line and column; for the tree, the joints and
/// links. Joints without a parent or child link name are left to urdfdom, which reports them.
///
/// Written by hand because urdfdom does not check this: it links the joints' links through
/// shared pointers whatever they form, so a loop is never freed (a leak for every such file
/// opened), and a link that is its own child makes every walk down the tree endless.
void checkUrdfJointTree(const QByteArray &xml, const QString &source);

} // namespace learnid
