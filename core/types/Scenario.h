#pragma once

#include "types/CartesianLine.h"
#include "types/ChainSettings.h"
#include "types/ControllerSettings.h"
#include "types/EstimatorSettings.h"
#include "types/PayloadSettings.h"

#include <Eigen/Core>
#include <QString>

namespace learnid {

/// How the simulated robot behaves: its true parameters and its measurement. Not part of what
/// the technician asks for; a robot on the bus ignores it.
struct SimulationSettings
{
    Eigen::VectorXd trueParameters = Eigen::Vector3d(20, 5, 8); ///< phi of the simulated robot
    qint64 encoderCounts = 0; ///< counts per revolution; 0 = ideal
    double torqueNoise = 0.0; ///< torque noise standard deviation / limit
    quint64 seed = 1;
    int substeps = 10; ///< RK4 steps per sample
    /// A URDF robot's real robot (trueParameters empty): its own URDF with the same joints
    /// (realUrdf), or else the CAD model with every link's inertia and every friction value
    /// changed at random by up to +-inertiaPerturbation (a fraction), consistently (seed).
    QString realUrdf;
    double inertiaPerturbation = 0.0;
    // What real joints have beyond the rigid-body model (docs/scenario.md, simulation); empty
    // vectors and 0 are off. Vectors have one entry per joint.
    Eigen::VectorXd staticFriction;     ///< Stribeck: static friction Fs [N m]
    double staticFrictionRatio = 0.0;   ///< Stribeck: Fs = ratio * Coulomb friction (>= 1)
    double stribeckVelocity = 0.1;      ///< Stribeck velocity vs [rad/s]
    Eigen::VectorXd armature;           ///< rotor inertia the model leaves out [kg m^2]
    Eigen::VectorXd armatureFactor;     ///< ... as a factor of the link's inertia about its axis
    Eigen::VectorXd jointStiffness;     ///< elastic joints: spring stiffness [N m/rad]
    Eigen::VectorXd jointDamping;       ///< elastic joints: spring damping [N m s/rad]
    bool linkSideEncoder = true;        ///< elastic joints: the encoder on the link (else motor)
    Eigen::VectorXd torqueSensorOffset; ///< [N m]
    double torqueSensorLag = 0.0;       ///< first-order time constant [s]
    /// The payload the robot carries (none by default; with a payload section and none given,
    /// the prior body).
    SimulatedPayload payload;
};

/// A commissioning scenario: what the technician asks for (the robot, the path, the controller,
/// the estimator, the safety limits) and, apart, how the simulated robot behaves (simulation).
/// Defaults are the paper scenario (docs/design.md §2). Every key of the JSON form is
/// documented in docs/scenario.md (the JSON form is unchanged: the simulation keys stay where
/// they are).
struct Scenario
{
    // robot
    /// "paper-2link" (the paper's arm, closed form), "urdf" (any serial arm: urdf.file) or a
    /// built-in URDF robot ("paper-2link-urdf", "double-pendulum", "puma560", "panda"). For URDF
    /// robots, empty vectors take the robot's values when the session starts: torqueLimits the
    /// URDF's efforts, initialParameters the CAD model's base parameters.
    QString model = QStringLiteral("paper-2link");
    UrdfRobotSettings urdf;
    Eigen::VectorXd linkLengths = Eigen::Vector2d(0.75, 0.75);       ///< [m]
    int elbowSign = +1;                                              ///< +1: theta2 - theta1 > 0
    Eigen::VectorXd torqueLimits = Eigen::Vector2d(8.0, 4.0);        ///< [N m]
    Eigen::VectorXd initialParameters = Eigen::Vector3d(40, 20, 30); ///< phi_0
    // path
    JointPathSettings path; ///< the kind of path; Line: the paper's Cartesian line below
    CartesianLine line;
    double restBefore = 0.1;       ///< [s]
    double restAfter = 0.5;        ///< [s]
    double planningFraction = 0.8; ///< planned peak torque / limit
    /// Trials planned gently, slower than the torque rule allows, until the estimate has been
    /// learned this many times (docs/scenario.md, path.gentleTrials).
    int gentleTrials = 0;
    /// A gentle trial's speed as a fraction of the planned one: its motion duration is the torque
    /// rule's divided by this, so its inertial torque is gentleSpeed^2 of the planned one.
    double gentleSpeed = 0.5;
    // controller
    ControllerSettings controller;
    // estimator
    QString law = QStringLiteral("improved");
    EstimatorSettings estimator;
    int iterations = 6;  ///< learning trials of a session
    int repetitions = 1; ///< runs of each trial averaged before identification (improved only)
    // safety
    double maxTrackingErrorDeg = 1.0; ///< abort threshold during a trial [deg]
    double stabilityMargin = 0.0;     ///< required decay rate of the linearised loop [1/s]
    // the payload the session learns (docs/payload.md); off by default
    PayloadSettings payload;
    // the simulated robot
    SimulationSettings simulation;
};

} // namespace learnid
