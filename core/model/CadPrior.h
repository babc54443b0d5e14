#pragma once

#include <Eigen/Core>
#include <vector>

namespace learnid {

/// The CAD model as a prior for what data do not determine (docs/robots.md §6): the standard
/// vector cad (10 per link, then joint terms) with each link made a real body where it is not
/// one (published data are not always: a link whose mass never acts may have none): its
/// pseudo-inertia's eigenvalues floored at 1e-6 of its largest (and that at 1e-6). The prior
/// holds only what the data do not see, so the floor decides nothing the data decide. The joint
/// terms listed in nonnegative (friction, damping, armature) that the CAD model gives negative
/// (a model identified elsewhere may: ModelCheck warns of it) are set to 0, the nearest value
/// a real joint can have, so that the prior lies in the set the estimate is kept to.
Eigen::VectorXd realBodyPrior(const Eigen::VectorXd &cad, int links,
                              const std::vector<int> &nonnegative = {});

/// The diagonal of the prior's metric D in nearestConsistentEstimate(): each standard parameter
/// relative to its size in the prior, floored at 1e-3 of its link's largest entry (+1e-9), so a
/// zero prior entry does not pin the parameter.
Eigen::VectorXd priorScale(const Eigen::VectorXd &prior, int links);

} // namespace learnid
