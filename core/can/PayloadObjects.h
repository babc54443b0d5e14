#pragma once

#include "can/ManufacturerObjects.h"
#include "can/SdoWrite.h"

#include <Eigen/Core>
#include <QList>

/// The payload a drive holds for the robot's controller: learnid's payload object, written by a
/// payload session's apply and stored with the parameters (docs/can-protocol.md §2.5).
namespace learnid::objects {

/// Payload, a RECORD: sub 0 = 11; sub 1 the joint whose moving body carries the payload,
/// 1-based (UNSIGNED8, rw; 0: no payload); subs 2..11 the payload's 10 standard parameters
/// about that body's frame origin, in its axes (REAL32, rw, SI units): m [kg], m cx, m cy, m cz
/// [kg m], Ixx, Ixy, Iyy, Ixz, Iyz, Izz [kg m^2] (a payload on a link fixed to the body already
/// moved into the body's frame: payloadInBody()). The controller adds them to that body's own.
constexpr quint16 payload = 0x2500;
constexpr quint8 payloadJoint = 1;
constexpr quint8 payloadFirstParameter = 2;
constexpr int payloadParameterCount = 10;
constexpr quint8 payloadHighestSubIndex = payloadFirstParameter + payloadParameterCount - 1;

/// The payload object's entries, sub 0 to 11, as the simulated drive's dictionary and the DCF
/// fragment describe them: sub 1 from 0 (no payload) to 127, the parameters any finite REAL32.
QList<ObjectDescription> payloadObjectDescriptions();

/// The writes of a payload on joint `joint` (1 .. nodes.size()) with parameters `body` (10, in
/// that joint's body frame) to every node, node after node: 0x2500:01 = joint, then
/// 0x2500:02..0B. Throws learnid::Error for a joint out of range or a value that is not a
/// finite REAL32.
QList<SdoWrite> payloadWrites(const QList<int> &nodes, int joint, const Eigen::VectorXd &body);

} // namespace learnid::objects
