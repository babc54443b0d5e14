#include "session/PayloadSession.h"

#include "identify/PayloadBaseline.h"
#include "model/Error.h"
#include "session/SafetyCheck.h"

#include <QCoreApplication>
#include <ctime>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadSession)
};

std::shared_ptr<const ChainModel> chainOf(const std::shared_ptr<const RobotModel> &model,
                                          const QString &modelId)
{
    auto chain = std::dynamic_pointer_cast<const ChainModel>(model);
    if (!chain) {
        throw Error(Text::tr("payload: only a URDF robot carries a payload (the model is %1)")
                        .arg(modelId));
    }
    return chain;
}

// The observability of the planned paths together (their samples stacked).
PayloadObservability plannedObservability(const PayloadModel &model,
                                          const std::vector<JointTrajectory> &paths)
{
    Eigen::Index total = 0;
    for (const JointTrajectory &p : paths)
        total += p.samples();
    Eigen::MatrixXd q(model.dof(), total), qd(model.dof(), total), qdd(model.dof(), total);
    Eigen::Index at = 0;
    for (const JointTrajectory &p : paths) {
        q.middleCols(at, p.samples()) = p.q;
        qd.middleCols(at, p.samples()) = p.qd;
        qdd.middleCols(at, p.samples()) = p.qdd;
        at += p.samples();
    }
    return payloadPathObservability(model, q, qd, qdd);
}

// The first `samples` samples of a filtered log (all when it has no more).
FilteredLog cutFilteredLog(FilteredLog log, Eigen::Index samples)
{
    if (log.q.cols() <= samples)
        return log;
    log.q = log.q.leftCols(samples).eval();
    log.qd = log.qd.leftCols(samples).eval();
    log.qdd = log.qdd.leftCols(samples).eval();
    log.tau = log.tau.leftCols(samples).eval();
    return log;
}

UniformLog trialLog(const PayloadTrial &t)
{
    UniformLog log;
    log.source =
        t.baseline ? Text::tr("baseline trial %1").arg(t.index) : Text::tr("trial %1").arg(t.index);
    log.period = t.record.samplePeriod;
    log.q = t.record.q;
    log.tau = t.record.tau;
    return log;
}

} // namespace

PayloadSession::PayloadSession(const Scenario &scenario, std::shared_ptr<const RobotModel> model,
                               std::shared_ptr<Robot> robot, std::shared_ptr<Robot> bareRobot)
    : m_scenario(scenario)
    , m_model(chainOf(model, scenario.model))
    , m_robot(std::move(robot))
    , m_bareRobot(std::move(bareRobot))
    , m_prior(payloadPriorOf(scenario.payload))
    , m_planner(scenario, model)
{
    checkScenarioFitsModel(scenario, *m_model);
    validatePayloadPrior(m_prior);
    // The arm held fixed: the standard vector whose base parameters are the scenario's.
    try {
        m_payload = std::make_unique<PayloadModel>(
            m_model, m_model->standardFromBase(scenario.initialParameters), scenario.payload.link);
    } catch (const Error &e) {
        throw Error(QStringLiteral("payload.link: %1").arg(e.message()));
    }
    m_filter.rho = scenario.estimator.rho;
    m_current = m_prior.parameters();
}

Eigen::VectorXd PayloadSession::feedforwardParameters(const InertialParameters &payload) const
{
    return m_scenario.initialParameters + payloadBaseShift(*m_model, m_payload->link(), payload);
}

bool PayloadSession::nextTrialIsBaseline() const
{
    return int(m_baselines.size()) < m_scenario.payload.baselineTrials;
}

PayloadSession::NextTiming PayloadSession::nextTiming() const
{
    if (m_scenario.payload.baselineTrials > 0) {
        // One timed path for every trial, so that the baseline's samples line up with each
        // payload trial's: timed with the prior, gentle throughout if any trial is to be.
        return {feedforwardParameters(m_prior.parameters()), m_scenario.gentleTrials > 0};
    }
    return {feedforwardParameters(m_current), int(m_history.size()) < m_scenario.gentleTrials};
}

PreTrialCheck PayloadSession::checkNextTrial() const
{
    PreTrialCheck check;
    try {
        const Eigen::VectorXd phi =
            nextTrialIsBaseline() ? m_scenario.initialParameters : feedforwardParameters(m_current);
        const NextTiming timing = nextTiming();
        check.plan = m_planner.plan(timing.phi, &check.rule, timing.gentle, &phi);
        const PayloadSettings &p = m_scenario.payload;
        if (nextTrialIsBaseline() && p.baselineKp.size() > 0) { // the bare arm's own gains
            check.plan.controller.kp = p.baselineKp;
            check.plan.controller.ki = p.baselineKi;
            check.plan.controller.kd = p.baselineKd;
        }
        check.verdict = checkTrial(*m_model, phi, check.plan, m_scenario.stabilityMargin);
    } catch (const Error &e) {
        check.planningError = e.message();
    }
    return check;
}

