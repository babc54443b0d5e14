// Issue-13 benchmark, any serial arm: the simulated KUKA LWR4+ (7 axes, gravity, friction) in
// one program run. Accuracy (chainaccuracy.cpp): whole commissioning sessions on the CAD robot
// perturbed by up to 30 % (8 seeds, encoder 2^20 counts, 1 % torque noise): tracking error,
// path-torque error and physical consistency after 3 learnings. Speed (chainspeed.cpp,
// chainsessions.cpp): inverse dynamics against Orocos KDL, the regressors, 6-trial sessions and
// one update over 10^5 samples. Prints Markdown. Usage: see usage().
#include "chain.h"

#include "model/Error.h"
#include "session/ScenarioRobot.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#ifndef LEARNID_SHARED_DATA
#error "bench/CMakeLists.txt defines LEARNID_SHARED_DATA"
#endif

namespace learnid::bench {

Scenario chainScenario(const ChainOptions &o, quint64 seed, bool noisy)
{
    Scenario s;
    s.model = QStringLiteral("urdf");
    s.urdf.file = o.urdf;
    s.torqueLimits.resize(0);              // the URDF's efforts
    s.initialParameters.resize(0);         // the CAD model
    s.simulation.trueParameters.resize(0); // the CAD model perturbed
    s.path.kind = PathKind::Waypoints;
    const Eigen::VectorXd a = (Eigen::VectorXd(7) << 0, 0.3, 0, -1.2, 0, 0.5, 0).finished();
    const Eigen::VectorXd b =
        (Eigen::VectorXd(7) << 0.8, 0.8, 0.5, -0.6, 0.6, -0.4, 0.9).finished();
    const Eigen::VectorXd c =
        (Eigen::VectorXd(7) << -0.4, 0.5, -0.5, -1.4, -0.5, 0.6, -0.7).finished();
    s.path.waypoints = {a, b, c};
    if (o.thereAndBack)
        s.path.waypoints.insert(s.path.waypoints.end(), {b, a});
    s.planningFraction = o.planningFraction;
    // PID from the CAD inertia along the path, about 15 rad/s, damped (tst_chainsession).
    s.controller.samplePeriod = o.samplePeriod;
    s.controller.kp = (Eigen::VectorXd(7) << 340, 600, 100, 140, 15, 14, 11).finished();
    s.controller.ki = s.controller.kp / 10.0;
    s.controller.kd = (Eigen::VectorXd(7) << 45, 80, 14, 19, 2, 1.9, 1.5).finished();
    s.controller.lambda = o.lambda;
    s.controller.feedforwardTime =
        o.midSample ? FeedforwardTime::MidSample : FeedforwardTime::SampleInstant;
    s.estimator.rho = o.rho;
    s.estimator.rankTolerance = o.rankTolerance;
    s.repetitions = o.repetitions;
    s.maxTrackingErrorDeg = 5;
    s.simulation.inertiaPerturbation = 0.3;
    s.simulation.seed = seed;
    s.simulation.substeps = o.substeps;
    if (noisy && !o.ideal) {
        s.simulation.encoderCounts = qint64(1) << 20;
        s.simulation.torqueNoise = 0.01;
    }
    return s;
}

Scenario resolvedChainScenario(const ChainOptions &o, const RobotModel &model, quint64 seed,
                               bool noisy)
{
    Scenario s = withRobotDefaults(chainScenario(o, seed, noisy), model);
    if (o.exactZeros) {
        for (double &x : s.initialParameters)
            x = std::abs(x) < 1e-12 ? 0.0 : x;
    }
    return s;
}

ChainOptions testSettings(ChainOptions o)
{
    o.thereAndBack = false;
    o.planningFraction = 0.3;
    o.lambda = 1000;
    o.rho = 40;
    o.rankTolerance = 1e-3;
    o.repetitions = 1;
    o.substeps = 10;
    o.midSample = false;
    o.exactZeros = false;
    return o;
}

} // namespace learnid::bench

using namespace learnid;

