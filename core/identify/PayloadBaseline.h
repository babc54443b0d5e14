#pragma once

#include "identify/LogSignals.h"
#include "model/Payload.h"

#include <vector>

namespace learnid {

/// The arm's own torque error measured without the payload, to take out of a payload log
/// (docs/payload.md, "A wrong arm model and the baseline trial").
///
/// A payload is fitted to tau - tau_arm: whatever the arm's model gets wrong along the path goes
/// into the payload (on the tip link a payload is indistinguishable from a change of that link's
/// body). A baseline is a log of the same timed path run without the payload: its residual
/// r_b = tau_b - tau_arm(q_b, qd_b, qdd_b) is the arm's error along the path plus noise. The
/// payload log minus the baseline's mean residual, sample by sample, leaves the payload's torque
/// and noise only (to first order in the tracking difference between the runs).
///
/// Returns `log` with its torque reduced by the mean residual of `baselines` (all filtered with
/// the same settings). Throws Error naming the logs when a baseline has another joint count,
/// period or sample count than `log`, or a value is not finite; no baselines: `log` unchanged.
FilteredLog withBaselineSubtracted(const PayloadModel &model, const FilteredLog &log,
                                   const std::vector<FilteredLog> &baselines);

} // namespace learnid
