#pragma once

#include <Eigen/Core>
#include <QString>
#include <vector>

namespace learnid {

/// Which per-joint terms a chain model carries beyond the links' inertia (a scenario choice).
/// Joint j's torque gains  Ia_j qdd_j + fv_j qd_j + fc_j tanh(qd_j / coulombVelocity) + o_j:
/// rotor (armature) inertia as the joint sees it [kg m^2], viscous [N m s/rad] and Coulomb
/// [N m] friction, and a torque offset [N m]. tanh is the smooth sign: within about
/// +-coulombVelocity of standstill the friction torque passes linearly through zero (a real
/// joint sticks there; a smooth model keeps the simulator and the regressor well defined).
struct JointTerms
{
    bool armature = false;
    bool viscous = true;
    bool coulomb = true;
    bool offset = false;
    double coulombVelocity = 0.05; ///< [rad/s] or [m/s]

    int count() const { return int(armature) + int(viscous) + int(coulomb) + int(offset); }
};

/// A serial arm read from a URDF (docs/scenario.md, robot.urdf).
struct UrdfRobotSettings
{
    QString file;     ///< the URDF; a relative path is relative to the scenario file
    QString baseLink; ///< empty: the URDF's root link
    QString tipLink;  ///< empty: the one leaf below the base
    Eigen::Vector3d gravity{0.0, 0.0, -9.81}; ///< [m/s^2] in the base link's frame
    JointTerms jointTerms;
};

/// The production path of a trial (docs/scenario.md, path).
enum class PathKind {
    Line,      ///< the paper's Cartesian line (2-link arm only)
    Waypoints, ///< joint-space waypoints, quintic between them
    File,      ///< a recorded joint path, CSV t, q1..qn
};

struct JointPathSettings
{
    PathKind kind = PathKind::Line;
    std::vector<Eigen::VectorXd> waypoints; ///< [rad or m] (n each), kind Waypoints
    QString file; ///< kind File; a relative path is relative to the scenario file
    /// kind File: the file's samples as read with the scenario (io/PathCsv.h): times [s] (N)
    /// and joint positions (n x N).
    Eigen::VectorXd fileTimes;
    Eigen::MatrixXd fileAngles;
};

} // namespace learnid
