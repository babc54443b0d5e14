#pragma once

#include <QByteArray>
#include <QHash>
#include <QString>

namespace learnid {

/// learnid's extension of URDF (docs/file-formats.md, "learnid's URDF extension"): inside a
/// <joint>, the element
///   <learnid:dynamics armature="IA" offset="O"/>
/// holds the joint's rotor inertia as the joint sees it [kg m^2 or kg] and its torque offset
/// [N m or N], the two joint terms URDF has no place for. The prefix is bound to
/// urdfExtensionNamespace on <robot>. urdfdom (and so KDL, pinocchio, MoveIt) skips elements it
/// does not know.
inline constexpr char urdfExtensionElement[] = "learnid:dynamics";
inline constexpr char urdfExtensionPrefix[] = "learnid";
inline constexpr char urdfExtensionNamespace[] = "urn:learnid:urdf:1";

/// A joint's extension values; 0 where the URDF has none.
struct JointExtension
{
    double armature = 0.0;
    double offset = 0.0;
};

/// The extension element of every <joint> directly below <robot> that has one, by joint name.
/// Throws Error naming source, line and column when an attribute is not a finite number, the
/// element is given twice in a joint, or has an attribute other than armature and offset. XML
/// errors are left to the URDF parser (this reads only what it accepted).
QHash<QString, JointExtension> readJointExtensions(const QByteArray &xml, const QString &source);

} // namespace learnid
