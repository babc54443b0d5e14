#pragma once

#include "io/JsonReader.h"
#include "io/JsonTree.h"
#include "types/Scenario.h"

namespace learnid {

class RobotModel;

// The scenario's payload keys (docs/scenario.md, payload and simulation.payload).

/// Reads the "payload" section into p (p.enabled becomes true): link, prior.mass (required),
/// prior.com, prior.inertia, bound.radius or bound.box. Throws Error at the key path.
void readPayloadSection(JsonObjectReader r, PayloadSettings &p);
/// Reads "simulation.payload": mass (required), com, inertia.
void readSimulatedPayload(JsonObjectReader r, SimulatedPayload &p);

JsonTree payloadSectionJson(const PayloadSettings &p);
JsonTree simulatedPayloadJson(const SimulatedPayload &p);

/// Checks the payload keys of scenario s on its model: a payload only on a URDF robot, the
/// prior (validatePayloadPrior, scenario key names), the link one of the chain's moving links,
/// the simulated payload a real body (mass > 0, finite, principal moments >= 0 and each at most
/// the sum of the others). Throws Error "<key path>: <problem>".
void validateScenarioPayload(const Scenario &s, const RobotModel &model);

} // namespace learnid
