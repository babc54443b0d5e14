// learnid-bench-zoo (issue 23 targets): sessions on simulated real KUKA LWR4+ robots, learnid
// always starting from the CAD URDF: (a) masses, centres of mass, inertia and joint friction
// off as on real arms; (b) (a) + Stribeck friction, static 1.5 x Coulomb; (c) (a) + rotor
// inertia 0.5-2 x the link's own about its axis; (d) (a) + elastic joints 5-15 kN m/rad and a
// 1 ms torque-sensor lag. Per robot, over seeds: trials needed to reach a max tracking error
// <= 5 % of trial 0's, trials aborted, path-torque error, the floor ideal measurement leaves,
// the floor the noise leaves (the same noisy session started at the true parameters), what the
// robot's own joint law tracks as feedforward (ownLawError), CPU per session. Prints Markdown
// for docs/benchmarks.md.
#include "zoo.h"

#include "BenchSupport.h"
#include "model/Error.h"
#include "session/ConvergenceFigures.h"

#include <QCoreApplication>
#include <QFile>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace learnid;
using namespace learnid::bench;

namespace {

struct SessionFigures
{
    double first = 0;       ///< trial 0's max error [deg] (at the stop if it aborted)
    int needed = -1;        ///< first trial with max error <= 5 % of trial 0's; -1: none
    int aborted = 0;        ///< trials stopped by the tracking limit
    int trials = 0;         ///< trials run
    double bestRatio = 0;   ///< best completed trial's max error / first [%]
    double best = 0;        ///< its max error [deg]
    double bestLearned = 0; ///< best completed trial after the first learning [deg]; NaN: none
    double pathTorque = 0;  ///< newest estimate's path-torque error against the rigid truth [%]
    double cpu = 0;         ///< [s]
    QString stop;           ///< why the session ended before its trials, if it did
};

double maxError(const TrialResult &t)
{
    return t.maxTrackingErrorDeg.size() ? t.maxTrackingErrorDeg.maxCoeff() : 0.0;
}

// Where a trial's largest error is: joint, time, and every joint's max [deg].
QString whereLargest(const TrialResult &t)
{
    const Eigen::MatrixXd e =
        (t.plan().desired.q.leftCols(t.record.samples()) - t.record.q).cwiseAbs() * 180.0 / M_PI;
    Eigen::Index j = 0, k = 0;
    e.maxCoeff(&j, &k);
    QString joints;
    for (Eigen::Index i = 0; i < e.rows(); ++i)
        joints += QStringLiteral(" %1").arg(e.row(i).maxCoeff(), 0, 'f', 3);
    return QStringLiteral("joint %1 at t = %2 s of %3 s; per joint:%4")
        .arg(j + 1)
        .arg(double(k) * t.record.samplePeriod, 0, 'f', 3)
        .arg(double(t.plan().samples() - 1) * t.record.samplePeriod, 0, 'f', 3)
        .arg(joints);
}

SessionFigures runSession(const Scenario &requested, int trials, bool verbose, bool startAtTruth)
{
    SessionFigures f;
    const auto model = makeRobotModel(requested.model, requested.urdf); // cached
    const double t0 = cpuSeconds();
    Scenario s = withRobotDefaults(requested, *model);
    if (startAtTruth)
        s.initialParameters = s.simulation.trueParameters;
    CommissioningSession session(s, model, makeSimulatedRobot(s, model));
    if (!session.runTrials(trials) && session.history().size() < trials)
        f.stop = session.history().isEmpty() ? QStringLiteral("no trial")
                                             : session.history().constLast().message;
    f.cpu = cpuSeconds() - t0;
    const QVector<TrialResult> &h = session.history();
    f.trials = int(h.size());
    if (h.isEmpty())
        return f;
    f.first = maxError(h.at(0));
    f.best = 1e9;
    f.bestLearned = 1e9;
    for (const TrialResult &t : h) {
        if (!t.record.completed()) {
            f.aborted += t.record.stoppedAtTrackingLimit() ? 1 : 0;
        } else {
            f.best = std::min(f.best, maxError(t));
            if (t.index > 0)
                f.bestLearned = std::min(f.bestLearned, maxError(t));
            if (f.needed < 0 && t.index > 0 && maxError(t) <= 0.05 * f.first)
                f.needed = t.index;
        }
        if (verbose)
            std::printf("    trial %d%s: %.4f deg, %s\n", t.index,
                        t.record.completed() ? "" : " (aborted)", maxError(t),
                        qPrintable(whereLargest(t)));
    }
    f.pathTorque =
        pathTorqueErrorPercent(*model, h.constLast().plan().desired,
                               session.estimates().constLast(), s.simulation.trueParameters);
    if (f.bestLearned > 1e8)
        f.bestLearned = NAN;
    if (f.best > 1e8) { // no trial completed
        f.best = NAN;
        f.pathTorque = NAN;
    }
    f.bestRatio = 100.0 * f.best / f.first;
    return f;
}

double worst(std::vector<double> v, bool larger = true)
{
    return v.empty() ? 0.0
           : larger  ? *std::max_element(v.begin(), v.end())
                     : *std::min_element(v.begin(), v.end());
}

QString trialsText(double v, int limit)
{
    return v < 0 || v > limit ? QStringLiteral("not reached") : QString::number(int(v));
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const ZooOptions o = parseZooOptions(app);

    const QString cadPath = QStringLiteral(LEARNID_SHARED_DATA "/kuka-lwr4/kuka_lwr4.urdf");
    QTemporaryDir dir;
    QString cad;
    bool armature = false;
    QString sensors; // the robots learned as having joint torque sensors
    try {
        cad = readText(cadPath);
        armature = zooScenario(o, cadPath, cadPath, 'a', 1, false).urdf.jointTerms.armature;
        for (const QChar r : o.robots)
            if (zooScenario(o, cadPath, cadPath, char(r.toLatin1()), 1, false)
                    .estimator.jointTorqueSensor)
                sensors += QStringLiteral(" (%1)").arg(r);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "learnid-bench-zoo: %s\n", e.what());
        return 1;
    }
    std::printf("KUKA LWR4+ from the CAD URDF, %s, rotor inertia %s, joint torque sensor "
                "(the rotor learned from the command) on%s, sensor lag undone %s, %.0f deg "
                "abort limit, "
                "2^20 counts, 1 %% torque noise, %d trials (Run all) of %d run(s) each, %d seeds "
                "per robot; the floor: the same robot with an ideal encoder and no noise, %d "
                "trials\n\n",
                o.docsGains ? "docs/scenario.md's gains and path"
                            : "scenario --print's gains, path and gentle first trial",
                armature ? "learned" : "not in the model",
                sensors.isEmpty() ? " no robot" : qPrintable(sensors),
                o.sensorLag < 0 ? "as each robot's (1 ms on (d))"
                                : qPrintable(QStringLiteral("%1 ms").arg(1000 * o.sensorLag)),
                o.limitDeg, o.trials, o.repetitions, o.seeds, o.floorTrials);
    std::printf(
        "| robot | trials needed to <= 5 %% of trial 0, median / worst | trials aborted, "
        "median / worst | best trial / trial 0, median / worst | path-torque error, "
        "median / worst | floor (ideal measurement) / trial 0, median / worst | noise floor "
        "(from the truth) / trial 0, median / worst | own law as feedforward / trial 0, "
        "median / worst | CPU per session, median / worst | target |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n");
    for (const QChar r : o.robots) {
        const char robot = char(r.toLatin1());
        std::vector<double> needed, aborted, ratio, torque, floorRatio, noiseRatio, lawRatio, cpu;
        QStringList stops;
        for (int seed = 1; seed <= o.seeds; ++seed) {
            const QString realPath =
                dir.filePath(QStringLiteral("lwr-%1-%2.urdf").arg(r).arg(seed));
            QFile f(realPath);
            if (!f.open(QIODevice::WriteOnly))
                return 1;
            f.write(zooRobotUrdf(cad, quint64(seed)).toUtf8());
            f.close();
            try {
                if (o.verbose)
                    std::printf("robot (%c) seed %d:\n", robot, seed);
                const SessionFigures s =
                    runSession(zooScenario(o, cadPath, realPath, robot, quint64(seed), false),
                               o.trials, o.verbose, o.startAtTruth);
                if (o.verbose)
                    std::printf("  floor:\n");
                const SessionFigures ideal =
                    runSession(zooScenario(o, cadPath, realPath, robot, quint64(seed), true),
                               o.floorTrials, o.verbose, o.startAtTruth);
                // The noise's own floor: the same noisy session learning from the truth; its
                // best trial after the first learning, over this session's trial 0.
                const SessionFigures fromTruth =
                    runSession(zooScenario(o, cadPath, realPath, robot, quint64(seed), false),
                               o.trials, false, true);
                const double law = ownLawError(
                    zooScenario(o, cadPath, realPath, robot, quint64(seed), true), o.ownLawRotor);
                // A session without a completed trial counts as infinitely far off.
                const auto orInf = [](double v) {
                    return std::isnan(v) ? INFINITY : v;
                };
                needed.push_back(s.needed < 0 ? 99 : s.needed);
                aborted.push_back(s.aborted);
                ratio.push_back(orInf(s.bestRatio));
                torque.push_back(orInf(s.pathTorque));
                floorRatio.push_back(orInf(100.0 * ideal.best / s.first));
                noiseRatio.push_back(orInf(100.0 * fromTruth.bestLearned / s.first));
                lawRatio.push_back(100.0 * law / s.first);
                cpu.push_back(s.cpu);
                if (!s.stop.isEmpty())
                    stops << QStringLiteral("seed %1: %2").arg(seed).arg(s.stop);
                std::fprintf(stderr,
                             "(%c) seed %d: trial 0 %.3f deg, best %.3f deg (%.1f %%), "
                             "needed %d, aborted %d, path torque %.2f %%, floor %.3f deg, "
                             "noise floor %.3f deg, own law %.3f deg, CPU %.2f s; floor path "
                             "torque %.3f %%\n",
                             robot, seed, s.first, s.best, s.bestRatio, s.needed, s.aborted,
                             s.pathTorque, ideal.best, fromTruth.bestLearned, law, s.cpu,
                             ideal.pathTorque);
            } catch (const Error &e) {
                stops << QStringLiteral("seed %1: %2").arg(seed).arg(e.message());
            }
        }
        const bool met = !needed.empty() && worst(needed) < o.trials && worst(cpu) < 2.0;
        std::printf("| (%c) | %s / %s | %.0f / %.0f | %.1f %% / %.1f %% | %.2f %% / %.2f %% | "
                    "%.1f %% / %.1f %% | %.1f %% / %.1f %% | %.1f %% / %.1f %% | "
                    "%.2f s / %.2f s | %s |\n",
                    robot, qPrintable(trialsText(median(needed), o.trials - 1)),
                    qPrintable(trialsText(worst(needed), o.trials - 1)), median(aborted),
                    worst(aborted), median(ratio), worst(ratio), median(torque), worst(torque),
                    median(floorRatio), worst(floorRatio), median(noiseRatio), worst(noiseRatio),
                    median(lawRatio), worst(lawRatio), median(cpu), worst(cpu),
                    met ? "met" : "**not met**");
        for (const QString &stop : stops)
            std::printf("|  | %s |||||||||\n", qPrintable(stop));
        std::fflush(stdout);
    }
    std::printf("\n(Target: every session within %d trials at <= 5 %% of trial 0's max tracking "
                "error, CPU < 2 s per session. Path-torque error: the newest estimate against "
                "the rigid-body truth on the last trial's path. Noise floor: the same session, "
                "noise and seed, started at the simulated robot's rigid-body parameters; its best "
                "trial after the first learning. Own law: one trial at the planned speed whose "
                "feedforward is the simulated robot's own law, rigid-body truth, rotor inertia "
                "and Stribeck friction with the exact sign of the desired velocity; elastic "
                "joints' spring dynamics left out.)\n",
                o.trials);
    return 0;
}
