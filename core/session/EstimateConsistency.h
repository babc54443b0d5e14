#pragma once

#include "model/PhysicalConsistency.h"
#include "model/Plausibility.h"
#include "model/RobotModel.h"
#include "types/JointTrajectory.h"

#include <QString>
#include <vector>

namespace learnid {

class ChainModel;

/// Whether an estimate describes real bodies (docs/robots.md §6), for models with standard
/// parameters (URDF robots): the estimate's base parameters with the CAD model's values for
/// what they do not fix (each CAD link first made a real body where the published data are
/// not one), each link's mass positive and pseudo-inertia positive semidefinite,
/// friction and rotor inertia not negative. With the nearest consistent estimate: the
/// consistent standard parameters whose torques on the path are closest to the estimate's,
/// what the path does not see held near the CAD model.
struct EstimateConsistency
{
    bool applicable = false;            ///< false: the model has no standard parameters
    std::vector<LinkConsistency> links; ///< per link, in chain order
    std::vector<int> negativeTerms;     ///< standard indices of negative friction or inertia
    bool consistent = true;             ///< every link and term as it should be
    /// Per link, whether it is a body a robot could have (Plausibility.h) against the CAD body
    /// and in its bounding volume (volumes, linkVolumes()); whether all are and no joint term
    /// lies strictly between 0 and the rule's floor (tinyTerms: their standard indices).
    std::vector<LinkPlausibility> plausibility;
    std::vector<std::optional<BoundingEllipsoid>> volumes;
    std::vector<int> tinyTerms;
    bool plausible = true;
    Eigen::VectorXd standard; ///< the standard parameters judged
    Eigen::VectorXd nearest;  ///< base parameters of the nearest consistent estimate
    /// Standard parameters with those base parameters that are consistent (the witness; its
    /// unseen part near the CAD model); empty when phi is consistent or nothing was found.
    Eigen::VectorXd nearestStandard;
    double pathTorqueChangePercent = 0; ///< ||W_path (nearest - phi)|| / ||W_path phi|| * 100
    QString nearestError;               ///< why no nearest estimate could be found, or empty
    /// Per standard parameter: the share of its own direction the path observes (0 to 1, as
    /// LogFit::standardDetermined); at least 0.5 counts as determined by the trials, below as
    /// kept from the CAD model. Empty when not known (no path).
    std::vector<double> standardDetermined;

    /// The verdict first ("physically consistent and plausible: ...", "physically consistent
    /// (every link a real body) but not plausible", "not physically consistent"), then one line
    /// per problem in the words of modelProblems() ("link 3 (lwr_3_link): ...", "joint 2
    /// (name): fc₂ is ..."). Empty when not applicable.
    QStringList describe(const RobotModel &model) const;
};

/// The verdict on standard parameters themselves (links and joint terms of a URDF robot's
/// model, ChainModel's layout), without a nearest estimate.
EstimateConsistency checkStandardConsistency(const ChainModel &model,
                                             const Eigen::VectorXd &standard);

/// When checkEstimateConsistency() finds standard parameters for the estimate.
enum class NearestEstimate {
    WhenInconsistent, ///< only for an estimate that is not consistent (the pre-trial check)
    Always, ///< always: what accept, apply and export offer (the CAD completion of a consistent
            ///< estimate can still be a point mass or a needle)
};

/// Checks phi (base parameters of model) and, as `when` asks and a path is given, finds the
/// nearest plausible estimate: standard parameters whose torques on path (the desired
/// trajectory of a trial) are closest to phi's, each link kept near the CAD body by the
/// geometric prior of plausibleEstimate() (docs/robots.md §6: what the path sees follows phi).
/// Never throws: a failure is in nearestError.
EstimateConsistency
checkEstimateConsistency(const RobotModel &model, const Eigen::VectorXd &phi,
                         const JointTrajectory &path,
                         NearestEstimate when = NearestEstimate::WhenInconsistent);

} // namespace learnid
