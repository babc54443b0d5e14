#include "identify/LearningLaw.h"
#include "io/JsonReader.h"
#include "io/ScenarioFile.h"
#include "io/ScenarioPayload.h"
#include "io/ValueChecks.h"
#include "model/Error.h"
#include "model/ModelFactory.h"

#include <QCoreApplication>
#include <cmath>
#include <utility>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ScenarioFile)
};

QString key(const char *path)
{
    return QString::fromLatin1(path);
}

} // namespace

void validateJointGains(const Eigen::VectorXd &kp, const Eigen::VectorXd &ki,
                        const Eigen::VectorXd &kd, int dof, const QString &path)
{
    const QString perJoint = Text::tr("one per joint");
    checkVector(jsonKeyPath(path, key("kp")), kp, dof, perJoint, EntryRule::Positive);
    // Zero integral or derivative gain is a plain PD or PI loop; the pre-trial stability check
    // decides whether the loop is usable.
    checkVector(jsonKeyPath(path, key("ki")), ki, dof, perJoint, EntryRule::NonNegative);
    checkVector(jsonKeyPath(path, key("kd")), kd, dof, perJoint, EntryRule::NonNegative);
}

void validateControllerSettings(const ControllerSettings &c, int dof, const QString &path)
{
    checkInterval(jsonKeyPath(path, key("samplePeriod")), c.samplePeriod, 0.0,
                  scenarioLimits::maxSamplePeriod, Bounds::LeftOpen);
    validateJointGains(c.kp, c.ki, c.kd, dof, path);
    checkPositive(jsonKeyPath(path, key("lambda")), c.lambda);
}

