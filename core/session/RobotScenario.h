#pragma once

#include "model/RobotModel.h"
#include "types/Scenario.h"

#include <QString>
#include <vector>

namespace learnid {

/// A scenario to start from when the technician picks a robot (the window's robot choice):
/// the paper scenario for "paper-2link"; for a URDF robot a path of three joint waypoints
/// around the middle of each joint's range (a fifth of the range, at most 0.5 rad or 0.05 m,
/// alternating in sign from joint to joint) and PID gains from the CAD model along it: each
/// joint's lightest inertia m = 1 / (M^-1)_jj, kp = max(m w^2 + max |dg_j/dq_j|, f / 0.05 rad)
/// with w = 25 rad/s and f the larger of the CAD's Coulomb friction and 1 % of the joint's
/// torque limit (what real geared joints lose), kd damping it 1.5 times critically together with
/// the joint's viscous friction, ki = 0.1 kp per second, the feedforward at the middle of each
/// sample (FeedforwardTime::MidSample); the planning fraction 1.5 times the
/// largest gravity share of a limit (30 to 80 %); the first trial gentle, at half speed
/// (path.gentleTrials 1, path.gentleSpeed 0.5); estimator.rankTolerance 1e-4 and
/// estimator.partialMaxRelativeStd 0.3; the torque limits and initial parameters left to
/// the robot (its URDF, its CAD base parameters) and, for the simulated robot, the CAD robot
/// perturbed by 30 % with a 20-bit encoder and 1 % torque noise. Throws Error when the model is
/// unknown or its URDF cannot be read.
/// With `payload` enabled (a payload section: the technician's prior), the design holds the arm
/// carrying the prior body; the friction rule adds, at each joint, half the prior's gravity
/// torque and what its weight adds with the centre of mass moved by a third of the bound's size
/// (an estimate may be off by that much); kd is sized for the geometric mean of the joint's
/// lightest and heaviest inertia along the path; the scenario gets that payload section. Throws
/// Error naming the payload key when the prior is refused or the link is unknown.
/// samplePeriod: the robot's clock [s]. The rule above assumes about 2 ms; where the pre-trial
/// check of the first trial (and of a full-speed one) with the CAD arm carrying the prior finds
/// the discrete closed loop unstable at this clock, the derivative gains of the joints whose
/// kd Ts / lightest inertia is largest are lowered step by step (x 0.8) until it is stable;
/// throws Error naming controller.samplePeriod when 20 steps do not do it, or for the paper's
/// arm at another clock than its scenario's 2 ms.
Scenario scenarioForRobot(const QString &modelId, const UrdfRobotSettings &urdf = {},
                          const PayloadSettings &payload = {}, double samplePeriod = 0.002);

/// The same for a robot named as a technician names it (`learnid-cli scenario --print --robot`):
/// "paper" or "paper-2link" (the paper scenario), a built-in URDF robot's id ("panda",
/// "puma560", "double-pendulum", "paper-2link-urdf"), or a URDF file (a name ending in ".urdf",
/// or any existing file), which becomes model "urdf" with the file's absolute path. Throws
/// Error naming the robot when it is none of these, or naming the file when it cannot be read
/// as a serial arm.
Scenario scenarioForRobotName(const QString &robot, const PayloadSettings &payload = {},
                              double samplePeriod = 0.002);

/// Why waypoints leave the robot's joint limits, or "" when they stay within: the first
/// offending value named by key (path.waypoints[i][j]), joint, value and limit (in degrees for
/// revolute joints). A model without limits (the paper's arm) accepts any waypoint.
QString waypointLimitError(const RobotModel &model, const std::vector<Eigen::VectorXd> &waypoints);

} // namespace learnid