namespace {

// bad: the argument refused, or nullptr for --help.
int usage(const char *bad)
{
    if (bad)
        std::fprintf(stderr, "unknown or incomplete argument %s\n", bad);
    std::fprintf(bad ? stderr : stdout,
                 "usage: learnid-bench-chain [--urdf FILE] [--seeds N] [--repeats N]\n"
                 "       [--accuracy-only | --speed-only]\n"
                 "  commissioning settings (defaults: the chosen ones, docs/benchmarks.md):\n"
                 "       [--one-way] [--planning-fraction F] [--lambda L] [--rho R]\n"
                 "       [--rank-tolerance T] [--repetitions N] [--substeps N]\n"
                 "       [--sample-period MS] [--feedforward-at-sample]\n"
                 "       [--cad-residues] [--ideal-measurement]\n");
    return bad ? 2 : 0;
}

QString defaultUrdf()
{
    const QString data = qEnvironmentVariable("LEARNID_DATA");
    return QDir(data.isEmpty() ? QStringLiteral(LEARNID_SHARED_DATA) : data)
        .filePath(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
}

// The first line of a file starting with prefix, after its colon ("?" when there is none).
// std::ifstream: QFile sees /proc files as empty.
std::string procLine(const char *path, const std::string &prefix = {})
{
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(prefix, 0) == 0)
            return prefix.empty() ? line : line.substr(line.find(':') + 2);
    }
    return "?";
}

void printContext(const char *when)
{
    std::printf("%s %s: %u cores (%s), load average %s\n\n", when,
                qPrintable(QDateTime::currentDateTime().toString(Qt::ISODate)),
                std::thread::hardware_concurrency(),
                procLine("/proc/cpuinfo", "model name").c_str(), procLine("/proc/loadavg").c_str());
}

} // namespace

int main(int argc, char **argv)
{
    bench::ChainOptions o;
    o.urdf = defaultUrdf();
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help")
            return usage(nullptr);
        bool *flag = a == "--accuracy-only"           ? &o.speed
                     : a == "--speed-only"            ? &o.accuracy
                     : a == "--one-way"               ? &o.thereAndBack
                     : a == "--cad-residues"          ? &o.exactZeros
                     : a == "--feedforward-at-sample" ? &o.midSample
                     : a == "--ideal-measurement"     ? &o.ideal
                                                      : nullptr;
        if (flag) {
            *flag = a == "--ideal-measurement"; // the others turn something off
            continue;
        }
        if (i + 1 >= argc)
            return usage(argv[i]);
        const char *v = argv[++i];
        if (a == "--urdf")
            o.urdf = QString::fromLocal8Bit(v);
        else if (a == "--seeds")
            o.seeds = std::max(1, std::atoi(v));
        else if (a == "--repeats")
            o.repeats = std::max(1, std::atoi(v));
        else if (a == "--planning-fraction")
            o.planningFraction = std::atof(v);
        else if (a == "--lambda")
            o.lambda = std::atof(v);
        else if (a == "--rho")
            o.rho = std::atof(v);
        else if (a == "--rank-tolerance")
            o.rankTolerance = std::atof(v);
        else if (a == "--repetitions")
            o.repetitions = std::max(1, std::atoi(v));
        else if (a == "--substeps")
            o.substeps = std::max(1, std::atoi(v));
        else if (a == "--sample-period" && std::atof(v) > 0.0)
            o.samplePeriod = 1e-3 * std::atof(v);
        else
            return usage(argv[i - 1]);
    }
    if (!QFileInfo::exists(o.urdf)) {
        std::fprintf(stderr, "no KUKA LWR4+ URDF at %s (set LEARNID_DATA or pass --urdf)\n",
                     qPrintable(o.urdf));
        return 2;
    }
    printContext("Started");
    std::printf(
        "Scenario: %s, waypoints %s, planning fraction %g, lambda %g 1/s, rho %g 1/s, "
        "rank tolerance %g, %d runs per trial, RK4 %d steps per %g ms sample, feedforward at %s, "
        "phi_0 %s.\n\n",
        qPrintable(QFileInfo(o.urdf).fileName()), o.thereAndBack ? "a b c b a" : "a b c",
        o.planningFraction, o.lambda, o.rho, o.rankTolerance, o.repetitions, o.substeps,
        1e3 * o.samplePeriod, o.midSample ? "the middle of each sample" : "each sample's instant",
        o.exactZeros ? "the CAD model, rounding residues < 1e-12 made 0"
                     : "the CAD model as withRobotDefaults() gives it");
    try {
        if (o.accuracy && !bench::runChainAccuracy(o))
            return 1;
        if (o.speed && !bench::runChainSpeed(o))
            return 1;
    } catch (const Error &e) {
        std::fprintf(stderr, "%s\n", qPrintable(e.message()));
        return 1;
    }
    printContext("Finished");
    return 0;
}
