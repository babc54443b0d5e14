#pragma once

// Small products of ChainDynamics' recursions, written out and always inlined: GCC otherwise
// calls Eigen's fixed-size 3 x 3 products out of line there, which cost a quarter of their time
// (learnid-bench-chain, docs/benchmarks.md). Internal to core/model.

#include <Eigen/Core>
#include <QtGlobal>

namespace learnid::chainproducts {

/// r v.
Q_ALWAYS_INLINE Eigen::Vector3d times(const Eigen::Matrix3d &r, const Eigen::Vector3d &v)
{
    return r.col(0) * v.x() + r.col(1) * v.y() + r.col(2) * v.z();
}

/// The symmetric inertia [Ixx Ixy Ixz; Ixy Iyy Iyz; Ixz Iyz Izz] of pi[4..9].
inline Eigen::Matrix3d inertiaOf(const double *pi)
{
    Eigen::Matrix3d i;
    i << pi[4], pi[5], pi[7], //
        pi[5], pi[6], pi[8],  //
        pi[7], pi[8], pi[9];
    return i;
}

} // namespace learnid::chainproducts
