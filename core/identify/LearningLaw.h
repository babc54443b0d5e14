#pragma once

#include "identify/ObservableUpdate.h"
#include "model/RobotModel.h"
#include "types/EstimatorSettings.h"
#include "types/Trial.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <memory>
#include <vector>

namespace learnid {

/// Work a law may keep per trial between updates, e.g. the filtered regression of a trial, which
/// later trials do not change. Owned with the trial by whoever keeps the trials.
struct LawCache
{
    virtual ~LawCache() = default;
};

/// One trial as a learning law sees it.
struct TrialData
{
    const TrialPlan *plan = nullptr;
    const TrialRecord *record = nullptr;
    std::shared_ptr<LawCache> *cache = nullptr; ///< optional slot the law may fill and reuse
    /// Samples to learn from: the first `rows` samples of the record (0: all). A trial stopped
    /// by the tracking limit is filtered over all it recorded, but the filter's settling at its
    /// end is left out (docs/method.md, "Learning from a trial stopped by the tracking limit").
    int rows = 0;

    /// The samples the law learns from: rows, bounded by the record's length.
    int usedSamples() const;
    /// The trial stopped early: the law learns from part of what was planned.
    bool partial() const;
};

/// The largest relative standard deviation of a direction learned from after `newest`:
/// settings.partialMaxRelativeStd after a partial trial, no limit after a completed one.
double partialTrialStdLimit(const TrialData &newest, const EstimatorSettings &settings);

/// One learning step (paper eq. 13): from a trial's plan and record and the estimate it ran
/// with, the next estimate. Laws are stateless; all they need comes in the arguments.
class LearningLaw
{
public:
    virtual ~LearningLaw() = default;
    virtual QString id() const = 0;
    /// trials: the completed trials so far, oldest first; the last is the newest, whose
    /// feedforward was built with phiPrev (m). A law uses the newest or all of them.
    /// Throws Error when a record cannot be used (too short, non-finite values).
    virtual ParameterUpdate update(const RobotModel &model, const std::vector<TrialData> &trials,
                                   const Eigen::VectorXd &phiPrev,
                                   const EstimatorSettings &settings) const = 0;
};

QStringList knownLearningLaws();
/// The law with this id ("paper" or "improved"), or nullptr.
std::unique_ptr<LearningLaw> makeLearningLaw(const QString &id);

/// Joint states estimated from the measured angles alone (paper eq. 15-17):
/// q_hat = q_d - F e, qd_hat = qd_d - F s e, qdd_hat = qdd_d - F s^2 e, e = q_d - q, with the
/// filter run causally (as a drive could online) or zero-phase (on recorded data). Each n x N.
struct JointStateEstimate
{
    Eigen::MatrixXd q;
    Eigen::MatrixXd qd;
    Eigen::MatrixXd qdd;
};
JointStateEstimate estimateJointStates(const class FilteringEstimator &filter,
                                       const TrialPlan &plan, const TrialRecord &record,
                                       bool zeroPhase);

/// Samples at the end of a record that the filtering estimator F(s) = rho^3 / (s + rho)^3,
/// run zero-phase, leaves unsettled when the record ends mid-motion (a trial stopped early):
/// the backward pass starts at rest there, so the joint states it estimates, and through them
/// the filtered regressor, are off for about partialSettlingRhoTimes / rho seconds.
constexpr double partialSettlingRhoTimes = 8.0;
int partialSettlingSamples(double rho, double samplePeriod);

/// Checks that plan and record agree in size and hold only finite numbers; throws Error naming
/// the first bad sample and joint.
void validateRecord(const RobotModel &model, const TrialPlan &plan, const TrialRecord &record);

} // namespace learnid
