#pragma once

#include "session/TrialResult.h"

#include <QVector>
#include <optional>

namespace learnid {

// What a series of trials makes of each trial beyond the trial itself: how far a trial stopped
// by the tracking limit ran, whether Run all goes on after it, and which estimate tracked best
// (docs/method.md, "Learning from a trial stopped by the tracking limit").

/// The first `samples` samples of a plan (desired motion and feedforward): what a trial stopped
/// early ran, the plan its partial record is learned against. samples <= plan.samples().
TrialPlan planUpTo(const TrialPlan &plan, int samples);

/// Aborts in a row after which Run all stops unless each was progress over the one before.
constexpr int maxAbortsInARow = 3;

/// Whether Run all stops after `latest`, a trial learned from a partial record, that follows
/// `earlier` (oldest first). It goes on while each abort of the aborts in a row ending with
/// `latest` is progress over the one before it: it stopped later on the path, or with a
/// smaller tracking error. Once maxAbortsInARow aborts are in a row and one was not progress,
/// it stops. Returns the reason in words, or empty to go on.
QString seriesStopAfterAbort(const QVector<TrialResult> &earlier, const TrialResult &latest);

/// The estimate (index into CommissioningSession::estimates()) each trial of `history` ran with.
QVector<int> estimateIndices(const QVector<TrialResult> &history);

/// A trial tracks worse than another when its max tracking error is larger by more than this
/// share: below it, converged trials differ by scatter (the noise-free paper arm's trials 1-3 by
/// 0.5 %, 1 % torque noise on the LWR4+ by 2 %), which is no reason to go back.
constexpr double worseTrackingMargin = 0.05;

/// The learned estimate (index >= 1) whose completed trial tracked best: the smallest max
/// tracking error over the joints; nullopt when no completed trial ran with a learned estimate.
std::optional<int> bestTrackingEstimate(const QVector<TrialResult> &history);

/// The estimate Accept proposes among 1 .. estimateCount - 1: the newest, unless the latest
/// completed trial tracked worse (worseTrackingMargin) than the best one run with a learned
/// estimate; then that one's.
/// 0 when nothing is learned yet.
int proposedEstimate(const QVector<TrialResult> &history, int estimateCount);

/// When `latest` completed and tracked worse (max error, by more than worseTrackingMargin) than
/// the completed trial before it in
/// `earlier`: says so, naming the estimate that tracked best; empty otherwise.
QString worseTrackingNote(const QVector<TrialResult> &earlier, const TrialResult &latest);

} // namespace learnid
