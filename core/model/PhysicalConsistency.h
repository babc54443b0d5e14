#pragma once

#include "model/Error.h"

#include <Eigen/Core>
#include <vector>

namespace learnid {

/// A link's 10 standard inertial parameters, pinocchio's order, about the link frame origin in
/// link-frame coordinates [kg, kg m, kg m^2]:
///   pi = [m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz],
/// I the rotational inertia about the origin, I = I_c + m (|c|^2 E - c c^T).
/// A robot's standard vector (p) holds `links` such blocks (link l at 10 l) followed by joint
/// terms (armature, friction, offsets: whatever the caller enabled).
using Vector10d = Eigen::Matrix<double, 10, 1>;
using Matrix10d = Eigen::Matrix<double, 10, 10>;

/// The pseudo-inertia J = [[Sigma, h], [h^T, m]] = integral of [r; 1][r; 1]^T dm (4 x 4), with
/// Sigma = 0.5 tr(I) E - I [kg m^2] and h = m c [kg m] (Wensing et al., IEEE RA-L 2018).
/// The link is physically consistent (a nonnegative mass density can have these moments)
/// exactly when J is positive semidefinite. Throws Error unless pi10 has 10 entries.
Eigen::Matrix4d pseudoInertia(const Eigen::Ref<const Eigen::VectorXd> &pi10);
/// The inverse of pseudoInertia(): I = tr(Sigma) E - Sigma, read from J's upper triangle.
/// Linear in J, so it also maps a derivative of J to the derivative of pi.
Vector10d inertialFromPseudoInertia(const Eigen::Matrix4d &j);

/// The verdict on one link's block.
struct LinkConsistency
{
    int link = 0;               ///< index of the link (its block starts at 10 link)
    double mass = 0.0;          ///< m [kg]
    double minEigenvalue = 0.0; ///< smallest eigenvalue of J [kg m^2 or kg, mixed]
    double maxEigenvalue = 0.0; ///< largest eigenvalue of J, the scale of the rule below
    /// m > 0 and lambda_min(J) >= -tolerance lambda_max(J): J positive semidefinite up to
    /// rounding of the size tolerance * lambda_max (the size of pi's own rounding, whose
    /// terms are up to m |c|^2 + m). A point mass (J of rank 1), a thin rod (rank 2) and a
    /// flat plate (rank 3) are consistent: they are real bodies idealised.
    bool consistent = false;
    /// Consistent but lambda_min(J) <= tolerance lambda_max(J): a point mass, rod or plate
    /// (a limit of solid bodies). The log-Cholesky parameters cannot represent it exactly.
    bool degenerate = false;
};

/// Every link's verdict (links entries, in order) for the first 10 links entries of standard
/// (p >= 10 links). tolerance: relative to lambda_max(J), e.g. 1e-12 (a few thousand machine
/// epsilons); the length unit is the metre (the eigenvalues mix kg and kg m^2).
/// Throws Error when standard is too short, tolerance is negative or an entry is not finite.
std::vector<LinkConsistency> checkConsistency(const Eigen::VectorXd &standard, int links,
                                              double tolerance);

/// The indices among nonnegativeIndices whose entry of standard is negative (< 0), in the
/// given order. Throws Error when an index is out of range or an entry is not finite.
std::vector<int> negativeJointTerms(const Eigen::VectorXd &standard,
                                    const std::vector<int> &nonnegativeIndices);

} // namespace learnid
