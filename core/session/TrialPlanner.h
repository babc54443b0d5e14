#pragma once

#include "model/RobotModel.h"
#include "motion/JointPath.h"
#include "motion/Kinematics.h"
#include "motion/TorqueRule.h"
#include "types/Scenario.h"
#include "types/Trial.h"

#include <memory>

namespace learnid {

/// Plans the trials of a scenario: the path (the paper's Cartesian line, or a joint path of
/// waypoints or from a file), its duration by the torque rule with the current estimate
/// (re-planned before every trial), the sampled trajectory and the feedforward (at each
/// sample's instant, or the middle of its hold: controller.feedforwardTime). A path from a
/// file never runs faster than it was recorded: its duration is the longer of the recording's
/// and the torque rule's. A joint path of a robot with speed limits (URDF) also takes at least
/// the duration at which every joint's peak speed is 99 % of its limit.
class TrialPlanner
{
public:
    /// Throws Error when the line leaves the workspace or the model has no line kinematics, or
    /// when the joint path does not fit the model.
    TrialPlanner(const Scenario &scenario, std::shared_ptr<const RobotModel> model);

    const RobotModel &model() const { return *m_model; }
    /// The line's kinematics; only for a path of kind Line.
    const Kinematics &kinematics() const { return *m_kinematics; }
    /// The joint path; nullptr for a path of kind Line.
    const JointPath *jointPath() const { return m_path.get(); }

    /// Throws Error when the torque rule cannot be met with phiHat. gentle: a gentle trial
    /// (path.gentleTrials), its motion duration the rule's divided by path.gentleSpeed; rule
    /// then holds that duration. feedforwardPhi: the feedforward built with these parameters
    /// instead, on the same timed path (a reference run of the arm without its payload).
    TrialPlan plan(const Eigen::VectorXd &phiHat, TorqueRuleResult *rule = nullptr,
                   bool gentle = false, const Eigen::VectorXd *feedforwardPhi = nullptr) const;

private:
    Scenario m_scenario;
    std::shared_ptr<const RobotModel> m_model;
    std::unique_ptr<Kinematics> m_kinematics;
    std::unique_ptr<JointPath> m_path;
    double m_shortestDuration = 0.0; ///< [s] a recorded path's own duration
    Eigen::VectorXd m_positionLower, m_positionUpper, m_velocityLimit; ///< a URDF robot's
    /// [s] the shortest duration keeping every joint's peak speed within 99 % of its speed limit
    /// (0 without limits)
    double m_speedDuration = 0.0;
    TorqueRuleGrid m_ruleGrid; ///< the line's geometry, computed once
};

/// Throws Error unless the scenario has the model's parameter count of initial parameters and its
/// joint count of torque limits and gains (what a session needs before its first plan).
void checkScenarioFitsModel(const Scenario &scenario, const RobotModel &model);

} // namespace learnid
