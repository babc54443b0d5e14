#pragma once

#include "model/ChainModel.h"

namespace learnid {

/// A simulated real robot from the CAD one: every link's mass, each coordinate of its centre of
/// mass and each principal moment of its inertia about the centre of mass multiplied by
/// 1 + fraction u (u uniform in [-1, 1], one draw each), and every nonzero joint term likewise.
/// The link stays a real body: a draw whose principal moments break the triangle inequality
/// (I1 <= I2 + I3) is drawn again. The principal axes stay. fraction in [0, 0.9]; seed: the
/// same seed gives the same robot. Returns the standard vector (ChainModel's layout).
Eigen::VectorXd perturbedStandard(const ChainModel &model, double fraction, quint64 seed);

} // namespace learnid
