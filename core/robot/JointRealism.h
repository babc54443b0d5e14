#pragma once

#include <Eigen/Core>

namespace learnid {

/// What the simulated robot's joints have beyond the rigid-body model of its true parameters,
/// resolved to numbers per joint (session/ScenarioRobot.h makes it from a scenario's simulation
/// keys, docs/scenario.md). Empty vectors are off; every non-empty vector has one entry per
/// joint (n).
struct JointRealism
{
    /// Stribeck friction (on when staticFriction is non-empty): the joint friction is
    ///   tau_f = (Fc + (Fs - Fc) exp(-(v/vs)^2)) sign(v) + Fv v
    /// with stiction at v = 0 (RealisticPlant). Fc [N m] (coulomb), Fs >= Fc [N m], vs [rad/s].
    /// Fv stays in the rigid model; its smooth Coulomb term is taken out (linkParameters).
    Eigen::VectorXd coulomb;
    Eigen::VectorXd staticFriction;
    double stribeckVelocity = 0.1;
    /// The true parameters the rigid link dynamics use; empty: the robot's true parameters.
    /// With Stribeck friction: the true parameters without their Coulomb terms.
    Eigen::VectorXd linkParameters;
    /// Rotor inertia the model leaves out [kg m^2]: on a rigid joint it adds to M_jj, on an
    /// elastic one it is the motor side's inertia (then each entry > 0).
    Eigen::VectorXd armature;
    /// Elastic joints (on when stiffness is non-empty): motor and link joined by a spring
    /// tau_s = K (theta - q) + D (theta' - q') [N m/rad], [N m s/rad]; the torque sensor
    /// measures tau_s, the drive's torque acts on the motor.
    Eigen::VectorXd stiffness;
    Eigen::VectorXd damping;
    bool linkSideEncoder = false; ///< false: the encoder reads the motor angle theta
    Eigen::VectorXd sensorOffset; ///< added to every torque reading [N m]
    double sensorLag = 0.0;       ///< first-order lag of the torque reading [s]; 0: none

    bool stribeck() const { return staticFriction.size() > 0; }
    bool elastic() const { return stiffness.size() > 0; }
    /// Anything that needs RealisticPlant (a sensor offset or lag alone does not change motion,
    /// but the plant measures the torque too).
    bool any() const
    {
        return stribeck() || elastic() || armature.size() > 0 || sensorOffset.size() > 0 ||
               sensorLag > 0.0 || linkParameters.size() > 0;
    }
};

} // namespace learnid
