#include "session/CommissioningSession.h"

#include "model/Error.h"
#include "session/TrialSeries.h"

#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcSession, "learnid.session")

namespace learnid {

CommissioningSession::CommissioningSession(const Scenario &scenario,
                                           std::shared_ptr<const RobotModel> model,
                                           std::shared_ptr<Robot> robot, QObject *parent)
    : QObject(parent)
    , m_scenario(scenario)
    , m_model(std::move(model))
    , m_robot(std::move(robot))
    , m_law(makeLearningLaw(scenario.law))
    , m_planner(scenario, m_model)
{
    if (!m_law)
        throw Error(tr("unknown estimator law '%1' (known: %2)")
                        .arg(scenario.law, knownLearningLaws().join(QStringLiteral(", "))));
    checkScenarioFitsModel(scenario, *m_model);
    m_estimates.append(scenario.initialParameters);
    qRegisterMetaType<learnid::TrialResult>();
}

CommissioningSession::~CommissioningSession() = default;

const TrialResult *CommissioningSession::trialRunWith(int estimateIndex) const
{
    // Trials that were not learned from leave the estimate unchanged: the next one runs with it.
    const TrialResult *found = nullptr;
    int estimate = 0;
    for (const TrialResult &t : m_history) {
        if (estimate == estimateIndex)
            found = &t;
        if (t.learned())
            ++estimate;
    }
    return found;
}

PreTrialCheck CommissioningSession::checkNextTrial() const
{
    PreTrialCheck check;
    try {
        // Gentle until the estimate has been learned path.gentleTrials times.
        const bool gentle = int(m_estimates.size()) - 1 < m_scenario.gentleTrials;
        check.plan = m_planner.plan(currentEstimate(), &check.rule, gentle);
        // The check linearises the robot as the estimate describes it. An estimate that is not
        // a set of real bodies (URDF robots: what the path does not see is filled in from the
        // CAD model) can describe a plant no robot is; its nearest consistent estimate has the
        // same torques on the path and stands in for it (docs/robots.md §6).
        Eigen::VectorXd standIn = currentEstimate();
        const EstimateConsistency c =
            checkEstimateConsistency(*m_model, standIn, check.plan.desired);
        if (c.applicable && !c.consistent && c.nearestError.isEmpty())
            standIn = c.nearest;
        check.verdict = checkTrial(*m_model, standIn, check.plan, m_scenario.stabilityMargin);
    } catch (const Error &e) {
        check.planningError = e.message();
    }
    return check;
}

const TrialResult &CommissioningSession::runTrial()
{
    m_cancel.store(false);
    return runNextTrial();
}

const TrialResult &CommissioningSession::runNextTrial()
{
    TrialResult result;
    result.index = int(m_history.size());
    result.phiUsed = currentEstimate();
    result.check = checkNextTrial();
    result.repetitions = std::max(1, m_scenario.repetitions);

    if (!result.check.passed()) {
        result.record.status = TrialStatus::Refused;
        result.record.samplePeriod = m_scenario.controller.samplePeriod;
        result.message =
            tr("trial %1 refused before motion: %2").arg(result.index).arg(result.check.reason());
        qCWarning(lcSession).noquote() << result.message;
    } else {
        emit trialStarted(result.index, result.plan().samples());
        result.record = runRepetitions(result.plan(), result.index, &result.message);
        trackingErrorFigures(result.plan(), result.record, result.maxTrackingErrorDeg,
                             result.rmsTrackingErrorDeg);
        if (result.record.completed())
            learnFrom(result);
        else if (result.record.stoppedAtTrackingLimit())
            learnFromPartial(result);
        // Never learned from: a fault, an EMCY, a lost heartbeat, missing samples, Stop.
        if (result.message.isEmpty()) { // nothing else to say: the late set-points, if any
            result.message = lateSetpointsNote(result.record);
            if (!result.message.isEmpty())
                qCWarning(lcSession).noquote() << result.message;
        }
        result.seriesStop = seriesStopAfterAbort(m_history, result);
        result.worseTracking = worseTrackingNote(m_history, result);
        for (const QString &note : {result.seriesStop, result.worseTracking})
            if (!note.isEmpty())
                qCInfo(lcSession).noquote() << note;
    }
    m_history.append(result);
    emit trialFinished(m_history.constLast());
    return m_history.constLast();
}

TrialRecord CommissioningSession::runRepetitions(const TrialPlan &plan, int index, QString *message)
{
    const int reps = std::max(1, m_scenario.repetitions);
    const int total = plan.samples() * reps;
    TrialRecord sum;
    for (int r = 0; r < reps; ++r) {
        TrialMonitor monitor;
        monitor.cancel = &m_cancel;
        monitor.progress = [this, index, r, &plan, total](int done, int) {
            emit progress(index, r * plan.samples() + done, total);
        };
        TrialRecord record = m_robot->runTrial(plan, monitor);
        if (!record.completed()) {
            *message = reps > 1
                           ? tr("repetition %1 of %2: %3").arg(r + 1).arg(reps).arg(record.message)
                           : record.message;
            return record; // the partial record of the run that failed is kept
        }
        if (r == 0) {
            sum = std::move(record);
        } else {
            sum.q += record.q;
            sum.tau += record.tau;
            sum.lateSetpoints += record.lateSetpoints;
        }
    }
    sum.q /= double(reps);
    sum.tau /= double(reps);
    return sum;
}

void CommissioningSession::learnFromPartial(TrialResult &result)
{
    // The samples up to the stop, less the filter's settling at the end (LearningLaw.h); too
    // short a record observes nothing once it has settled and is not learned from.
    const int recorded = result.record.samples();
    const int settling =
        partialSettlingSamples(m_scenario.estimator.rho, result.record.samplePeriod);
    const int rows = recorded - settling;
    if (rows < minimumPartialSamples) {
        result.message =
            tr("trial %1 stopped at the tracking limit after %2 s: too short to learn from once "
               "the filter has settled (%3 s); the estimate is unchanged")
                .arg(result.index)
                .arg(std::max(recorded - 1, 0) * result.record.samplePeriod, 0, 'f', 3)
                .arg(settling * result.record.samplePeriod, 0, 'f', 3);
        qCWarning(lcSession).noquote() << result.message;
        return;
    }
    m_partialPlans[result.index] = planUpTo(result.plan(), recorded);
    result.partialSamples = rows;
    learnFrom(result);
    if (result.learned() && result.update->rank == 0) {
        // Nothing observed: the estimate did not move; not counted as progress.
        m_estimates.removeLast();
        result.update.reset();
        result.partialSamples = 0;
        result.message = tr("trial %1 stopped at the tracking limit: its %2 s before the stop "
                            "observe no parameter; the estimate is unchanged")
                             .arg(result.index)
                             .arg(rows * result.record.samplePeriod, 0, 'f', 3);
    }
    if (!result.learned())
        m_partialPlans.erase(result.index);
}

TrialData CommissioningSession::trialData(const TrialResult &t,
                                          std::shared_ptr<LawCache> *cache) const
{
    const auto partial = m_partialPlans.find(t.index);
    if (partial == m_partialPlans.end())
        return {&t.plan(), &t.record, cache};
    return {&partial->second, &t.record, cache, t.partialSamples};
}

void CommissioningSession::learnFrom(TrialResult &result)
{
    // One cache slot per trial index, the new trial's last; the law fills and reuses them.
    m_lawCaches.resize(std::size_t(m_history.size()) + 1);
    std::vector<TrialData> trials;
    for (qsizetype i = 0; i < m_history.size(); ++i) {
        const TrialResult &earlier = m_history.at(i);
        if (earlier.learned())
            trials.push_back(trialData(earlier, &m_lawCaches[std::size_t(i)]));
    }
    trials.push_back(trialData(result, &m_lawCaches.back()));
    try {
        ParameterUpdate update =
            m_law->update(*m_model, trials, result.phiUsed, m_scenario.estimator);
        if (!update.phi.allFinite())
            throw Error(tr("the update produced non-finite parameters"));
        m_estimates.append(update.phi);
        result.update = std::move(update);
    } catch (const Error &e) {
        result.message = tr("trial %1 not learned from: %2").arg(result.index).arg(e.message());
        qCWarning(lcSession).noquote() << result.message;
    }
}

bool CommissioningSession::runTrials(int count, bool keepEarlierStop)
{
    // Reset once: a Stop that arrives between two trials of the series must end it.
    if (!keepEarlierStop)
        m_cancel.store(false);
    for (int i = 0; i < count; ++i) {
        if (m_cancel.load())
            return false;
        const TrialResult &t = runNextTrial();
        if (!t.learned() || !t.seriesStop.isEmpty())
            return false;
    }
    return true;
}

void CommissioningSession::requestCancel()
{
    m_cancel.store(true);
}

QString CommissioningSession::accept(int estimateIndex, bool nearestConsistent)
{
    if (estimateIndex < 1 || estimateIndex >= m_estimates.size()) {
        return m_estimates.size() < 2
                   ? tr("there is no learned estimate to accept yet: run a trial first")
                   : tr("estimate %1 does not exist: choose 1 to %2")
                         .arg(estimateIndex)
                         .arg(m_estimates.size() - 1);
    }
    Eigen::VectorXd phi = m_estimates.at(estimateIndex);
    if (nearestConsistent) {
        const EstimateConsistency c = consistency(estimateIndex, NearestEstimate::Always);
        if (!c.applicable)
            return tr("only URDF robots have standard parameters to make consistent");
        if (!c.nearestError.isEmpty())
            return tr("no consistent estimate near estimate %1: %2")
                .arg(estimateIndex)
                .arg(c.nearestError);
        phi = c.nearest;
    }
    m_accepted = estimateIndex;
    m_acceptedParameters = phi;
    emit estimateAccepted(estimateIndex);
    return {};
}

Eigen::VectorXd CommissioningSession::acceptedParameters() const
{
    return m_accepted ? m_acceptedParameters : Eigen::VectorXd();
}

PathIdentifiability CommissioningSession::identifiability() const
{
    const PreTrialCheck check = checkNextTrial();
    if (!check.planningError.isEmpty())
        return {};
    return pathIdentifiability(*m_model, check.plan.desired, currentEstimate(),
                               m_scenario.estimator.rankTolerance);
}

EstimateConsistency CommissioningSession::consistency(int estimateIndex, NearestEstimate when) const
{
    if (estimateIndex < 0 || estimateIndex >= m_estimates.size())
        return {};
    const TrialResult *ran = trialRunWith(estimateIndex);
    if (!ran && !m_history.isEmpty())
        ran = &m_history.constLast();
    const JointTrajectory path = ran ? ran->plan().desired : JointTrajectory();
    return checkEstimateConsistency(*m_model, m_estimates.at(estimateIndex), path, when);
}

QString CommissioningSession::apply()
{
    if (!m_accepted)
        return tr("nothing accepted: accept an estimate before applying it");
    const Eigen::VectorXd before = m_robot->storedParameters();
    const Eigen::VectorXd phi = m_acceptedParameters;
    const QString error = m_robot->applyParameters(phi);
    if (!error.isEmpty())
        return error;
    m_storedBeforeApply.append(before);
    m_appliedIndices.append(*m_accepted);
    m_applied.append(phi);
    emit parametersApplied(phi);
    return {};
}

QString CommissioningSession::revert()
{
    if (m_storedBeforeApply.isEmpty())
        return tr("nothing to revert: no parameter set has been applied in this session");
    const Eigen::VectorXd previous = m_storedBeforeApply.constLast();
    if (previous.size() == 0)
        return tr("the robot held no parameter set before the first apply; there is nothing "
                  "to restore");
    const QString error = m_robot->applyParameters(previous);
    if (!error.isEmpty())
        return error;
    m_storedBeforeApply.removeLast();
    m_appliedIndices.removeLast();
    m_applied.append(previous);
    emit parametersApplied(previous);
    return {};
}

} // namespace learnid
