#include "motion/JointPath.h"

#include "model/Error.h"

#include <Eigen/SparseCholesky>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(JointPath)
};

QString number(double v)
{
    return QString::number(v, 'g', 17);
}

// Index i of the interval [knots[i], knots[i+1]) holding u, clamped to the first and last.
Eigen::Index intervalOf(const double *knots, Eigen::Index count, double u)
{
    const Eigen::Index i = std::upper_bound(knots, knots + count, u) - knots - 1;
    return std::clamp<Eigen::Index>(i, 0, count - 2);
}

} // namespace

WaypointPath::WaypointPath(std::vector<Eigen::VectorXd> waypoints)
    : m_waypoints(std::move(waypoints))
{
    const int count = int(m_waypoints.size());
    if (count < 2) {
        throw Error(Text::tr("waypoint path: %1 waypoints; a path needs at least 2").arg(count));
    }
    const Eigen::Index n = m_waypoints.front().size();
    if (n < 1)
        throw Error(Text::tr("waypoint path: waypoint 0 has no joints"));
    for (int i = 0; i < count; ++i) {
        const Eigen::VectorXd &w = m_waypoints[std::size_t(i)];
        if (w.size() != n) {
            throw Error(Text::tr("waypoint path: waypoint %1 has %2 joints, waypoint 0 has %3")
                            .arg(i)
                            .arg(w.size())
                            .arg(n));
        }
        for (Eigen::Index j = 0; j < n; ++j) {
            if (!std::isfinite(w[j])) {
                throw Error(
                    Text::tr("waypoint path: waypoint %1: joint %2 is %3, not a finite angle")
                        .arg(i)
                        .arg(j + 1)
                        .arg(number(w[j])));
            }
        }
    }

    // Shares proportional to sqrt(largest displacement) (see the header).
    std::vector<double> root(std::size_t(count - 1));
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < m_waypoints.size(); ++i) {
        root[i] = std::sqrt((m_waypoints[i + 1] - m_waypoints[i]).cwiseAbs().maxCoeff());
        sum += root[i];
    }
    m_times.assign(std::size_t(count), 0.0);
    double cumulative = 0.0;
    for (std::size_t i = 0; i + 1 < m_waypoints.size(); ++i) {
        cumulative += root[i];
        m_times[i + 1] = i + 2 == m_waypoints.size() ? 1.0 : cumulative / sum;
        // A segment too short to tell from its neighbours in u would have no time to move in.
        if (root[i] == 0.0 || !(m_times[i + 1] > m_times[i])) {
            throw Error(
                Text::tr("waypoint path: waypoints %1 and %2 are equal or too close to tell "
                         "apart (largest joint difference %3 rad); the path stops at every "
                         "waypoint already, remove the repeat")
                    .arg(i)
                    .arg(i + 1)
                    .arg(number(root[i] * root[i])));
        }
    }
}

void WaypointPath::stateInto(double u, Eigen::Ref<Eigen::VectorXd> q,
                             Eigen::Ref<Eigen::VectorXd> dq_du,
                             Eigen::Ref<Eigen::VectorXd> d2q_du2) const
{
    u = std::clamp(u, 0.0, 1.0);
    const Eigen::Index i = intervalOf(m_times.data(), Eigen::Index(m_times.size()), u);
    const double width = m_times[std::size_t(i) + 1] - m_times[std::size_t(i)];
    // Local time v is exactly 0 at u_i and 1 at u = 1, so the waypoints are reached exactly.
    const double v = std::clamp((u - m_times[std::size_t(i)]) / width, 0.0, 1.0);
    const double v2 = v * v;
    const double s = v2 * v * (10.0 - 15.0 * v + 6.0 * v2);
    const double ds = 30.0 * v2 * (1.0 - 2.0 * v + v2) / width;
    const double d2s = 60.0 * v * (1.0 - 3.0 * v + 2.0 * v2) / (width * width);
    const Eigen::VectorXd &a = m_waypoints[std::size_t(i)];
    const Eigen::VectorXd &b = m_waypoints[std::size_t(i) + 1];
    q = (1.0 - s) * a + s * b;
    dq_du = ds * (b - a);
    d2q_du2 = d2s * (b - a);
}