namespace {

// A vector a URDF robot may leave empty (the robot's own values), or one entry per item.
void checkOptionalVector(const QString &path, const Eigen::VectorXd &v, int size,
                         const QString &what, EntryRule rule, bool mayBeEmpty)
{
    if (!(mayBeEmpty && v.size() == 0))
        checkVector(path, v, size, what, rule);
}

std::shared_ptr<const RobotModel> scenarioModel(const Scenario &s)
{
    const bool urdf = isUrdfModel(s.model);
    if (urdf) {
        if (s.model == QLatin1String("urdf") && s.urdf.file.isEmpty())
            throwAtKey(key("robot.urdf.file"), Text::tr("the \"urdf\" model needs a URDF file"));
        checkFinite(key("robot.urdf.gravity[0]"), s.urdf.gravity.x());
        checkFinite(key("robot.urdf.gravity[1]"), s.urdf.gravity.y());
        checkFinite(key("robot.urdf.gravity[2]"), s.urdf.gravity.z());
        checkPositive(key("robot.jointTerms.coulombVelocity"), s.urdf.jointTerms.coulombVelocity);
    }
    try {
        if (auto model = makeRobotModel(s.model, s.urdf))
            return model;
    } catch (const Error &e) {
        throwAtKey(key(s.model == QLatin1String("urdf") ? "robot.urdf.file" : "robot.model"),
                   e.message());
    }
    throwAtKey(key("robot.model"),
               Text::tr("unknown model \"%1\"; known models: %2")
                   .arg(s.model, knownRobotModels().join(QStringLiteral(", "))));
}

void validatePath(const Scenario &s, int n)
{
    if (isUrdfModel(s.model) && s.path.kind == PathKind::Line) {
        throwAtKey(key("path.kind"), Text::tr("the Cartesian line is the paper-2link arm's path; "
                                              "a URDF robot runs \"waypoints\" or \"file\""));
    }
    if (!isUrdfModel(s.model) && s.path.kind != PathKind::Line)
        throwAtKey(key("path.kind"), Text::tr("the paper-2link arm runs the Cartesian \"line\""));
    if (s.path.kind == PathKind::Line) {
        checkFinite(key("path.start[0]"), s.line.start.x());
        checkFinite(key("path.start[1]"), s.line.start.y());
        checkPositive(key("path.length"), s.line.length);
        checkFinite(key("path.directionDeg"), s.line.directionDeg);
    } else if (s.path.kind == PathKind::Waypoints) {
        if (s.path.waypoints.size() < 2) {
            throwAtKey(key("path.waypoints"),
                       Text::tr("needs at least 2 waypoints, got %1").arg(s.path.waypoints.size()));
        }
        for (size_t i = 0; i < s.path.waypoints.size(); ++i) {
            checkVector(jsonIndexPath(key("path.waypoints"), int(i)), s.path.waypoints[i], n,
                        Text::tr("one per joint of %1").arg(s.model), EntryRule::Finite);
        }
    } else if (s.path.file.isEmpty()) {
        throwAtKey(key("path.file"), Text::tr("a path of kind \"file\" needs a CSV file"));
    } else if (s.path.fileAngles.rows() != n) {
        throwAtKey(key("path.file"), Text::tr("%1 has %2 joint columns, %3 has %4 joints")
                                         .arg(s.path.file)
                                         .arg(s.path.fileAngles.rows())
                                         .arg(s.model)
                                         .arg(n));
    }
}

// The realistic-joint keys (docs/scenario.md, simulation); whether static friction reaches the
// true robot's Coulomb friction is checked when the simulated robot is made (simulatedJoints()).
void validateJointRealism(const SimulationSettings &sim, int n, const QString &perJoint)
{
    const auto optional = [&](const char *name, const Eigen::VectorXd &v, EntryRule rule) {
        checkOptionalVector(key(name), v, n, perJoint, rule, true);
    };
    optional("simulation.staticFriction", sim.staticFriction, EntryRule::NonNegative);
    checkFinite(key("simulation.staticFrictionRatio"), sim.staticFrictionRatio);
    if (sim.staticFrictionRatio != 0.0 && !(sim.staticFrictionRatio >= 1.0)) {
        throwAtKey(key("simulation.staticFrictionRatio"),
                   Text::tr("must be 0 (off) or at least 1 (static friction is not below "
                            "Coulomb friction), got %1")
                       .arg(describeNumber(sim.staticFrictionRatio)));
    }
    if (sim.staticFrictionRatio != 0.0 && sim.staticFriction.size() > 0) {
        throwAtKey(key("simulation.staticFrictionRatio"),
                   Text::tr("give static friction either as simulation.staticFriction or as "
                            "this ratio, not both"));
    }
    checkPositive(key("simulation.stribeckVelocity"), sim.stribeckVelocity);
    optional("simulation.armature", sim.armature, EntryRule::NonNegative);
    optional("simulation.armatureFactor", sim.armatureFactor, EntryRule::NonNegative);
    optional("simulation.jointStiffness", sim.jointStiffness, EntryRule::Positive);
    for (Eigen::Index j = 0; j < sim.jointStiffness.size(); ++j) {
        checkInterval(jsonIndexPath(key("simulation.jointStiffness"), int(j)),
                      sim.jointStiffness[j], 0.0, scenarioLimits::maxJointStiffness,
                      Bounds::LeftOpen);
    }
    optional("simulation.jointDamping", sim.jointDamping, EntryRule::NonNegative);
    if (sim.jointStiffness.size() == 0 && (sim.jointDamping.size() > 0 || !sim.linkSideEncoder)) {
        throwAtKey(key(sim.linkSideEncoder ? "simulation.jointDamping" : "simulation.encoderSide"),
                   Text::tr("applies to elastic joints only: give simulation.jointStiffness"));
    }
    optional("simulation.torqueSensorOffset", sim.torqueSensorOffset, EntryRule::Finite);
    checkInterval(key("simulation.torqueSensorLag"), sim.torqueSensorLag, 0.0,
                  scenarioLimits::maxTorqueSensorLag, Bounds::Closed);
}

} // namespace

