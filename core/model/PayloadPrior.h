#pragma once

#include "model/BoundingVolume.h"
#include "model/SerialChain.h"
#include "types/PayloadSettings.h"

#include <Eigen/Core>
#include <QString>
#include <optional>

namespace learnid {

/// The sphere around the flange a payload's mass must lie in when the technician gives no
/// bound [m]: 0.3 m, a gripper with a part or a welding torch.
constexpr double defaultPayloadRadius = 0.3;
/// A prior without inertia is taken as a uniform solid sphere around the prior centre of mass
/// whose radius is this share of the bound's size (the sphere's radius, the box's smallest half
/// side), and at most a third of the distance to the bound's edge: a body of the bound's scale
/// (10 cm in the default sphere, 2/5 m r^2 = 0.012 kg m^2 for 3 kg). A point mass has a singular
/// pseudo-inertia, from which the log-det prior cannot measure, and a small sphere would hold a
/// real tool's inertia far too low where the data are weak.
constexpr double payloadPriorShare = 1.0 / 3.0;

/// Where the payload's mass may lie, in its link's frame [m]: a sphere (default: radius
/// defaultPayloadRadius around the link frame's origin, the flange) or an axis-aligned box.
struct PayloadBound
{
    bool box = false;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< sphere
    double radius = defaultPayloadRadius;             ///< sphere
    Eigen::Vector3d lower = Eigen::Vector3d::Zero();  ///< box
    Eigen::Vector3d upper = Eigen::Vector3d::Zero();  ///< box

    /// The ellipsoid the estimate's mass is held in (BoundingEllipsoid: an LMI on the
    /// pseudo-inertia): the sphere itself, or the box's circumscribed ellipsoid (semi-axes
    /// sqrt(3) times its half sizes: a body filling the box fits, its centre of mass is checked
    /// against the box itself).
    BoundingEllipsoid ellipsoid() const;
    /// c strictly inside the sphere or the box.
    bool contains(const Eigen::Vector3d &c) const;
    /// "sphere of radius 0.3 m around (0, 0, 0) m" or "box (x0, y0, z0) to (x1, y1, z1) m".
    QString describe() const;
};

/// What the technician knows of the payload before it is identified: the mass, where its
/// centre of mass is (default: the flange's origin) and, when known, its inertia about that
/// centre; all in the link frame. Directions the data do not see keep this body.
struct PayloadPrior
{
    double mass = 0.0;                             ///< [kg] > 0
    Eigen::Vector3d com = Eigen::Vector3d::Zero(); ///< [m]
    std::optional<Eigen::Matrix3d> inertiaAtCom;   ///< [kg m^2]; none: a point mass
    PayloadBound bound;

    /// The prior's 10 parameters, a real body inside the bound: the given inertia, or a solid
    /// sphere (payloadPriorShare) when none is given.
    InertialParameters parameters() const;
};

/// The names a payload's fields go by in messages: scenario keys by default, the CLI's options
/// when it checks its own.
struct PayloadFieldNames
{
    QString mass = QStringLiteral("payload.prior.mass");
    QString com = QStringLiteral("payload.prior.com");
    QString inertia = QStringLiteral("payload.prior.inertia");
    QString radius = QStringLiteral("payload.bound.radius");
    QString box = QStringLiteral("payload.bound.box");
    QString link = QStringLiteral("payload.link");
};

/// Throws Error naming the field when the prior is not usable: a mass that is not positive, a
/// value that is not finite (NaN), a radius that is not positive, a box whose upper corner is
/// not above its lower one, a centre of mass not strictly inside its own bound, an inertia that
/// is not a real body (principal moments positive, triangle inequalities) or whose body does
/// not fit in the bound.
void validatePayloadPrior(const PayloadPrior &prior, const PayloadFieldNames &names = {});

/// The prior a scenario's payload section describes (not checked: validatePayloadPrior()).
PayloadPrior payloadPriorOf(const PayloadSettings &settings);

/// The inertia about the centre of mass from its 6 entries Ixx, Ixy, Iyy, Ixz, Iyz, Izz.
Eigen::Matrix3d inertiaFromEntries(const Eigen::Ref<const Eigen::VectorXd> &entries);

/// The 10 parameters of the payload the simulated robot carries: simulation.payload, or the
/// prior body of the payload section when the simulation gives none, or zero (no payload).
InertialParameters simulatedPayloadParameters(const SimulatedPayload &simulated,
                                              const PayloadSettings &settings);

} // namespace learnid
