#include "io/ScenarioFile.h"

#include "io/AtomicFile.h"
#include "io/JsonReader.h"
#include "io/JsonTree.h"
#include "io/ScenarioChain.h"
#include "io/ScenarioPayload.h"
#include "model/Error.h"
#include "model/ModelFactory.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ScenarioFile)
};

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

void readRobot(JsonObjectReader r, Scenario &s)
{
    r.read(key("model"), s.model);
    r.read(key("linkLengths"), s.linkLengths);
    r.readInteger(key("elbow"), s.elbowSign, -1, 1, Text::tr("1 or -1"));
    r.read(key("torqueLimits"), s.torqueLimits);
    r.read(key("initialParameters"), s.initialParameters);
    if (auto section = r.optionalObject(key("urdf")))
        readUrdfRobot(*section, s.urdf);
    if (auto section = r.optionalObject(key("jointTerms")))
        readJointTerms(*section, s.urdf.jointTerms);
    r.rejectUnknownKeys();
}

void readPath(JsonObjectReader r, Scenario &s)
{
    readJointPath(r, s.path);
    Eigen::VectorXd start = s.line.start;
    r.read(key("start"), start);
    if (start.size() != 2) {
        throwAtKey(r.keyPath(key("start")),
                   Text::tr("must have 2 entries (x and y), got %1").arg(start.size()));
    }
    s.line.start = start;
    r.read(key("length"), s.line.length);
    r.read(key("directionDeg"), s.line.directionDeg);
    r.read(key("restBefore"), s.restBefore);
    r.read(key("restAfter"), s.restAfter);
    r.read(key("planningFraction"), s.planningFraction);
    r.readInteger(key("gentleTrials"), s.gentleTrials, 0, scenarioLimits::maxIterations);
    r.read(key("gentleSpeed"), s.gentleSpeed);
    r.rejectUnknownKeys();
}

const std::pair<FeedforwardTime, const char *> feedforwardTimes[] = {
    {FeedforwardTime::SampleInstant, "sample"}, {FeedforwardTime::MidSample, "midSample"}};

void readController(JsonObjectReader r, ControllerSettings &c)
{
    r.read(key("samplePeriod"), c.samplePeriod);
    r.read(key("kp"), c.kp);
    r.read(key("ki"), c.ki);
    r.read(key("kd"), c.kd);
    r.read(key("lambda"), c.lambda);
    const QJsonValue time = r.value(key("feedforwardTime"));
    if (!time.isUndefined())
        c.feedforwardTime = jsonEnum(time, r.keyPath(key("feedforwardTime")), feedforwardTimes);
    r.rejectUnknownKeys();
}

void readEstimator(JsonObjectReader r, Scenario &s)
{
    r.read(key("law"), s.law);
    r.read(key("rho"), s.estimator.rho);
    r.read(key("rankTolerance"), s.estimator.rankTolerance);
    r.read(key("partialMaxRelativeStd"), s.estimator.partialMaxRelativeStd);
    r.read(key("accumulate"), s.estimator.accumulate);
    r.read(key("jointTorqueSensor"), s.estimator.jointTorqueSensor);
    r.read(key("torqueSensorLag"), s.estimator.torqueSensorLag);
    r.readInteger(key("iterations"), s.iterations, 1, scenarioLimits::maxIterations);
    r.readInteger(key("repetitions"), s.repetitions, 1, scenarioLimits::maxRepetitions);
    r.rejectUnknownKeys();
}

const std::pair<bool, const char *> encoderSides[] = {{false, "motor"}, {true, "link"}};

void readSimulation(JsonObjectReader r, Scenario &s)
{
    r.read(key("trueParameters"), s.simulation.trueParameters);
    // Any integer here; validateScenario() names the allowed set (0 or 16 .. 2^31).
    r.readInteger(key("encoderCounts"), s.simulation.encoderCounts, -scenarioLimits::maxSeed,
                  scenarioLimits::maxSeed);
    r.read(key("torqueNoise"), s.simulation.torqueNoise);
    r.readInteger(key("seed"), s.simulation.seed, 0, scenarioLimits::maxSeed);
    r.readInteger(key("substeps"), s.simulation.substeps, 1, scenarioLimits::maxSubsteps);
    r.read(key("realUrdf"), s.simulation.realUrdf);
    r.read(key("inertiaPerturbation"), s.simulation.inertiaPerturbation);
    SimulationSettings &sim = s.simulation;
    r.read(key("staticFriction"), sim.staticFriction);
    r.read(key("staticFrictionRatio"), sim.staticFrictionRatio);
    r.read(key("stribeckVelocity"), sim.stribeckVelocity);
    r.read(key("armature"), sim.armature);
    r.read(key("armatureFactor"), sim.armatureFactor);
    r.read(key("jointStiffness"), sim.jointStiffness);
    r.read(key("jointDamping"), sim.jointDamping);
    const QJsonValue side = r.value(key("encoderSide"));
    if (!side.isUndefined())
        sim.linkSideEncoder = jsonEnum(side, r.keyPath(key("encoderSide")), encoderSides);
    r.read(key("torqueSensorOffset"), sim.torqueSensorOffset);
    r.read(key("torqueSensorLag"), sim.torqueSensorLag);
    if (auto payload = r.optionalObject(key("payload")))
        readSimulatedPayload(*payload, sim.payload);
    r.rejectUnknownKeys();
}

