#pragma once

// learnid-bench-chain (issue 13): the KUKA LWR4+ scenario both halves of the benchmark share,
// and the two halves (chainaccuracy.cpp, chainspeed.cpp).

#include "model/RobotModel.h"
#include "types/Scenario.h"

#include <QString>

namespace learnid::bench {

/// The scenario and the commissioning settings chosen for it (the defaults; the command
/// line may change them). The robot, its perturbation, the measurement and the seeds are the
/// issue's and are not options.
struct ChainOptions
{
    QString urdf;     ///< the KUKA LWR4+ URDF
    int seeds = 8;    ///< seeds 1 .. seeds
    int repeats = 15; ///< timing repetitions (medians)
    bool accuracy = true;
    bool speed = true;
    // commissioning settings
    bool thereAndBack = true;       ///< the path's waypoints and back to the start
    double planningFraction = 0.25; ///< planned peak torque and speed / limit
    double lambda = 1500;           ///< derivative filter [rad/s]
    double rho = 120;               ///< estimator bandwidth [rad/s]
    double rankTolerance = 1e-4;
    int repetitions = 16;        ///< runs of each trial averaged before learning
    int substeps = 5;            ///< RK4 steps per sample of the simulated robot
    double samplePeriod = 0.002; ///< [s]
    bool midSample = true;       ///< feedforward at the middle of each sample's hold
    bool exactZeros = true;      ///< phi_0: the CAD's rounding residues (< 1e-12) made 0
    bool ideal = false;          ///< measurement without encoder steps and noise (diagnosis)
};

/// The scenario for one seed: the LWR4+ along the smooth waypoint path of
/// tst_chainsession (gains from the CAD inertia), the real robot the CAD one with every inertial
/// and friction value changed by up to +-30 % (seed), encoder 2^20 counts and torque noise 1 %
/// of the limits (seed); noisy = false (or o.ideal) leaves the measurement ideal. Robot defaults
/// (limits, phi_0, truth) not filled in: see resolvedChainScenario().
Scenario chainScenario(const ChainOptions &o, quint64 seed, bool noisy = true);

/// chainScenario() with the robot's defaults filled in (withRobotDefaults) and, with
/// o.exactZeros, phi_0's entries below 1e-12 in magnitude set to 0. Base parameters whose CAD
/// value cancels to a rounding residue (m cy3 + m cy4 = 2.8e-17, Ixx7 - Iyy7 = -2.1e-17) are 0
/// in the CAD robot, and the same torques to 1e-17; but the learning law scales each direction
/// by |phi_prev| (ObservableUpdate.h), and a direction of scale 1e-17 is never learned.
Scenario resolvedChainScenario(const ChainOptions &o, const RobotModel &model, quint64 seed,
                               bool noisy = true);

/// o with tst_chainsession's settings (kukaLwr4_learnsThePathTorquesOfSevenAxes): the path
/// a b c, planning fraction 0.3, lambda 1000, rho 40, rank tolerance 1e-3, 1 run per trial,
/// RK4 10 steps per sample, the feedforward at the sample instant, phi_0 as withRobotDefaults()
/// gives it.
ChainOptions testSettings(ChainOptions o);

/// Prints the accuracy tables; returns false when the sessions of the main table failed.
bool runChainAccuracy(const ChainOptions &o);
/// Prints the speed tables; returns false when a measurement failed.
bool runChainSpeed(const ChainOptions &o);
/// Prints the CPU time of 6-trial sessions (part of runChainSpeed).
void printChainSessions(const ChainOptions &o);

} // namespace learnid::bench
