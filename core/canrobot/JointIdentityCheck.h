#pragma once

#include "canrobot/SdoSequence.h"
#include "types/DriveIdentity.h"

#include <QList>
#include <QVector>
#include <memory>

namespace learnid {

/// What the nodes say about themselves, per joint (docs/can-protocol.md §2.4).
struct JointIdentityFound
{
    QVector<DriveIdentity> drives; ///< 0x1018:01..04
    QVector<quint32> robot;        ///< 0x2400:01, 0 when never commissioned
    QVector<int> joint;            ///< 0x2400:02, 1-based, 0 when never commissioned
};

/// What the master expects of the nodes.
struct JointIdentityExpectation
{
    quint32 robot = 0;                   ///< objects::robotIdentityOf(the model's id)
    bool commissioning = false;          ///< --commission: the technician confirmed the node list
    QList<DriveIdentity> recordedDrives; ///< per joint from a parameter file; empty: not compared
};

/// The reads of every node's identity, in node order: 0x1018:01..04, 0x2400:01..02; they fill
/// found, which must outlive the sequence.
QList<SdoStep> jointIdentityReads(const QList<int> &nodes,
                                  std::shared_ptr<JointIdentityFound> found);

/// Why a node is not the drive of the joint it is listed for, naming node and joint, or empty:
/// a node commissioned as another joint of this robot (always refused, with the node list the
/// drives give when they all agree); a drive other than the one the parameter file recorded for
/// the joint (always refused); a drive never commissioned (0x2400:01 = 0) or commissioned for
/// another robot, refused unless the expectation is commissioning (the first-time procedure).
QString jointIdentityError(const QList<int> &nodes, const JointIdentityFound &found,
                           const JointIdentityExpectation &expected);

} // namespace learnid
