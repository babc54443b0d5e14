#pragma once

#include "identify/LogSignals.h"
#include "model/Payload.h"

#include <limits>
#include <vector>

namespace learnid {

/// How baselines are laid over a payload log (withBaselineSubtracted).
struct BaselineSettings
{
    /// [s] 0: a baseline is on the log's grid sample for sample (the learning loop: one plan,
    /// one length). > 0: recorded logs that start at different moments; each baseline is shifted
    /// by the whole number of samples within +-maxShift whose joint angles match the log's best.
    double maxShift = 0.0;
    /// [deg] Refuse a baseline whose joint angles differ from the log's by more than this (RMS
    /// over joints and samples, after the shift): it did not run the same path.
    double maxAngleRmsDeg = std::numeric_limits<double>::infinity();
    /// The part of the log every baseline must cover after its shift; the rest is cut off.
    double minOverlap = 0.8;
};

/// Where a baseline was laid: its sample k + shift lines up with the log's sample k.
struct BaselineAlignment
{
    QString baseline, log;
    Eigen::Index shift = 0;
    double shiftSeconds = 0.0;
    double angleRmsDeg = 0.0; ///< RMS of q_log - q_baseline over joints and overlapping samples
};

/// The arm's own torque error measured without the payload, taken out of a payload log
/// (docs/payload.md, "A wrong arm model and the baseline trial").
///
/// A payload is fitted to tau - tau_arm: whatever the arm's model gets wrong along the path goes
/// into the payload (on the tip link a payload is indistinguishable from a change of that link's
/// body). A baseline is a log of the same timed path run without the payload: its residual
/// r_b = tau_b - tau_arm(q_b, qd_b, qdd_b) is the arm's error along the path plus noise. The
/// payload log minus the baselines' mean residual, sample by sample, leaves the payload's torque
/// and noise only (to first order in the difference between the runs' motions).
///
/// Returns `log` reduced to the samples every baseline covers, its torque less their mean
/// residual (all filtered with the same settings); `alignments` (if given) gets one entry per
/// baseline. Throws Error naming the logs when a baseline has another joint count or period, on
/// the log's grid another length (maxShift 0), covers less than minOverlap of it, does not
/// follow its path within maxAngleRmsDeg, or has a value that is not finite. No baselines: `log`
/// unchanged.
FilteredLog withBaselineSubtracted(const PayloadModel &model, const FilteredLog &log,
                                   const std::vector<FilteredLog> &baselines,
                                   const BaselineSettings &settings = {},
                                   std::vector<BaselineAlignment> *alignments = nullptr);

} // namespace learnid
