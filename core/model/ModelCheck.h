#pragma once

#include "model/Plausibility.h"

#include <Eigen/Core>
#include <QStringList>

namespace learnid {

class ChainModel;
struct SerialChain;

/// What a URDF's own values would be wrong as a real robot's (docs/robots.md §7), one line per
/// problem naming the link or joint:
///  - a link that is not a real body: mass not positive, or a pseudo-inertia with a negative
///    eigenvalue (checkConsistency, tolerance 1e-12);
///  - a real body that is not plausible against cadPrior (checkPlausibility with `rule` and the
///    volumes linkVolumes() gives model's chain): a principal moment below the rule's share of
///    the CAD link's smallest, the triangle inequality with its margin broken, the centre of mass
///    outside the link's bounding volume;
///  - a joint's <dynamics damping> or <dynamics friction>, or its armature (learnid's extension),
///    negative.
/// chain: the URDF read with model's joints (same count; model.standardOf(chain) gives its
/// links); cadPrior: the CAD standard vector made real bodies (realBodyPrior of
/// model.cadStandard()). Empty when nothing is wrong.
QStringList modelProblems(const ChainModel &model, const SerialChain &chain,
                          const Eigen::VectorXd &cadPrior, const PlausibilityRule &rule = {});

/// modelProblems() of the model's own URDF (its CAD values against themselves made real
/// bodies): what to warn about when it serves as the model and prior.
QStringList modelWarnings(const ChainModel &model);

} // namespace learnid
