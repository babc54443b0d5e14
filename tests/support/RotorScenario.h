#pragma once

// Test support: a robot whose torque sensors sit behind its motors' rotors (elastic joints: the
// sensor measures the spring), for estimator.jointTorqueSensor; and how far a learned model's
// torque is from the motor's along a path.

#include "model/RobotModel.h"
#include "types/Scenario.h"
#include "types/Trial.h"

#include <Eigen/Core>
#include <cmath>

namespace learnid::test {

/// The double pendulum on a joint path, its model learning rotor inertia; the simulated robot
/// is the URDF's (the initial estimate is its rigid truth) with an ideal encoder and no noise.
inline Scenario rotorDoublePendulum()
{
    Scenario s;
    s.model = QStringLiteral("double-pendulum");
    s.urdf.jointTerms.armature = true;
    s.torqueLimits.resize(0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.simulation.encoderCounts = 0;
    s.simulation.torqueNoise = 0.0;
    s.path.kind = PathKind::Waypoints;
    s.path.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1.2, -0.8), Eigen::Vector2d(0, 0)};
    s.controller.kp = Eigen::Vector2d(20, 8);
    s.controller.ki = Eigen::Vector2d(2, 1);
    s.controller.kd = Eigen::Vector2d(1.5, 0.6);
    return s;
}

/// The same with elastic joints whose motors carry `factor` times their link's inertia about
/// the axis, the encoder on the motor: the torque sensor measures the spring, behind the rotor.
inline Scenario behindAJointSensor(double factor)
{
    Scenario s = rotorDoublePendulum();
    s.simulation.armatureFactor = Eigen::Vector2d::Constant(factor);
    s.simulation.jointStiffness = Eigen::Vector2d::Constant(2000.0);
    s.simulation.jointDamping = Eigen::Vector2d::Constant(1.0);
    s.simulation.linkSideEncoder = false;
    // Slow enough that the first trial, without the rotor, stays within the limit.
    s.planningFraction = 0.3;
    s.maxTrackingErrorDeg = 20.0;
    return s;
}

/// Relative RMS difference of the model's torque with phi on the plan's path against the
/// motor's true torque there: the rigid truth plus the rotor's Ia qdd.
inline double motorTorqueError(const RobotModel &model, const TrialPlan &plan,
                               const Eigen::VectorXd &phi, const Eigen::VectorXd &truth,
                               const Eigen::VectorXd &rotor)
{
    const JointTrajectory &d = plan.desired;
    Eigen::VectorXd learned(model.dof()), actual(model.dof());
    double diff = 0.0, level = 0.0;
    for (int k = 0; k < d.samples(); ++k) {
        model.inverseDynamics(d.q.col(k), d.qd.col(k), d.qdd.col(k), phi, learned);
        model.inverseDynamics(d.q.col(k), d.qd.col(k), d.qdd.col(k), truth, actual);
        actual += rotor.cwiseProduct(d.qdd.col(k));
        diff += (learned - actual).squaredNorm();
        level += actual.squaredNorm();
    }
    return std::sqrt(diff / level);
}

} // namespace learnid::test
