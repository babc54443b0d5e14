#pragma once

#include "motion/CartesianLine.h"
#include "types/JointTrajectory.h"

#include <Eigen/Core>
#include <vector>

namespace learnid {

/// A joint-space path over normalised time u in [0, 1], the geometry of a motion without its
/// duration (docs/design.md §7): any serial arm's production path. At motion duration T [s]
/// and time t = u T: q [rad], qd = dq/du / T [rad/s], qdd = d2q/du2 / T^2 [rad/s^2].
/// A path starts and ends at rest (dq/du = 0 at u = 0 and 1); outside [0, 1] it rests at its
/// end points with zero derivatives. A path does not change after construction.
class JointPath
{
public:
    virtual ~JointPath() = default;
    /// n, the number of joints.
    virtual int dof() const = 0;
    /// q [rad], dq/du [rad], d2q/du2 [rad] (n each) at u, into caller storage (no allocation).
    virtual void stateInto(double u, Eigen::Ref<Eigen::VectorXd> q,
                           Eigen::Ref<Eigen::VectorXd> dq_du,
                           Eigen::Ref<Eigen::VectorXd> d2q_du2) const = 0;
};

/// Point to point through waypoints w_0 .. w_m [rad] (n each), stopping at each one: segment i
/// runs q = (1 - s) w_i + s w_{i+1} with the quintic s(v) = 10v^3 - 15v^4 + 6v^5 over its local
/// time v in [0, 1], so velocity and acceleration are zero at every waypoint.
/// Segment i gets the share of [0, 1] proportional to sqrt(d_i), d_i = max_j |w_{i+1,j} - w_ij|:
/// a quintic segment's shortest time under an acceleration bound grows as sqrt(distance), so
/// with these shares every segment reaches the same peak |d2q/du2| on its largest joint
/// (10 / sqrt(3) (sum_i sqrt(d_i))^2), and no segment is slower than it needs to be.
/// Two equal consecutive waypoints (d_i = 0, or so small that the segment has no width in u) are
/// refused: a path stops at every waypoint already, and a zero-length segment would have no
/// share of u to dwell in.
class WaypointPath final : public JointPath
{
public:
    /// Throws Error naming the waypoint (index into waypoints) and joint (1-based) when there
    /// are fewer than 2 waypoints, sizes differ, an angle is not finite or two consecutive
    /// waypoints are equal.
    explicit WaypointPath(std::vector<Eigen::VectorXd> waypoints);

    int dof() const override { return int(m_waypoints.front().size()); }
    void stateInto(double u, Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> dq_du,
                   Eigen::Ref<Eigen::VectorXd> d2q_du2) const override;

    const std::vector<Eigen::VectorXd> &waypoints() const { return m_waypoints; }
    /// u at each waypoint: 0 = u_0 < u_1 < ... < u_m = 1 (m + 1 entries). The state at u_i is
    /// exactly w_i at rest.
    const std::vector<double> &waypointTimes() const { return m_times; }

private:
    std::vector<Eigen::VectorXd> m_waypoints;
    std::vector<double> m_times;
};

/// A recorded path: per joint the C2 cubic spline interpolating samples q (n x N) [rad] at
/// strictly increasing times t (N) [s], over u = (t - t_0) / (t_N-1 - t_0). The spline is
/// clamped: dq/du = 0 at both ends, so the path starts and ends at rest in velocity. Its
/// acceleration at the ends is the spline's (a recording that starts at rest has little); the
/// motion starts with that step in acceleration from the rest before it.
class SampledPath final : public JointPath
{
public:
    /// Throws Error naming the sample (0-based index) and joint (1-based) when t and q differ
    /// in length, N < 4, n < 1, a value is not finite or a time does not increase.
    SampledPath(Eigen::VectorXd t, Eigen::MatrixXd q);

    int dof() const override { return int(m_q.rows()); }
    void stateInto(double u, Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> dq_du,
                   Eigen::Ref<Eigen::VectorXd> d2q_du2) const override;

    /// t_N-1 - t_0 [s]: the duration the recording had.
    double nominalDuration() const { return m_duration; }
    int samples() const { return int(m_u.size()); }

private:
    Eigen::VectorXd m_u;      ///< knots, normalised sample times (N)
    Eigen::MatrixXd m_q;      ///< samples [rad] (n x N)
    Eigen::MatrixXd m_moment; ///< d2q/du2 at the knots (n x N)
    double m_duration = 0.0;
};

/// The state of path at time t of a motion of duration T [s]: q [rad], qd [rad/s], qdd [rad/s^2]
/// (n each, caller storage). t outside [0, T] rests at the path's ends. Throws Error when T is
/// not positive or the sizes are not path.dof().
void jointPathStateInto(const JointPath &path, double T, double t, Eigen::Ref<Eigen::VectorXd> q,
                        Eigen::Ref<Eigen::VectorXd> qd, Eigen::Ref<Eigen::VectorXd> qdd);

/// The sampled joint trajectory of the path with rests, as planLine() samples a line: samples
/// t_k = k Ts, k = 0 .. floor(total / Ts), total = restBefore + T + restAfter; the start is held
/// before the motion, the end after it, with zero qd and qdd there. Throws Error on invalid
/// timing (as planLine()).
JointTrajectory planJointPath(const JointPath &path, const MotionTiming &timing);

} // namespace learnid