PayloadObservability PayloadSession::observability() const
{
    const PreTrialCheck check = checkNextTrial();
    if (!check.planningError.isEmpty())
        return {};
    const JointTrajectory &d = check.plan.desired;
    return payloadPathObservability(*m_payload, d.q, d.qd, d.qdd);
}

PayloadPathChange PayloadSession::pathChange() const
{
    const PayloadObservability before = observability();
    if (before.rank == 0)
        return {};                          // not planned: nothing to compare with
    const NextTiming timing = nextTiming(); // as checkNextTrial() times the next trial
    return smallestPayloadPathChange(m_scenario, m_model, *m_payload, m_prior, timing.phi,
                                     timing.gentle, before);
}

const PayloadTrial &PayloadSession::runTrial()
{
    PayloadTrial t;
    t.index = int(m_history.size());
    t.baseline = nextTrialIsBaseline();
    t.payloadUsed = t.baseline ? InertialParameters::Zero() : m_current;
    t.check = checkNextTrial();
    if (!t.check.passed()) {
        t.record.status = TrialStatus::Refused;
        t.message =
            Text::tr("trial %1 refused before motion: %2").arg(t.index).arg(t.check.reason());
        m_history.push_back(std::move(t));
        return m_history.back();
    }
    TrialMonitor monitor;
    monitor.cancel = &m_cancel;
    Robot &robot = t.baseline && m_bareRobot ? *m_bareRobot : *m_robot;
    t.record = robot.runTrial(t.plan(), monitor);
    trackingErrorFigures(t.plan(), t.record, t.maxTrackingErrorDeg, t.rmsTrackingErrorDeg);
    t.partial = !t.baseline && t.record.stoppedAtTrackingLimit();
    t.message = lateSetpointsNote(t.record); // replaced by a reason the trial ended or failed
    if (!t.record.completed() && !t.partial) {
        t.message = Text::tr("trial %1 did not complete (%2): the payload estimate is unchanged")
                        .arg(t.index)
                        .arg(t.record.message);
        m_history.push_back(std::move(t));
        return m_history.back();
    }
    if (t.baseline) {
        try {
            m_baselines.push_back(filterLog(trialLog(t), m_filter));
            t.baselineKept = true;
        } catch (const Error &e) {
            t.message = Text::tr("baseline trial %1 not usable: %2").arg(t.index).arg(e.message());
        }
        m_history.push_back(std::move(t));
        return m_history.back();
    }
    try {
        const std::clock_t start = std::clock();
        // A record stopped early: the baselines and the planned path up to the stop.
        const Eigen::Index kept = t.record.samples();
        std::vector<FilteredLog> baselines = m_baselines;
        for (FilteredLog &b : baselines)
            b = cutFilteredLog(b, kept);
        std::vector<FilteredLog> logs = m_logs;
        logs.push_back(
            withBaselineSubtracted(*m_payload, filterLog(trialLog(t), m_filter), baselines));
        JointTrajectory planned = t.plan().desired;
        if (planned.samples() > kept) {
            planned.q = planned.q.leftCols(kept).eval();
            planned.qd = planned.qd.leftCols(kept).eval();
            planned.qdd = planned.qdd.leftCols(kept).eval();
        }
        std::vector<JointTrajectory> paths = m_paths;
        paths.push_back(planned);
        t.planned = plannedObservability(*m_payload, paths);
        PayloadFitSettings settings;
        settings.unseen = t.planned.unseen;
        PayloadFit fit = fitPayload(*m_payload, logs, m_prior, settings);
        t.updateCpuSeconds = double(std::clock() - start) / CLOCKS_PER_SEC;
        if (!fit.estimate.parameters.allFinite())
            throw Error(Text::tr("the payload fit produced non-finite parameters"));
        m_logs = std::move(logs);
        m_paths = std::move(paths);
        m_current = fit.estimate.parameters;
        t.fit = std::move(fit);
        if (t.partial) {
            t.message = Text::tr("trial %1 stopped at the tracking limit (%2): learned from the "
                                 "%3 s before the stop")
                            .arg(t.index)
                            .arg(t.record.message)
                            .arg(double(kept) * t.record.samplePeriod, 0, 'f', 2);
            // The previous payload trial stopped too: learning did not help, the gains must.
            for (auto it = m_history.rbegin(); it != m_history.rend(); ++it) {
                if (it->baseline)
                    continue;
                if (it->partial) {
                    t.seriesStop = true;
                    t.message += Text::tr("; the second stop in a row: the gains do not hold the "
                                          "payload, stiffen them (scenario --print --payload)");
                }
                break;
            }
        }
    } catch (const Error &e) {
        t.message = Text::tr("trial %1 not learned from: %2").arg(t.index).arg(e.message());
    }
    m_history.push_back(std::move(t));
    return m_history.back();
}

bool PayloadSession::runTrials(int count)
{
    m_cancel.store(false);
    while (nextTrialIsBaseline()) {
        if (m_cancel.load() || !runTrial().usable())
            return false;
    }
    for (int i = 0; i < count; ++i) {
        if (m_cancel.load() || !runTrial().usable())
            return false;
    }
    return true;
}

} // namespace learnid
