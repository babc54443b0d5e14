#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <QString>
#include <limits>
#include <vector>

namespace learnid {

/// A link's 10 standard inertial parameters, pinocchio's order, about the link frame's origin
/// in link-frame coordinates: [m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]
/// [kg, kg m (3), kg m^2 (6)], I the rotational inertia about the frame origin (not the centre
/// of mass): I = I_c + m (|c|^2 E - c c^T).
using InertialParameters = Eigen::Matrix<double, 10, 1>;

/// The standard parameters of a body of mass m [kg] whose centre of mass is at c [m] and whose
/// rotational inertia about its centre of mass is inertiaAtCom [kg m^2], all in the link frame.
InertialParameters inertialParameters(double mass, const Eigen::Vector3d &c,
                                      const Eigen::Matrix3d &inertiaAtCom);
/// The rotational inertia about the frame origin held in pi (3 x 3, symmetric).
Eigen::Matrix3d rotationalInertia(const InertialParameters &pi);
/// pi (expressed in a frame B) expressed in another frame F whose pose in B is `pose`
/// (x_B = pose * x_F): how a fixed child's inertia is merged into its parent's.
InertialParameters transformedInertial(const InertialParameters &pi, const Eigen::Isometry3d &pose);

enum class JointType { Revolute, Prismatic };

/// A link fixed (directly or through other fixed joints) to a moving body and merged into it.
struct FixedLink
{
    QString name;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity(); ///< its frame in the body's frame
};

/// One moving joint of a serial chain and the rigid body it moves (its child link with every
/// link fixed to it merged in). Angles [rad] or positions [m] as the joint type says.
struct ChainJoint
{
    QString name;                                             ///< the URDF joint's name
    QString link;                                             ///< the child link's name
    JointType type = JointType::Revolute;                     ///< continuous joints are revolute
    Eigen::Isometry3d origin = Eigen::Isometry3d::Identity(); ///< in the previous joint's frame
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();          ///< unit, in this joint's frame
    double lower = -std::numeric_limits<double>::infinity();  ///< position limits
    double upper = std::numeric_limits<double>::infinity();
    double velocityLimit = std::numeric_limits<double>::infinity(); ///< [rad/s] or [m/s]
    double effortLimit = std::numeric_limits<double>::infinity();   ///< [N m] or [N]
    double damping = 0.0;  ///< the URDF's <dynamics damping> (viscous friction), 0 when absent
    double friction = 0.0; ///< the URDF's <dynamics friction> (Coulomb friction), 0 when absent
    /// Rotor inertia as the joint sees it [kg m^2 or kg] and torque offset [N m or N]: learnid's
    /// URDF extension element (UrdfExtension.h), 0 when absent.
    double armature = 0.0;
    double offset = 0.0;
    InertialParameters inertial = InertialParameters::Zero(); ///< the body it moves
    /// The axis-aligned box around the body's URDF geometry (its collision shapes, else its
    /// visual ones; links fixed to it included) in this joint's frame [m]; empty when it has
    /// none that could be read. The plausibility rule's bounding volume (Plausibility.h).
    Eigen::AlignedBox3d geometryBox;
    QString geometryDescription; ///< what geometryBox was made of, e.g. "2 cylinders, 1 sphere"
    std::vector<FixedLink> fixedLinks; ///< the links merged into the body, in the URDF's order
};

/// A serial chain from a base to a tip: the moving joints in order, each joint frame placed in
/// the previous one (the first in the base link's frame) by its origin, then moved by q about
/// or along its axis. Links fixed to the base do not move and are not part of it.
struct SerialChain
{
    QString name;     ///< the robot's name
    QString baseLink; ///< the link the chain starts from (fixed in the world)
    QString tipLink;
    std::vector<ChainJoint> joints;
    Eigen::Vector3d gravity{0.0, 0.0, -9.81}; ///< [m/s^2] in the base link's frame

    int dof() const { return int(joints.size()); }
};

} // namespace learnid