SampledPath::SampledPath(Eigen::VectorXd t, Eigen::MatrixXd q)
    : m_q(std::move(q))
{
    const Eigen::Index count = t.size();
    if (m_q.cols() != count) {
        throw Error(Text::tr("recorded path: %1 sample times but %2 samples of the joints")
                        .arg(count)
                        .arg(m_q.cols()));
    }
    if (count < 4)
        throw Error(Text::tr("recorded path: %1 samples; a path needs at least 4").arg(count));
    if (m_q.rows() < 1)
        throw Error(Text::tr("recorded path: the samples have no joints"));
    for (Eigen::Index k = 0; k < count; ++k) {
        if (!std::isfinite(t[k])) {
            throw Error(Text::tr("recorded path: sample %1: the time is %2, not a finite number")
                            .arg(k)
                            .arg(number(t[k])));
        }
        if (k > 0 && !(t[k] > t[k - 1])) {
            throw Error(Text::tr("recorded path: sample %1: the time %2 s does not increase from "
                                 "sample %3 (%4 s)")
                            .arg(k)
                            .arg(number(t[k]))
                            .arg(k - 1)
                            .arg(number(t[k - 1])));
        }
        for (Eigen::Index j = 0; j < m_q.rows(); ++j) {
            if (!std::isfinite(m_q(j, k))) {
                throw Error(Text::tr("recorded path: sample %1: joint %2 is %3, not a finite angle")
                                .arg(k)
                                .arg(j + 1)
                                .arg(number(m_q(j, k))));
            }
        }
    }
    m_duration = t[count - 1] - t[0];
    m_u = (t.array() - t[0]) / m_duration;
    m_u[count - 1] = 1.0;

    // Moments M_k = d2q/du2 at the knots of the clamped cubic spline (q' = 0 at both ends):
    //   h_{k-1} M_{k-1} + 2 (h_{k-1} + h_k) M_k + h_k M_{k+1} = 6 (D_k - D_{k-1}),
    // D_k = (q_{k+1} - q_k) / h_k, with D_{-1} = D_{N-1} = 0 (the end velocities) and the
    // missing neighbours dropped. The matrix is tridiagonal, symmetric and diagonally dominant:
    // a sparse LDLT in natural order has no fill-in and solves all joints in O(N).
    const Eigen::VectorXd h = m_u.tail(count - 1) - m_u.head(count - 1);
    Eigen::MatrixXd slope(count + 1, m_q.rows()); // D_{k-1} in row k, zero at both ends
    slope.row(0).setZero();
    slope.row(count).setZero();
    for (Eigen::Index k = 0; k + 1 < count; ++k)
        slope.row(k + 1) = (m_q.col(k + 1) - m_q.col(k)).transpose() / h[k];
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(std::size_t(3 * count));
    for (Eigen::Index k = 0; k < count; ++k) {
        const double left = k > 0 ? h[k - 1] : 0.0;
        const double right = k + 1 < count ? h[k] : 0.0;
        entries.emplace_back(k, k, 2.0 * (left + right));
        if (k + 1 < count)
            entries.emplace_back(k + 1, k, right); // lower triangle only
    }
    Eigen::SparseMatrix<double> system(count, count);
    system.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
        ldlt(system);
    const Eigen::MatrixXd rhs =
        6.0 * (slope.bottomRows(count) - slope.topRows(count)); // D_k - D_{k-1}
    m_moment = ldlt.solve(rhs).transpose();
    if (ldlt.info() != Eigen::Success || !m_moment.allFinite())
        throw Error(Text::tr("recorded path: the sample times are too close to fit a spline"));
}

void SampledPath::stateInto(double u, Eigen::Ref<Eigen::VectorXd> q,
                            Eigen::Ref<Eigen::VectorXd> dq_du,
                            Eigen::Ref<Eigen::VectorXd> d2q_du2) const
{
    if (u < 0.0 || u > 1.0) { // at rest at an end
        q = m_q.col(u < 0.0 ? 0 : m_q.cols() - 1);
        dq_du.setZero();
        d2q_du2.setZero();
        return;
    }
    const Eigen::Index k = intervalOf(m_u.data(), m_u.size(), u);
    const double h = m_u[k + 1] - m_u[k];
    const double b = (u - m_u[k]) / h;
    const double a = 1.0 - b;
    const auto m0 = m_moment.col(k);
    const auto m1 = m_moment.col(k + 1);
    q = a * m_q.col(k) + b * m_q.col(k + 1) +
        (h * h / 6.0) * ((a * a * a - a) * m0 + (b * b * b - b) * m1);
    dq_du = (m_q.col(k + 1) - m_q.col(k)) / h +
            (h / 6.0) * ((1.0 - 3.0 * a * a) * m0 + (3.0 * b * b - 1.0) * m1);
    d2q_du2 = a * m0 + b * m1;
}

void jointPathStateInto(const JointPath &path, double T, double t, Eigen::Ref<Eigen::VectorXd> q,
                        Eigen::Ref<Eigen::VectorXd> qd, Eigen::Ref<Eigen::VectorXd> qdd)
{
    const Eigen::Index n = path.dof();
    if (!(T > 0.0) || !std::isfinite(T) || !std::isfinite(t) || q.size() != n || qd.size() != n ||
        qdd.size() != n) {
        throw Error(
            Text::tr("joint path: the duration must be positive and finite, the time finite, "
                     "and the state have %1 joints")
                .arg(n));
    }
    path.stateInto(t / T, q, qd, qdd);
    qd /= T;
    qdd /= T * T;
}

JointTrajectory planJointPath(const JointPath &path, const MotionTiming &timing)
{
    return sampleMotion(path.dof(), timing,
                        [&](double t, Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                            Eigen::Ref<Eigen::VectorXd> qdd) {
                            jointPathStateInto(path, timing.motionDuration, t, q, qd, qdd);
                        });
}

} // namespace learnid
