#pragma once

#include "canrobot/CanRobotOptions.h"
#include "canrobot/DriveScaling.h"
#include "canrobot/SdoSequence.h"
#include "types/Trial.h"

#include <QVector>
#include <memory>

namespace learnid {

/// What configuring the nodes for a trial learns from them: the units of each drive.
struct NodeConfigurationResult
{
    QVector<DriveScaling> scaling; ///< per joint
};

/// The SDO accesses that prepare every node for a trial (docs/can-protocol.md, "A trial",
/// step 1): heartbeat, mode 8, interpolation period, gains, torque limit, RPDO1 and TPDO1
/// mappings, then the reads of the SYNC period (0x1006, must equal the plan's period), rated
/// torque (0x6076) and encoder resolution (0x608F). The reads fill result, which must outlive
/// the sequence. Throws learnid::Error when the plan cannot be sent (sample period not a whole
/// number of ms, a gain that does not fit REAL32, sizes that do not match the nodes).
QList<SdoStep> trialConfigurationSteps(const QList<int> &nodes, const TrialPlan &plan,
                                       const CanRobotOptions &options,
                                       std::shared_ptr<NodeConfigurationResult> result);

} // namespace learnid
