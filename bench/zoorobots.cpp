// learnid-bench-zoo: the simulated real KUKA LWR4+ robots of issue 23 (robot (a) and its
// realistic-joint variants), built from the CAD URDF's text with a seed.
#include "zoo.h"

#include "../tests/support/ZooRobot.h"

#include "io/ScenarioFile.h"
#include "session/RobotScenario.h"

#include <QFile>
#include <QRegularExpression>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>

namespace learnid::bench {

QString zooRobotUrdf(const QString &cad, quint64 seed)
{
    std::mt19937_64 rng(seed * 7919u + 17u);
    std::bernoulli_distribution heavier(0.5);
    std::normal_distribution<double> gauss;
    // Link masses x0.8 or x1.25, drawn per link (the base's block too, which never moves);
    // centres of mass moved 2 cm in a direction drawn uniformly on the sphere.
    return support::robotAUrdf(
        cad, [&](int) { return heavier(rng) ? 1.25 : 0.8; },
        [&](int) {
            std::array<double, 3> d = {gauss(rng), gauss(rng), gauss(rng)};
            const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (double &v : d)
                v *= 0.02 / norm;
            return d;
        });
}

Scenario zooScenario(const ZooOptions &o, const QString &cadPath, const QString &realPath,
                     char robot, quint64 seed, bool ideal)
{
    Scenario s = o.docsGains ? support::docsLwrScenario(cadPath) : scenarioForRobotName(cadPath);
    s.maxTrackingErrorDeg = o.limitDeg;
    s.estimator.accumulate = o.accumulate;
    if (o.rankTolerance > 0)
        s.estimator.rankTolerance = o.rankTolerance;
    if (o.maxRelativeStd >= 0)
        s.estimator.partialMaxRelativeStd =
            o.maxRelativeStd > 0 ? o.maxRelativeStd : std::numeric_limits<double>::infinity();
    s.repetitions = o.repetitions;
    s.estimator.jointLevelObservability = o.jointLevels;
    if (o.armature == QLatin1String("on") || o.armature == QLatin1String("off"))
        s.urdf.jointTerms.armature = o.armature == QLatin1String("on");
    if (o.coulombVelocity > 0)
        s.urdf.jointTerms.coulombVelocity = o.coulombVelocity;
    SimulationSettings &sim = s.simulation;
    sim = SimulationSettings{};
    sim.trueParameters.resize(0);
    sim.realUrdf = realPath;
    sim.encoderCounts = ideal ? 0 : (qint64(1) << 20);
    sim.torqueNoise = ideal ? 0.0 : 0.01;
    sim.seed = seed;
    std::mt19937_64 rng(seed * 104729u + quint64(robot));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int n = 7;
    if (robot == 'b')
        sim.staticFrictionRatio = 1.5;
    if (robot == 'c') {
        sim.armatureFactor.resize(n);
        for (int j = 0; j < n; ++j)
            sim.armatureFactor[j] = 0.5 + 1.5 * unit(rng);
    }
    if (robot == 'd') {
        sim.armatureFactor = Eigen::VectorXd::Constant(n, 1.0);
        sim.jointStiffness.resize(n);
        for (int j = 0; j < n; ++j)
            sim.jointStiffness[j] = 5000.0 + 10000.0 * unit(rng);
        sim.torqueSensorLag = 0.001;
    }
    s.estimator.torqueSensorLag = o.sensorLag >= 0 ? o.sensorLag : sim.torqueSensorLag;
    // (d)'s sensor measures the spring, behind the rotor: a joint torque sensor.
    s.estimator.jointTorqueSensor = o.jointTorqueSensor.isEmpty()
                                        ? robot == 'd' && s.urdf.jointTerms.armature
                                        : o.jointTorqueSensor == QLatin1String("on");
    return s;
}

QString readText(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        throw std::runtime_error(qPrintable(QStringLiteral("cannot read %1").arg(path)));
    return QString::fromUtf8(f.readAll());
}

} // namespace learnid::bench