void readSafety(JsonObjectReader r, Scenario &s)
{
    r.read(key("maxTrackingErrorDeg"), s.maxTrackingErrorDeg);
    r.read(key("stabilityMargin"), s.stabilityMargin);
    r.rejectUnknownKeys();
}

Scenario readScenario(const QJsonObject &root)
{
    Scenario s;
    JsonObjectReader r(root, QString());
    const QJsonValue schema = r.value(key("schema"));
    if (!schema.isUndefined() &&
        jsonString(schema, key("schema")) != QLatin1String(scenarioSchema) &&
        jsonString(schema, key("schema")) != QLatin1String(scenarioSchemaVersion1)) {
        throwAtKey(key("schema"),
                   Text::tr("this version of learnid reads \"%1\" and \"%2\", got %3")
                       .arg(QLatin1String(scenarioSchema), QLatin1String(scenarioSchemaVersion1),
                            describeJsonValue(schema)));
    }
    if (auto section = r.optionalObject(key("robot")))
        readRobot(*section, s);
    if (auto section = r.optionalObject(key("path")))
        readPath(*section, s);
    if (auto section = r.optionalObject(key("controller")))
        readController(*section, s.controller);
    if (auto section = r.optionalObject(key("estimator")))
        readEstimator(*section, s);
    if (auto section = r.optionalObject(key("payload")))
        readPayloadSection(*section, s.payload);
    if (auto section = r.optionalObject(key("simulation")))
        readSimulation(*section, s);
    if (auto section = r.optionalObject(key("safety")))
        readSafety(*section, s);
    r.rejectUnknownKeys();
    if (isUrdfModel(s.model)) {
        // The paper arm's defaults do not fit another robot: what the file leaves out, the
        // robot gives when the session starts (withRobotDefaults).
        const auto has = [&root](const char *section, const char *name) {
            return root.value(key(section)).toObject().contains(key(name));
        };
        if (!has("robot", "torqueLimits"))
            s.torqueLimits.resize(0);
        if (!has("robot", "initialParameters"))
            s.initialParameters.resize(0);
        if (!has("simulation", "trueParameters"))
            s.simulation.trueParameters.resize(0);
    }
    return s;
}

// The realistic-joint keys, each only when it differs from its default (off).
void insertJointRealism(JsonTree &out, const SimulationSettings &sim)
{
    const SimulationSettings off;
    const auto vector = [&out](const char *name, const Eigen::VectorXd &v) {
        if (v.size() > 0)
            out.insert(key(name), JsonTree::numbers(v));
    };
    const auto number = [&out](const char *name, double value, double byDefault) {
        if (!(value == byDefault)) // NaN is written too (as null, which the reader refuses)
            out.insert(key(name), value);
    };
    vector("staticFriction", sim.staticFriction);
    number("staticFrictionRatio", sim.staticFrictionRatio, off.staticFrictionRatio);
    number("stribeckVelocity", sim.stribeckVelocity, off.stribeckVelocity);
    vector("armature", sim.armature);
    vector("armatureFactor", sim.armatureFactor);
    vector("jointStiffness", sim.jointStiffness);
    vector("jointDamping", sim.jointDamping);
    if (sim.linkSideEncoder != off.linkSideEncoder)
        out.insert(key("encoderSide"), enumName(sim.linkSideEncoder, encoderSides));
    vector("torqueSensorOffset", sim.torqueSensorOffset);
    number("torqueSensorLag", sim.torqueSensorLag, off.torqueSensorLag);
}

// Seeds above 2^53 are invalid; written as a double they read back as out of range.
JsonTree seedValue(quint64 seed)
{
    if (seed <= quint64(scenarioLimits::maxSeed))
        return JsonTree(qint64(seed));
    return JsonTree(double(seed));
}

} // namespace

