#pragma once

#include "model/BoundingVolume.h"
#include "model/SerialChain.h"

#include <Eigen/Core>
#include <QString>
#include <optional>
#include <vector>

namespace learnid {

/// When a consistent link is also a body a robot could have (docs/robots.md §6). Consistency
/// (m > 0, pseudo-inertia positive semidefinite) admits point masses, needles and plates; a
/// least-squares fit with weak data slides onto them. The rule compares with the CAD body.
struct PlausibilityRule
{
    /// Each principal moment of inertia about the centre of mass at least this share of the
    /// CAD link's smallest one.
    double minMomentShare = 0.05;
    /// The triangle inequalities with a margin: I1 + I2 >= (1 + margin) I3 for the principal
    /// moments I1 <= I2 <= I3 (0: a flat plate passes; a real link has thickness).
    double triangleMargin = 0.02;
    /// A friction, damping or rotor inertia is either 0 or at least this [SI units]: values in
    /// between are the underflow of a positive parametrisation where 0 is meant.
    double termFloor = 1e-6;
};

/// The verdict on one link of a standard vector.
struct LinkPlausibility
{
    int link = 0;
    double mass = 0.0; ///< [kg]
    Eigen::Vector3d moments =
        Eigen::Vector3d::Zero();    ///< principal, about the CoM, ascending [kg m^2]
    double cadSmallestMoment = 0.0; ///< the CAD link's smallest [kg m^2]
    double triangleRatio = 0.0;     ///< (I1 + I2) / I3 (infinite when I3 = 0)
    bool hasVolume = false;
    double comDistance = 0.0; ///< |A (c - centre)|^2 of the bounding ellipsoid: <= 1 inside
    double fitShare = 0.0;    ///< BoundingEllipsoid::fitShare(): >= 0 when the mass can fit
    bool momentsOk = false;
    bool triangleOk = false;
    bool volumeOk = true;   ///< the centre of mass inside the volume (true without one)
    bool plausible = false; ///< mass > 0 and all three
};

/// Each link's bounding volume for a chain (links entries): the ellipsoid of its geometry
/// (ellipsoidAroundBox of ChainJoint::geometryBox) where there is one and the CAD body fits in
/// it (fitShare > 0), else the CAD body's inertia ellipsoid (ellipsoidFromInertia with
/// cadVolumeMargin); no volume for a CAD link without mass. cadPrior: the CAD standard vector made
/// real bodies (realBodyPrior).
std::vector<std::optional<BoundingEllipsoid>> linkVolumes(const SerialChain &chain,
                                                          const Eigen::VectorXd &cadPrior);

/// The verdict per link (links entries) for standard (10 per link first), against cadPrior's
/// links (same layout) and the volumes (links entries, or empty for none). Throws Error when a
/// size does not match or an entry is not finite.
std::vector<LinkPlausibility>
checkPlausibility(const Eigen::VectorXd &standard, const Eigen::VectorXd &cadPrior, int links,
                  const std::vector<std::optional<BoundingEllipsoid>> &volumes,
                  const PlausibilityRule &rule = {});

/// What is wrong with a link that is not plausible, one clause per criterion it fails, worded
/// for "link 3 (name): <clause>" (modelProblems(), EstimateConsistency::describe()): "its
/// smallest principal moment of inertia about the centre of mass, 5e-14 kg m^2, is below 5 % of
/// the CAD link's smallest (0.004 kg m^2): a point mass or a needle, not a link". volume: the
/// link's bounding volume, named in the clause on the centre of mass (none: not named). Empty for
/// a plausible link.
QStringList plausibilityProblems(const LinkPlausibility &verdict,
                                 const std::optional<BoundingEllipsoid> &volume = std::nullopt,
                                 const PlausibilityRule &rule = {});

/// plausibilityProblems() without the volume's name, joined by "; ".
QString plausibilityProblem(const LinkPlausibility &verdict, const PlausibilityRule &rule = {});

/// The indices among nonnegativeIndices whose entry lies strictly between 0 and rule.termFloor.
std::vector<int> tinyJointTerms(const Eigen::VectorXd &standard,
                                const std::vector<int> &nonnegativeIndices,
                                const PlausibilityRule &rule = {});

} // namespace learnid
