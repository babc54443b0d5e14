#pragma once

#include "service/PayloadRun.h"

#include <QString>

namespace learnid {

/// What the payload step says before any motion (rich text): the robot and the payload it
/// carries in the simulation, the trials to run (baseline trials first), how many of the
/// payload's 10 parameters the path determines and which groups (mass, centre of mass,
/// inertia), the advice on what it does not see (PayloadObservability::advice()), and whether
/// the first trial passes its check. simulated: the scenario's true payload, shown for the
/// technician to compare.
QString payloadPreviewHtml(const PayloadPreview &preview, const SimulatedPayload &simulated);

/// The result in one paragraph (rich text): after which trial, the fit's determined directions
/// and condition, the bound, the mass with its standard error and the centre of mass.
QString payloadResultHtml(const PayloadRunResult &result);

} // namespace learnid
