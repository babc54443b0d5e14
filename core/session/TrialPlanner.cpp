#include "session/TrialPlanner.h"

#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/VectorState.h"
#include "motion/TwoLinkKinematics.h"

#include <QCoreApplication>
#include <algorithm>

namespace learnid {

TrialPlanner::TrialPlanner(const Scenario &scenario, std::shared_ptr<const RobotModel> model)
    : m_scenario(scenario)
    , m_model(std::move(model))
{
    if (const auto *chain = dynamic_cast<const ChainModel *>(m_model.get())) {
        const int n = chain->dof();
        m_positionLower.resize(n);
        m_positionUpper.resize(n);
        m_velocityLimit.resize(n);
        for (int j = 0; j < n; ++j) {
            const ChainJoint &joint = chain->chain().joints[size_t(j)];
            m_positionLower[j] = joint.lower;
            m_positionUpper[j] = joint.upper;
            m_velocityLimit[j] = joint.velocityLimit;
        }
    }
    if (scenario.path.kind == PathKind::Waypoints) {
        m_path = std::make_unique<WaypointPath>(scenario.path.waypoints);
    } else if (scenario.path.kind == PathKind::File) {
        auto sampled =
            std::make_unique<SampledPath>(scenario.path.fileTimes, scenario.path.fileAngles);
        m_shortestDuration = sampled->nominalDuration();
        m_path = std::move(sampled);
    }
    if (m_path) {
        if (m_path->dof() != m_model->dof()) {
            throw Error(
                QCoreApplication::translate("TrialPlanner", "the path has %1 joints, the robot %2")
                    .arg(m_path->dof())
                    .arg(m_model->dof()));
        }
        m_ruleGrid = torqueRuleGrid(*m_model, *m_path);
        if (m_velocityLimit.size() == m_path->dof()) {
            // 99 %: the sampled trajectory's peak lies between the grid's points, and the
            // pre-trial check refuses a speed above the limit by any rounding.
            constexpr double speedShare = 0.99;
            // qd = dq/du / T: the peak of |dq/du| over the path fixes the duration a limit needs.
            const int n = m_path->dof();
            Eigen::VectorXd q(n), dq(n), ddq(n), peak = Eigen::VectorXd::Zero(n);
            constexpr int points = 2001;
            for (int i = 0; i < points; ++i) {
                m_path->stateInto(double(i) / (points - 1), q, dq, ddq);
                peak = peak.cwiseMax(dq.cwiseAbs());
            }
            for (int j = 0; j < n; ++j)
                m_speedDuration =
                    std::max(m_speedDuration, peak[j] / (speedShare * m_velocityLimit[j]));
        }
        return;
    }
    if (m_model->dof() != 2 || scenario.linkLengths.size() != 2) {
        throw Error(QCoreApplication::translate(
            "TrialPlanner", "only planar 2-link arms have Cartesian line kinematics"));
    }
    m_kinematics = std::make_unique<TwoLinkKinematics>(scenario.linkLengths[0],
                                                       scenario.linkLengths[1], scenario.elbowSign);
    m_ruleGrid = torqueRuleGrid(*m_model, *m_kinematics, scenario.line);
}

TrialPlan TrialPlanner::plan(const Eigen::VectorXd &phiHat, TorqueRuleResult *ruleOut, bool gentle,
                             const Eigen::VectorXd *feedforwardPhi) const
{
    const Eigen::VectorXd &phiFeedforward = feedforwardPhi ? *feedforwardPhi : phiHat;
    clearUpperVectorState();
    TorqueRuleResult rule =
        shortestDuration(m_ruleGrid, phiHat, m_scenario.torqueLimits, m_scenario.planningFraction);
    rule.duration = std::max({rule.duration, m_shortestDuration, m_speedDuration});
    // A gentle trial moves the same path slower: every speed times gentleSpeed, every
    // acceleration times its square.
    if (gentle)
        rule.duration /= m_scenario.gentleSpeed;
    if (ruleOut)
        *ruleOut = rule;
    MotionTiming timing;
    timing.motionDuration = rule.duration;
    timing.restBefore = m_scenario.restBefore;
    timing.restAfter = m_scenario.restAfter;
    timing.samplePeriod = m_scenario.controller.samplePeriod;

    const auto sampled = [&](const MotionTiming &at) {
        return m_path ? planJointPath(*m_path, at) : planLine(*m_kinematics, m_scenario.line, at);
    };
    TrialPlan plan;
    plan.desired = sampled(timing);
    if (m_scenario.controller.feedforwardTime == FeedforwardTime::MidSample) {
        MotionTiming middle = timing;
        middle.sampleOffset = 0.5 * timing.samplePeriod;
        plan.feedforward = feedforwardTorque(*m_model, sampled(middle), phiFeedforward);
    } else {
        plan.feedforward = feedforwardTorque(*m_model, plan.desired, phiFeedforward);
    }
    plan.feedforwardParameters = phiFeedforward;
    plan.controller = m_scenario.controller;
    plan.torqueLimit = m_scenario.torqueLimits;
    plan.maxTrackingError = m_scenario.maxTrackingErrorDeg * M_PI / 180.0;
    plan.motionDuration = rule.duration;
    plan.positionLower = m_positionLower;
    plan.positionUpper = m_positionUpper;
    plan.velocityLimit = m_velocityLimit;
    return plan;
}

void checkScenarioFitsModel(const Scenario &scenario, const RobotModel &model)
{
    if (scenario.initialParameters.size() != model.parameterCount() ||
        scenario.torqueLimits.size() != model.dof() || scenario.controller.dof() != model.dof()) {
        throw Error(QCoreApplication::translate("CommissioningSession",
                                                "scenario does not fit the %1 model: it needs %2 "
                                                "parameters and %3 joint limits and gains")
                        .arg(model.id())
                        .arg(model.parameterCount())
                        .arg(model.dof()));
    }
}

} // namespace learnid
