#pragma once

#include "model/RobotModel.h"
#include "robot/JointRealism.h"
#include "types/Scenario.h"

namespace learnid {

/// The simulated robot's joints beyond the rigid-body model, from the scenario's simulation keys
/// (docs/scenario.md) resolved against its true parameters (scenario.simulation.trueParameters,
/// filled in: withRobotDefaults()):
/// - Stribeck friction: Fc the true robot's Coulomb friction (0 where the model has none), Fs
///   staticFriction or staticFrictionRatio * Fc; the rigid dynamics then run on the true
///   parameters without their Coulomb terms;
/// - rotor inertia: armature plus armatureFactor times the link's own inertia about its joint
///   axis, from the robot's URDF (the CAD link, about the joint's origin);
/// - elastic joints, the torque sensor's offset and lag as given.
/// Throws Error naming the key when a value does not fit this robot: static friction below its
/// Coulomb friction, a factor without a URDF, elastic joints without rotor inertia.
JointRealism simulatedJoints(const Scenario &scenario, const RobotModel &model);

} // namespace learnid
