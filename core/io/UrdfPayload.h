#pragma once

#include "model/SerialChain.h"

#include <QByteArray>
#include <QString>

namespace learnid {

/// The names urdfWithPayload() gives the payload's link and joint (made unique with "_2", "_3"
/// when the URDF already has such a link or joint).
inline constexpr char urdfPayloadLinkName[] = "payload";
inline constexpr char urdfPayloadJointName[] = "payload_joint";

/// The URDF text `xml` with a payload added before its closing </robot>, the rest of the text
/// as it is (docs/file-formats.md, "URDF with a payload"):
///
///   <!-- comment -->
///   <joint name="payload_joint" type="fixed">
///     <parent link="LINK"/><child link="payload"/><origin xyz="0 0 0" rpy="0 0 0"/>
///   </joint>
///   <link name="payload"><inertial><origin xyz="c" rpy="0 0 0"/><mass value="m"/>
///     <inertia about the centre of mass, in LINK's axes/></inertial></link>
///
/// so the payload's frame is LINK's. payload: its 10 standard parameters about LINK's frame
/// origin (SerialChain.h), a real body. chain gives the base and tip links the text is read with;
/// LINK is one of its moving links or a link fixed to one (payloadLinkOf(); empty: the tip's
/// body), and LINK's body is the moving one it is on. Numbers in the
/// shortest form that reads back to the same double. The result is read back (readUrdfChain()
/// with the chain's base and tip): LINK's body must be the one before plus the payload, every
/// other body unchanged. Throws Error naming source and the link when the text is not a URDF of
/// that chain, the link is unknown, the payload is not a real body (mass <= 0, not finite, a
/// pseudo-inertia not positive semidefinite up to rounding), or the text does not read back so.
QByteArray urdfWithPayload(const QByteArray &xml, const QString &source, const SerialChain &chain,
                           const QString &link, const InertialParameters &payload,
                           const QString &comment);

} // namespace learnid
