#pragma once

#include <Eigen/Core>
#include <QString>

namespace learnid {

/// A scenario's payload (docs/scenario.md, payload): the body fixed to one link that the
/// learning loop identifies with the arm's model held fixed (docs/payload.md). The fields of
/// model/PayloadPrior.h as the scenario file holds them; payloadPriorOf() makes the prior.
struct PayloadSettings
{
    bool enabled = false; ///< the scenario has a payload section: the session learns the payload
    QString link;         ///< the moving link it is fixed to; empty: the tip
    double mass = 0.0;    ///< the prior's mass [kg] > 0
    Eigen::Vector3d com = Eigen::Vector3d::Zero(); ///< the prior's centre of mass [m]
    /// The prior's inertia about its centre of mass, Ixx, Ixy, Iyy, Ixz, Iyz, Izz [kg m^2];
    /// empty: a uniform sphere (PayloadPrior::parameters()).
    Eigen::VectorXd inertia;
    double radius = 0.3; ///< the bounding sphere around the link frame's origin [m]
    Eigen::VectorXd box; ///< or the bounding box x0, y0, z0, x1, y1, z1 [m] (empty: the sphere)
    /// Trials of the same timed path run first without the payload, whose torque residual is
    /// taken out of every payload trial: a wrong arm model then biases the payload no more
    /// (docs/payload.md, "A wrong arm model and the baseline trial"). 0: none.
    int baselineTrials = 0;
    /// The gains of the baseline trials, one per joint, where they differ from the controller's
    /// (payload.baselineGains): gains that hold the payload may leave the bare arm's light wrist
    /// unstable (the PUMA 560 with 2 kg). Empty: the controller's gains.
    Eigen::VectorXd baselineKp, baselineKi, baselineKd;
};

/// The payload the simulated robot really carries (simulation.payload): a rigid body on the
/// scenario's payload link (the tip without a payload section), in that link's frame.
struct SimulatedPayload
{
    bool present = false;
    double mass = 0.0;                             ///< [kg] > 0
    Eigen::Vector3d com = Eigen::Vector3d::Zero(); ///< [m]
    /// About the centre of mass, Ixx, Ixy, Iyy, Ixz, Iyz, Izz [kg m^2]; zero: a point mass.
    Eigen::Matrix<double, 6, 1> inertia = Eigen::Matrix<double, 6, 1>::Zero();
};

} // namespace learnid
