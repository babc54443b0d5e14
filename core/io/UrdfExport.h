#pragma once

#include "model/SerialChain.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <vector>

namespace learnid {

/// A joint's identified terms: friction as URDF's <dynamics> holds it (finite, not negative),
/// rotor inertia (not negative) and torque offset in learnid's extension (UrdfExtension.h).
struct IdentifiedJoint
{
    double viscous = 0.0;  ///< <dynamics damping> [N m s/rad] or [N s/m]
    double coulomb = 0.0;  ///< <dynamics friction> [N m] or [N]
    double armature = 0.0; ///< <learnid:dynamics armature> [kg m^2] or [kg]
    double offset = 0.0;   ///< <learnid:dynamics offset> [N m] or [N]
};

/// The URDF text of `originalXml` (the robot's own URDF, as given) with, for each moving joint j
/// of `chain` (as readUrdfChain() read it from that text with chain.baseLink and chain.tipLink):
///  - the moving body's inertial replaced by inertials[j] (standard parameters about the joint's
///    child link frame, SerialChain.h): written on the child link as
///    <inertial><origin xyz="c" rpy="0 0 0"/><mass/><inertia about the centre of mass/></inertial>
///    with c = h / m and I_c = I_O - m (|c|^2 E - c c^T);
///  - the <inertial> of every link readUrdfChain() merged into that body (links on fixed joints
///    below it, on the chain or off it, such as a tool) removed: their mass is in the moving
///    link now, so re-reading the text gives inertials[j] again, not the sum of both;
///  - the joint's <dynamics damping friction> set to friction[j] (viscous, Coulomb); a joint
///    without <dynamics> gets one;
///  - the joint's <learnid:dynamics armature offset> (UrdfExtension.h) set to friction[j]'s,
///    added after <dynamics> where either is not 0 (with xmlns:learnid on <robot>).
/// Everything else (visuals, collisions, materials, transmissions, gazebo tags, links fixed to
/// the base, links beyond moving joints off the chain, the order of elements, comments) is kept
/// as the original has it; attributes are written in name order (Qt's DOM does not keep their
/// order). An XML comment before <robot> holds `comment` (e.g. tool version and date), which links
/// were merged into which, and where armature and offsets are; a second one the lines of `notes`
/// (e.g. what the data determined), when there are any. Numbers are
/// written in the shortest form that reads back to the same double. source names the original in
/// messages.
///
/// Throws Error naming source and the link or joint when inertials or friction do not have
/// chain.dof() entries, the text is not XML, chain is not the one the text gives, a body is not
/// physical (mass <= 0, an entry not finite, or a pseudo-inertia not positive semidefinite up to
/// rounding: checkConsistency() with tolerance 1e-12), a friction or armature is negative or not
/// finite, an offset not finite, or re-reading the written text does not give the written
/// bodies and joint terms.
QByteArray identifiedUrdf(const QByteArray &originalXml, const QString &source,
                          const SerialChain &chain,
                          const std::vector<InertialParameters> &inertials,
                          const std::vector<IdentifiedJoint> &friction, const QString &comment,
                          const QStringList &notes = {});

} // namespace learnid
