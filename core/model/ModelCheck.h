#pragma once

#include "model/PhysicalConsistency.h"
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

/// "link 3 (lwr_3_link)" and "joint 3 (lwr_a3_joint)": how the verdicts name a link or joint
/// (chain order, l from 0).
QString linkLabel(const SerialChain &chain, int l);
QString jointLabel(const SerialChain &chain, int j);

/// What is wrong with one link, one line per problem starting with `label` (linkLabel()): not a
/// real body (consistency: its mass, or no mass distribution has its inertia), else the
/// criteria of plausibility it fails (plausibilityProblems()). The words of modelProblems() and
/// EstimateConsistency::describe(). Empty for a plausible link.
QStringList linkProblems(const QString &label, const LinkConsistency &consistency,
                         const LinkPlausibility &plausibility,
                         const std::optional<BoundingEllipsoid> &volume,
                         const PlausibilityRule &rule = {});

/// What is wrong with a joint term `term` (a URDF element or a standard parameter's name) of
/// value: negative (friction and rotor inertia take energy), or strictly between 0 and the
/// rule's termFloor (the underflow of a positive parametrisation where 0 is meant). One line
/// starting with `label` (jointLabel()), empty when the value is fine.
QString jointTermProblem(const QString &label, const QString &term, double value,
                         const PlausibilityRule &rule = {});

/// modelProblems() of the model's own URDF (its CAD values against themselves made real
/// bodies): what to warn about when it serves as the model and prior.
QStringList modelWarnings(const ChainModel &model);

} // namespace learnid
