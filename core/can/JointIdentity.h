#pragma once

#include "can/SdoWrite.h"

#include <QList>
#include <QString>

/// Which joint a drive moves: learnid's joint identity object, written at apply and stored with
/// the parameters, read before any motion, and the CiA 301 identity object (docs/can-protocol.md
/// §2.4).
namespace learnid::objects {

/// Joint identity, a RECORD: sub 0 = 2; sub 1 the robot's identity (UNSIGNED32, rw), sub 2 the
/// joint the drive moves, 1-based (UNSIGNED8, rw). 0 in both: never commissioned.
constexpr quint16 jointIdentity = 0x2400;
constexpr quint8 jointIdentityRobot = 1;
constexpr quint8 jointIdentityJoint = 2;
/// CiA 301 identity object (RECORD): sub 1 vendor id, 2 product code, 3 revision, 4 serial.
constexpr quint16 identityObject = 0x1018;

/// The robot identity of a model: CRC-32 (IEEE 802.3) of its id in UTF-8 (e.g. "paper-2link"),
/// never 0 (0 means "never commissioned").
quint32 robotIdentityOf(const QString &modelId);

/// The writes that commission the nodes (joint j's node gets robot and j + 1), in node order:
/// 0x2400:01 = robot, 0x2400:02 = joint.
QList<SdoWrite> jointIdentityWrites(const QList<int> &nodes, quint32 robot);

} // namespace learnid::objects