QByteArray scenarioToJson(const Scenario &s)
{
    const bool urdf = isUrdfModel(s.model);
    JsonTree robot = JsonTree::object();
    robot.insert(key("model"), s.model);
    if (urdf) {
        robot.insert(key("urdf"), urdfRobotJson(s.urdf))
            .insert(key("jointTerms"), jointTermsJson(s.urdf.jointTerms));
    } else {
        robot.insert(key("linkLengths"), JsonTree::numbers(s.linkLengths))
            .insert(key("elbow"), s.elbowSign);
    }
    robot.insert(key("torqueLimits"), JsonTree::numbers(s.torqueLimits))
        .insert(key("initialParameters"), JsonTree::numbers(s.initialParameters));
    JsonTree path = JsonTree::object();
    insertJointPath(path, s.path);
    if (s.path.kind == PathKind::Line) {
        path.insert(key("start"), JsonTree::numbers(s.line.start))
            .insert(key("length"), s.line.length)
            .insert(key("directionDeg"), s.line.directionDeg);
    }
    path.insert(key("restBefore"), s.restBefore)
        .insert(key("restAfter"), s.restAfter)
        .insert(key("planningFraction"), s.planningFraction)
        .insert(key("gentleTrials"), s.gentleTrials)
        .insert(key("gentleSpeed"), s.gentleSpeed);
    JsonTree controller = JsonTree::object();
    controller.insert(key("samplePeriod"), s.controller.samplePeriod)
        .insert(key("kp"), JsonTree::numbers(s.controller.kp))
        .insert(key("ki"), JsonTree::numbers(s.controller.ki))
        .insert(key("kd"), JsonTree::numbers(s.controller.kd))
        .insert(key("lambda"), s.controller.lambda)
        .insert(key("feedforwardTime"), enumName(s.controller.feedforwardTime, feedforwardTimes));
    JsonTree estimator = JsonTree::object();
    estimator.insert(key("law"), s.law)
        .insert(key("rho"), s.estimator.rho)
        .insert(key("rankTolerance"), s.estimator.rankTolerance)
        .insert(key("accumulate"), s.estimator.accumulate)
        .insert(key("iterations"), s.iterations)
        .insert(key("repetitions"), s.repetitions);
    // Drive torques and no lag (the defaults) are the keys left out.
    if (s.estimator.jointTorqueSensor)
        estimator.insert(key("jointTorqueSensor"), true);
    if (s.estimator.torqueSensorLag != 0.0)
        estimator.insert(key("torqueSensorLag"), s.estimator.torqueSensorLag);
    // No limit (the default) is the key left out: JSON has no infinity.
    if (std::isfinite(s.estimator.partialMaxRelativeStd))
        estimator.insert(key("partialMaxRelativeStd"), s.estimator.partialMaxRelativeStd);
    JsonTree simulation = JsonTree::object();
    simulation.insert(key("trueParameters"), JsonTree::numbers(s.simulation.trueParameters))
        .insert(key("encoderCounts"), s.simulation.encoderCounts)
        .insert(key("torqueNoise"), s.simulation.torqueNoise)
        .insert(key("seed"), seedValue(s.simulation.seed))
        .insert(key("substeps"), s.simulation.substeps);
    if (urdf) {
        simulation.insert(key("realUrdf"), s.simulation.realUrdf)
            .insert(key("inertiaPerturbation"), s.simulation.inertiaPerturbation);
    }
    insertJointRealism(simulation, s.simulation);
    if (s.simulation.payload.present)
        simulation.insert(key("payload"), simulatedPayloadJson(s.simulation.payload));
    JsonTree safety = JsonTree::object();
    safety.insert(key("maxTrackingErrorDeg"), s.maxTrackingErrorDeg)
        .insert(key("stabilityMargin"), s.stabilityMargin);

    JsonTree root = JsonTree::object();
    root.insert(key("schema"), QString::fromLatin1(scenarioSchema))
        .insert(key("robot"), robot)
        .insert(key("path"), path)
        .insert(key("controller"), controller)
        .insert(key("estimator"), estimator);
    if (s.payload.enabled)
        root.insert(key("payload"), payloadSectionJson(s.payload));
    root.insert(key("simulation"), simulation).insert(key("safety"), safety);
    return root.toJson();
}

Scenario scenarioFromJson(const QByteArray &json, const QString &sourceName,
                          const QString &directory)
{
    const QJsonObject root = parseJsonObject(json, sourceName);
    try {
        Scenario s = readScenario(root);
        resolveScenarioPaths(s, directory.isEmpty() ? QDir::currentPath() : directory);
        loadJointPathFile(s.path);
        validateScenario(s);
        return s;
    } catch (const Error &e) {
        throw Error(Text::tr("%1: %2").arg(sourceName, e.message()));
    }
}

Scenario readScenarioFile(const QString &path)
{
    return scenarioFromJson(readFile(path), QDir::toNativeSeparators(path),
                            QFileInfo(path).absolutePath());
}

void writeScenarioFile(const QString &path, const Scenario &scenario)
{
    writeFileAtomically(path, scenarioToJson(scenario));
}

} // namespace learnid
