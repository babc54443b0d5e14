#pragma once

#include "model/ModelFactory.h"
#include "types/Scenario.h"

#include <QCoreApplication>
#include <QString>

namespace learnid::bench {

struct ZooOptions
{
    int seeds = 8;
    bool docsGains = false; ///< docs/scenario.md's KUKA gains and path; else scenario --print's
    double limitDeg = 5.0;  ///< safety.maxTrackingErrorDeg
    int trials = 6;         ///< trials of a session (Run all)
    int floorTrials = 12;   ///< trials of the ideal-measurement session
    QString robots = QStringLiteral("abcd");
    bool verbose = false; ///< per trial: the joint and time of the largest error
    // Experiments on the floor (docs/benchmarks.md): the model's (and so the simulated robot's)
    // Coulomb velocity scale (0: the scenario's); the first estimate the true robot's.
    double coulombVelocity = 0.0;
    bool startAtTruth = false;
    bool accumulate = true;       ///< estimator.accumulate
    double rankTolerance = 0.0;   ///< estimator.rankTolerance (0: the scenario's)
    double maxRelativeStd = -1.0; ///< estimator.partialMaxRelativeStd (< 0: the scenario's)
    int repetitions = 1;          ///< estimator.repetitions: runs per trial, averaged
    bool jointLevels = false;     ///< EstimatorSettings::jointLevelObservability
    /// robot.jointTerms.armature (the model learns rotor inertia): "on", "off", else the
    /// scenario's (the starter's: on; docs/scenario.md's: off)
    QString armature;
    /// estimator.jointTorqueSensor: "on", "off", else on for (d) alone, whose simulated sensor
    /// measures the spring behind the rotor (the others' measure the drive's torque)
    QString jointTorqueSensor;
    bool ownLawRotor = true; ///< ownLawError(): the feedforward has the rotor inertia
    /// estimator.torqueSensorLag [s]; < 0: each robot's own sensor's (1 ms for (d), else 0), as
    /// its data sheet gives it
    double sensorLag = -1.0;
};

/// The options of learnid-bench-zoo's command line (exits with usage on an unknown one).
ZooOptions parseZooOptions(const QCoreApplication &app);

/// Robot (a) of issue 23 from the CAD URDF's text: link masses x0.8 or x1.25 and centres of
/// mass moved 2 cm in a direction drawn with `seed`, inertia x1.4, support::kRobotACoulomb, viscous
/// x1.5 (tests/support/ZooRobot.h).
QString zooRobotUrdf(const QString &cad, quint64 seed);

/// The session's scenario for robot 'a'..'d' (realistic joints drawn with `seed`): 2^20 counts
/// and 1 % torque noise, or an ideal encoder and no noise (`ideal`, the floor).
Scenario zooScenario(const ZooOptions &o, const QString &cadPath, const QString &realPath,
                     char robot, quint64 seed, bool ideal);

QString readText(const QString &path);

/// The max tracking error [deg] of a trial at the planned speed (no gentle planning) whose
/// feedforward is the simulated robot's own law on the desired path: its rigid-body truth,
/// its rotor inertia, and Stribeck friction with the exact sign of the desired velocity. No
/// identified model can give the controller more. Elastic joints: their rigid law (the spring's
/// own dynamics left out). rotor false: without the rotor inertia. Infinite when the trial
/// stops at the tracking limit.
double ownLawError(const Scenario &scenario, bool rotor = true);

} // namespace learnid::bench
