#pragma once

#include "model/RobotModel.h"
#include "motion/Kinematics.h"
#include "motion/TorqueRule.h"
#include "types/Scenario.h"
#include "types/Trial.h"

#include <memory>

namespace learnid {

/// Plans the trials of a scenario: the line, its duration by the torque rule with the current
/// estimate (re-planned before every trial), the sampled trajectory and the feedforward.
class TrialPlanner
{
public:
    /// Throws Error when the path leaves the workspace or the model has no line kinematics.
    TrialPlanner(const Scenario &scenario, std::shared_ptr<const RobotModel> model);

    const RobotModel &model() const { return *m_model; }
    const Kinematics &kinematics() const { return *m_kinematics; }

    /// Throws Error when the torque rule cannot be met with phiHat.
    TrialPlan plan(const Eigen::VectorXd &phiHat, TorqueRuleResult *rule = nullptr) const;

private:
    Scenario m_scenario;
    std::shared_ptr<const RobotModel> m_model;
    std::unique_ptr<Kinematics> m_kinematics;
    TorqueRuleGrid m_ruleGrid; ///< the line's geometry, computed once
};

} // namespace learnid
