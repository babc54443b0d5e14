#pragma once

#include "cansim/CanArmSimulator.h"
#include "types/Scenario.h"

#include <QByteArray>
#include <QList>

namespace learnid {

/// The CAN arm a scenario describes, as SimulatedRobot would simulate it (makeSimulatedRobot):
/// the model's true parameters (with the payload of simulation.payload), encoder counts, torque
/// noise, seed and substeps; the controller's gains and sample period (the SYNC period); the torque
/// limits; the arm at rest at the start of the scenario's path. Throws learnid::Error when the path
/// start is out of reach.
CanArmSettings canArmSettings(const Scenario &scenario, std::shared_ptr<const RobotModel> model,
                              const QList<int> &nodes);

/// learnid-robot-sim's --state file: {"nodes": {"1": {"storedParameters": [...]}, ...}} with
/// each node's stored identified parameters (0x2200 at the last "save"; [] before any) and,
/// once one was stored, its payload: "storedPayload": {"joint": k, "parameters": [10 values]}
/// (0x2500).
QByteArray simulatorStateJson(const CanArmSimulator &simulator);

} // namespace learnid
