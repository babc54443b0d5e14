// learnid-bench-zoo's command line (ZooOptions).
#include "zoo.h"

#include <QCommandLineParser>
#include <algorithm>

namespace learnid::bench {

ZooOptions parseZooOptions(const QCoreApplication &app)
{
    QCommandLineParser parser;
    parser.addHelpOption();
    const QCommandLineOption seedsOpt(QStringLiteral("seeds"), QStringLiteral("Seeds per robot."),
                                      QStringLiteral("n"), QStringLiteral("8"));
    const QCommandLineOption robotsOpt(QStringLiteral("robots"), QStringLiteral("Robots: abcd."),
                                       QStringLiteral("letters"), QStringLiteral("abcd"));
    const QCommandLineOption docsOpt(QStringLiteral("docs-gains"),
                                     QStringLiteral("docs/scenario.md's KUKA gains and path "
                                                    "instead of scenario --print's."));
    const QCommandLineOption limitOpt(QStringLiteral("limit"), QStringLiteral("Abort limit [deg]."),
                                      QStringLiteral("deg"), QStringLiteral("5"));
    const QCommandLineOption floorOpt(QStringLiteral("floor-trials"),
                                      QStringLiteral("Trials of the ideal-measurement session."),
                                      QStringLiteral("n"), QStringLiteral("12"));
    const QCommandLineOption verboseOpt(QStringLiteral("verbose"),
                                        QStringLiteral("Where each trial's largest error is."));
    const QCommandLineOption coulombOpt(QStringLiteral("coulomb-velocity"),
                                        QStringLiteral("Experiment: robot.jointTerms."
                                                       "coulombVelocity [rad/s]."),
                                        QStringLiteral("v"), QStringLiteral("0"));
    const QCommandLineOption truthOpt(QStringLiteral("start-at-truth"),
                                      QStringLiteral("Experiment: the first estimate is the "
                                                     "simulated robot's rigid-body truth."));
    const QCommandLineOption newestOpt(QStringLiteral("newest-only"),
                                       QStringLiteral("Experiment: estimator.accumulate false."));
    const QCommandLineOption rankOpt(QStringLiteral("rank-tolerance"),
                                     QStringLiteral("Experiment: estimator.rankTolerance."),
                                     QStringLiteral("r"), QStringLiteral("0"));
    const QCommandLineOption jointOpt(QStringLiteral("joint-levels"),
                                      QStringLiteral("Experiment: observability decided on rows "
                                                     "divided by each joint's torque level."));
    const QCommandLineOption stdOpt(QStringLiteral("max-relative-std"),
                                    QStringLiteral("Experiment: after a partial trial, learn no "
                                                   "direction whose relative std is above s."),
                                    QStringLiteral("s"), QStringLiteral("-1"));
    const QCommandLineOption repOpt(QStringLiteral("repetitions"),
                                    QStringLiteral("Runs per trial, averaged (estimator."
                                                   "repetitions; the CPU target is for 1)."),
                                    QStringLiteral("n"), QStringLiteral("1"));
    const QCommandLineOption armatureOpt(
        QStringLiteral("armature"),
        QStringLiteral("robot.jointTerms.armature on or off (the model learns each joint's "
                       "rotor inertia); default: the scenario's (the starter's on)."),
        QStringLiteral("on|off"));
    const QCommandLineOption sensorOpt(
        QStringLiteral("joint-torque-sensor"),
        QStringLiteral("estimator.jointTorqueSensor on or off; default: on for (d), whose "
                       "simulated sensor measures the spring behind the rotor."),
        QStringLiteral("on|off"));
    const QCommandLineOption lawRotorOpt(
        QStringLiteral("own-law-rotor"),
        QStringLiteral("Experiment: the own-law column's feedforward with (on, default) or "
                       "without (off) the rotor inertia."),
        QStringLiteral("on|off"), QStringLiteral("on"));
    const QCommandLineOption lagOpt(
        QStringLiteral("sensor-lag"),
        QStringLiteral("estimator.torqueSensorLag [s] for every robot; default: each robot's "
                       "own sensor lag (1 ms for (d), else 0)."),
        QStringLiteral("s"), QStringLiteral("-1"));
    parser.addOptions({seedsOpt, robotsOpt, docsOpt, limitOpt, floorOpt, verboseOpt, coulombOpt,
                       truthOpt, newestOpt, rankOpt, stdOpt, repOpt, jointOpt, armatureOpt,
                       sensorOpt, lawRotorOpt, lagOpt});
    parser.process(app);
    ZooOptions o;
    o.seeds = parser.value(seedsOpt).toInt();
    o.robots = parser.value(robotsOpt);
    o.docsGains = parser.isSet(docsOpt);
    o.limitDeg = parser.value(limitOpt).toDouble();
    o.floorTrials = parser.value(floorOpt).toInt();
    o.verbose = parser.isSet(verboseOpt);
    o.coulombVelocity = parser.value(coulombOpt).toDouble();
    o.startAtTruth = parser.isSet(truthOpt);
    o.accumulate = !parser.isSet(newestOpt);
    o.rankTolerance = parser.value(rankOpt).toDouble();
    o.maxRelativeStd = parser.value(stdOpt).toDouble();
    o.repetitions = std::max(1, parser.value(repOpt).toInt());
    o.jointLevels = parser.isSet(jointOpt);
    o.armature = parser.value(armatureOpt);
    o.jointTorqueSensor = parser.value(sensorOpt);
    o.ownLawRotor = parser.value(lawRotorOpt) != QStringLiteral("off");
    o.sensorLag = parser.value(lagOpt).toDouble();
    return o;
}

} // namespace learnid::bench
