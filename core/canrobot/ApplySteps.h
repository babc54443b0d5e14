#pragma once

#include "canrobot/SdoSequence.h"

#include <Eigen/Core>
#include <QList>

namespace learnid {

/// The SDO accesses of "apply" (docs/can-protocol.md, "Apply"): objects::parameterWriteSequence
/// without its stores, then every written object read back and compared bit for bit, then the
/// stores (0x1010:01 = "save") on each node. Run as one SdoSequence, a refused write or read or
/// a difference stops it before any store is written. Throws learnid::Error for a set that
/// cannot be sent (see parameterWriteSequence). With robotIdentity (not 0) the joint identity
/// objects 0x2400 are written, read back and stored with the parameters.
QList<SdoStep> applySteps(const QList<int> &nodes, const Eigen::VectorXd &phi,
                          quint32 robotIdentity = 0);

/// The SDO accesses of a payload's apply (docs/can-protocol.md, "Apply"): objects::payloadWrites
/// (0x2500:01..0B on every node), every one read back and compared bit for bit, then the stores
/// on each node, as applySteps(). joint is 1-based; body the payload's 10 parameters in that
/// joint's body frame. Throws learnid::Error for a payload that cannot be sent.
QList<SdoStep> payloadApplySteps(const QList<int> &nodes, int joint, const Eigen::VectorXd &body);

} // namespace learnid
