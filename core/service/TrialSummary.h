#pragma once

#include "session/TrialResult.h"

namespace learnid {

/// A trial as the GUI thread keeps it: everything but the samples. The plan's trajectories and
/// feedforward and the record's angles and torques keep their column count with zero rows, so
/// plan().samples() and record.samples() still answer. The samples
/// stay with the session in the worker thread (trial CSV export goes there), so a trial costs
/// the GUI thread its figures only, however long it ran.
TrialResult trialSummary(const TrialResult &trial);

} // namespace learnid
