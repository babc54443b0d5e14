#pragma once

#include "identify/LearningLaw.h"
#include "identify/ObservableUpdate.h"
#include "motion/TorqueRule.h"
#include "session/SafetyCheck.h"
#include "types/Trial.h"

#include <Eigen/Core>
#include <QMetaType>
#include <QString>
#include <memory>
#include <optional>

namespace learnid {

/// The pre-trial check of the next trial: its plan and the safety verdict, before any motion.
struct PreTrialCheck
{
    TrialPlan plan;
    TorqueRuleResult rule;
    SafetyVerdict verdict;
    QString planningError; ///< set when no plan could be made (then verdict is meaningless)

    bool passed() const { return planningError.isEmpty() && verdict.passed(); }
    QString reason() const { return planningError.isEmpty() ? verdict.reason : planningError; }
};

/// One trial of a session: what ran, what was measured and what was learned from it.
struct TrialResult
{
    int index = 0;           ///< 0 = the run with the initial estimate
    Eigen::VectorXd phiUsed; ///< estimate the feedforward was built with (m)
    PreTrialCheck check;     ///< plan and verdict before the motion
    TrialRecord record;      ///< measured (averaged over repetitions)
    int repetitions = 1;
    Eigen::VectorXd maxTrackingErrorDeg;   ///< max |q_d - q| per joint over the record [deg] (n)
    Eigen::VectorXd rmsTrackingErrorDeg;   ///< RMS of q_d - q per joint [deg] (n)
    std::optional<ParameterUpdate> update; ///< the learning step made from this trial
    QString message; ///< why it was refused, ended early or not learned from; or late set-points
    /// A trial stopped by the tracking limit and learned from: the samples learned from (the
    /// record's, less the filter's settling at its end); 0 for a completed trial.
    int partialSamples = 0;
    /// Why a series of trials (Run all) stops after this trial although it was learned from
    /// (a partial trial that is no progress, TrialSeries.h); empty: it may go on.
    QString seriesStop;
    /// Set when this trial tracked worse (max error) than the completed trial before it: in
    /// words, with the estimate that tracked best (TrialSeries.h); empty otherwise.
    QString worseTracking;

    const TrialPlan &plan() const { return check.plan; }
    TrialStatus status() const { return record.status; }
    bool learned() const { return update.has_value(); }
    /// Learned from the samples of a trial stopped by the tracking limit.
    bool learnedFromPartial() const { return learned() && !record.completed(); }
};

/// Tracking error figures of a record against its plan [deg], per joint.
void trackingErrorFigures(const TrialPlan &plan, const TrialRecord &record, Eigen::VectorXd &maxDeg,
                          Eigen::VectorXd &rmsDeg);

/// What a technician should know of a record's late set-points (TrialRecord::lateSetpoints), in
/// words; empty when there were none.
QString lateSetpointsNote(const TrialRecord &record);

} // namespace learnid

Q_DECLARE_METATYPE(learnid::TrialResult)
Q_DECLARE_METATYPE(learnid::PreTrialCheck)
Q_DECLARE_METATYPE(Eigen::VectorXd)
