#pragma once

// What the built-in robot tests share: a built-in URDF read from the source tree, its standard
// parameters, random vectors, and the mass matrix and gravity torques summed over a robot's
// table of bodies (independent of learnid's dynamics).

#include "model/UrdfChain.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <QString>
#include <random>
#include <vector>

#ifndef LEARNID_ROBOTS_DIR
#error "tests/model/CMakeLists.txt defines LEARNID_ROBOTS_DIR"
#endif

namespace learnid::test {

inline SerialChain builtIn(const char *file)
{
    return readUrdfChain(QStringLiteral(LEARNID_ROBOTS_DIR "/") + QLatin1String(file));
}

inline Eigen::VectorXd standardParameters(const SerialChain &chain)
{
    Eigen::VectorXd pi(10 * chain.dof());
    for (int k = 0; k < chain.dof(); ++k)
        pi.segment<10>(10 * k) = chain.joints[size_t(k)].inertial;
    return pi;
}

inline Eigen::VectorXd randomVector(int size, std::mt19937 &random, double scale)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Eigen::VectorXd v(size);
    for (double &x : v)
        x = scale * unit(random);
    return v;
}

// A body of a table: mass, centre of mass and inertia about it, in the body's own frame.
struct TableBody
{
    double mass;
    Eigen::Vector3d c;
    Eigen::Matrix3d inertia;
};

// M = sum_k m_k Jv_k^T Jv_k + Jw_k^T R_k I_k R_k^T Jw_k and the holding torque against gravity
// g_j = sum_k z_j . ((c_k - o_j) x (-m_k g)), from a table alone: joint j turns about z of
// axes[j] through its origin, body k sits in bodies[k] (both in the base, n each).
inline void sumOverLinks(const std::vector<Eigen::Isometry3d> &axes,
                         const std::vector<Eigen::Isometry3d> &bodies,
                         const std::vector<TableBody> &table, Eigen::MatrixXd &mass,
                         Eigen::VectorXd &gravity)
{
    const int n = int(table.size());
    const Eigen::Vector3d g(0, 0, -9.81);
    mass.setZero(n, n);
    gravity.setZero(n);
    for (int k = 0; k < n; ++k) {
        const TableBody &b = table[size_t(k)];
        const Eigen::Vector3d c = bodies[size_t(k)] * b.c;
        const Eigen::Matrix3d rot = bodies[size_t(k)].linear();
        const Eigen::Matrix3d inertia = rot * b.inertia * rot.transpose();
        Eigen::MatrixXd jv = Eigen::MatrixXd::Zero(3, n), jw = Eigen::MatrixXd::Zero(3, n);
        for (int j = 0; j <= k; ++j) {
            const Eigen::Vector3d z = axes[size_t(j)].linear().col(2);
            const Eigen::Vector3d lever = c - axes[size_t(j)].translation();
            jw.col(j) = z;
            jv.col(j) = z.cross(lever);
            gravity[j] += z.dot(lever.cross(-b.mass * g));
        }
        mass += b.mass * jv.transpose() * jv + jw.transpose() * inertia * jw;
    }
}

} // namespace learnid::test