void validateScenario(const Scenario &s)
{
    const auto model = scenarioModel(s);
    const bool urdf = isUrdfModel(s.model);
    const int n = model->dof();
    const int m = model->parameterCount();
    const QString perJoint = Text::tr("one per joint of %1").arg(s.model);
    const QString perParameter = Text::tr("one per parameter of %1").arg(s.model);

    if (!urdf) {
        checkVector(key("robot.linkLengths"), s.linkLengths, n, perJoint, EntryRule::Positive);
        if (s.elbowSign != 1 && s.elbowSign != -1)
            throwAtKey(key("robot.elbow"), Text::tr("must be 1 or -1, got %1").arg(s.elbowSign));
    }
    checkOptionalVector(key("robot.torqueLimits"), s.torqueLimits, n, perJoint, EntryRule::Positive,
                        urdf);
    checkOptionalVector(key("robot.initialParameters"), s.initialParameters, m, perParameter,
                        EntryRule::Finite, urdf);

    validatePath(s, n);
    checkInterval(key("path.restBefore"), s.restBefore, 0.0, scenarioLimits::maxRest,
                  Bounds::Closed);
    checkInterval(key("path.restAfter"), s.restAfter, 0.0, scenarioLimits::maxRest, Bounds::Closed);
    checkInterval(key("path.planningFraction"), s.planningFraction, 0.0, 1.0, Bounds::LeftOpen);
    checkIntegerRange(key("path.gentleTrials"), s.gentleTrials, 0, scenarioLimits::maxIterations);
    checkInterval(key("path.gentleSpeed"), s.gentleSpeed, 0.0, 1.0, Bounds::LeftOpen);
    if (s.payload.enabled) {
        checkIntegerRange(key("payload.baselineTrials"), s.payload.baselineTrials, 0,
                          scenarioLimits::maxIterations);
    }

    validateControllerSettings(s.controller, n, key("controller"));

    if (!knownLearningLaws().contains(s.law)) {
        throwAtKey(key("estimator.law"),
                   Text::tr("unknown learning law \"%1\"; known laws: %2")
                       .arg(s.law, knownLearningLaws().join(QStringLiteral(", "))));
    }
    checkPositive(key("estimator.rho"), s.estimator.rho);
    checkInterval(key("estimator.rankTolerance"), s.estimator.rankTolerance, 0.0, 1.0,
                  Bounds::Open);
    if (!std::isinf(s.estimator.partialMaxRelativeStd))
        checkPositive(key("estimator.partialMaxRelativeStd"), s.estimator.partialMaxRelativeStd);
    checkIntegerRange(key("estimator.iterations"), s.iterations, 1, scenarioLimits::maxIterations);
    checkIntegerRange(key("estimator.repetitions"), s.repetitions, 1,
                      scenarioLimits::maxRepetitions);
    checkInterval(key("estimator.torqueSensorLag"), s.estimator.torqueSensorLag, 0.0,
                  scenarioLimits::maxTorqueSensorLag, Bounds::Closed);
    for (const auto &[on, name] :
         {std::pair{s.estimator.jointTorqueSensor, "estimator.jointTorqueSensor"},
          std::pair{s.estimator.torqueSensorLag > 0.0, "estimator.torqueSensorLag"}}) {
        if (on && s.law != QLatin1String("improved")) {
            throwAtKey(key(name), Text::tr("needs the improved law (estimator.law \"improved\"), "
                                           "got \"%1\"")
                                      .arg(s.law));
        }
    }
    if (s.estimator.jointTorqueSensor && !(urdf && s.urdf.jointTerms.armature)) {
        throwAtKey(key("estimator.jointTorqueSensor"),
                   Text::tr("needs a URDF robot with robot.jointTerms.armature true: the rotor "
                            "inertia the sensor does not see is learned as the armature term"));
    }

    checkOptionalVector(key("simulation.trueParameters"), s.simulation.trueParameters, m,
                        perParameter, EntryRule::Finite, urdf);
    checkInterval(key("simulation.inertiaPerturbation"), s.simulation.inertiaPerturbation, 0.0,
                  scenarioLimits::maxInertiaPerturbation, Bounds::Closed);
    if (s.simulation.encoderCounts != 0 &&
        (s.simulation.encoderCounts < scenarioLimits::minEncoderCounts ||
         s.simulation.encoderCounts > scenarioLimits::maxEncoderCounts)) {
        throwAtKey(key("simulation.encoderCounts"),
                   Text::tr("must be 0 (an ideal encoder) or an integer from %1 to %2, got %3")
                       .arg(scenarioLimits::minEncoderCounts)
                       .arg(scenarioLimits::maxEncoderCounts)
                       .arg(s.simulation.encoderCounts));
    }
    checkInterval(key("simulation.torqueNoise"), s.simulation.torqueNoise, 0.0,
                  scenarioLimits::maxTorqueNoise, Bounds::Closed);
    if (s.simulation.seed > quint64(scenarioLimits::maxSeed)) {
        throwAtKey(key("simulation.seed"), Text::tr("must be %1, got %2")
                                               .arg(integerRangeText(0, scenarioLimits::maxSeed))
                                               .arg(s.simulation.seed));
    }
    checkIntegerRange(key("simulation.substeps"), s.simulation.substeps, 1,
                      scenarioLimits::maxSubsteps);
    validateJointRealism(s.simulation, n, perJoint);
    validateScenarioPayload(s, *model);

    checkPositive(key("safety.maxTrackingErrorDeg"), s.maxTrackingErrorDeg);
    checkNonNegative(key("safety.stabilityMargin"), s.stabilityMargin);
}

} // namespace learnid
