// CAN benchmark (docs/benchmarks.md, "CAN"): the computed bus load of 2 to 7 joints at 1, 2 and
// 4 ms with the tool's verdict and offer, then consecutive trials of one plan on a CanRobot over
// virtualcan against learnid-robot-sim: the paper arm (2 joints, SYNC every 2 ms) and the 7-axis
// KUKA LWR4+ (URDF of ../shared/data, SYNC every 4 ms): lost samples, late set-points, and the
// time from a SYNC's arrival in the tool to its RPDOs written (median, 99th percentile).
//   learnid-bench-can [--trials N] [--sim PATH] [--arm paper|lwr4|all] [--urdf FILE]
//                     [--can-sync-timeout MS]   (default: the SYNC period's, as learnid-cli)
//                     [--can-plugin socketcan --can-interface vcan0] [--lwr4-period-ms 4|5|10]
// Over socketcan it needs a kernel with AF_CAN: ../shared/tools/can-kernel runs it in a VM.
#include "BenchSupport.h"
#include "canrobot/CanRobot.h"
#include "io/ScenarioFile.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTcpServer>
#include <QTemporaryDir>
#include <cstdio>

using namespace learnid;

namespace {

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, size_t(p * double(v.size())))];
}

// The 1-minute load average (Linux), for the conditions of a run: the trials are real time on a
// machine shared with whatever else runs.
QString loadAverage()
{
    QFile f(QStringLiteral("/proc/loadavg"));
    return f.open(QIODevice::ReadOnly)
               ? QString::fromLatin1(f.readLine()).section(QLatin1Char(' '), 0, 0)
               : QStringLiteral("?");
}

void busLoadTable()
{
    std::printf(
        "| joints | SYNC period | frames/s | bit/s (worst case) | load of 1 Mbit/s | tool |\n"
        "|---|---|---|---|---|---|\n");
    for (int joints = 2; joints <= 7; ++joints) {
        for (const int ms : {1, 2, 4}) {
            CanRobotOptions o;
            o.nodes = defaultNodeList(joints);
            o.syncPeriod = ms / 1000.0;
            const BusLoad load = configuredBusLoad(o);
            const QString verdict =
                busLoadError(o).isEmpty()
                    ? QStringLiteral("accepted")
                    : QStringLiteral("refused; offers %1 ms").arg(shortestFittingSyncPeriodMs(o));
            // The percent as the tool prints it (Qt rounds 30.25 up, printf's %.1f to even).
            std::printf("| %d | %d ms | %.0f | %.0f | %s %% | %s |\n", joints, ms,
                        load.framesPerSecond, load.bitsPerSecond,
                        qPrintable(QString::number(load.percent, 'f', 1)), qPrintable(verdict));
        }
    }
}

// The 7-axis scenario of docs/scenario.md ("Any serial arm") at a SYNC period of 4, 5 or 10 ms,
// the gains scaled for it as tests/app/tst_can_e2e_7axis.cpp runs it: x 0.4 with lambda 400 at
// 4 ms; x 0.2 (5 ms) and x 0.15 (10 ms) with lambda 150 and the wrist (joints 5, 6, 7) x 4, 4, 3
// of that.
QByteArray lwrScenarioJson(const QString &urdf, int periodMs)
{
    const double kp[] = {340, 600, 100, 140, 15, 14, 11};
    const double ki[] = {34, 60, 10, 14, 1.5, 1.4, 1.1};
    const double kd[] = {45, 80, 14, 19, 2, 1.9, 1.5};
    const double gain = periodMs <= 4 ? 0.4 : periodMs <= 5 ? 0.2 : 0.15;
    const double wrist[] = {periodMs <= 4 ? 1.0 : 4.0, periodMs <= 4 ? 1.0 : 4.0,
                            periodMs <= 4 ? 1.0 : 3.0};
    const double lambda = periodMs <= 4 ? 400 : 150;
    QJsonArray p, i, d;
    for (int j = 0; j < 7; ++j) {
        const double g = gain * (j >= 4 ? wrist[j - 4] : 1);
        p.append(g * kp[j]);
        i.append(g * ki[j]);
        d.append(g * kd[j]);
    }
    const QJsonObject s{
        {"schema", "learnid-scenario/2"},
        {"robot", QJsonObject{{"model", "urdf"},
                              {"urdf", QJsonObject{{"file", urdf}}},
                              {"jointTerms", QJsonObject{{"viscous", true}, {"coulomb", true}}}}},
        {"path",
         QJsonObject{{"kind", "waypoints"},
                     {"waypoints", QJsonArray{QJsonArray{0, 0.3, 0, -1.2, 0, 0.5, 0},
                                              QJsonArray{0.8, 0.8, 0.5, -0.6, 0.6, -0.4, 0.9},
                                              QJsonArray{-0.4, 0.5, -0.5, -1.4, -0.5, 0.6, -0.7}}},
                     {"planningFraction", 0.3}}},
        {"controller", QJsonObject{{"samplePeriod", periodMs / 1000.0},
                                   {"kp", p},
                                   {"ki", i},
                                   {"kd", d},
                                   {"lambda", lambda}}},
        {"simulation", QJsonObject{{"inertiaPerturbation", 0.3},
                                   {"encoderCounts", 1048576},
                                   {"torqueNoise", 0.01}}},
        {"safety", QJsonObject{{"maxTrackingErrorDeg", 5}}}};
    return QJsonDocument(s).toJson();
}

struct Bus
{
    QString plugin = QStringLiteral("virtualcan");
    QString interface;     ///< socketcan: the interface; virtualcan: a free port is taken
    int syncTimeoutMs = 0; ///< 0: the default of the SYNC period
};

// Trials of the scenario's first plan against learnid-robot-sim (virtualcan: on a free port);
// the samples lost over all trials, or -1 when the simulator did not start.
int runTrials(const QString &simPath, const QString &title, const QString &scenarioPath, int trials,
              const Bus &bus)
{
    Scenario scenario = scenarioPath.isEmpty() ? Scenario{} : readScenarioFile(scenarioPath);
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    scenario = withRobotDefaults(scenario, *model);
    const PreTrialCheck check = bench::makeSession(scenario)->checkNextTrial();

    QString interface = bus.interface;
    if (bus.plugin == QLatin1String("virtualcan")) {
        QTcpServer probe;
        probe.listen(QHostAddress::LocalHost, 0);
        interface = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(probe.serverPort());
    }
    QStringList simArgs{QStringLiteral("--can-plugin"), bus.plugin,
                        QStringLiteral("--can-interface"), interface};
    if (!scenarioPath.isEmpty())
        simArgs << QStringLiteral("--scenario") << scenarioPath;
    QProcess sim;
    sim.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    sim.start(simPath, simArgs);
    QElapsedTimer wait;
    wait.start();
    bool ready = false;
    // Up to 30 s: in the VM of ../shared/tools/can-kernel the simulator needs seconds to start.
    while (!ready && wait.elapsed() < 30000 && sim.state() != QProcess::NotRunning) {
        if (sim.waitForReadyRead(500))
            ready = sim.readAll().contains("ready");
    }
    if (!ready) {
        std::fprintf(stderr, "learnid-bench-can: %s did not get ready\n", qPrintable(simPath));
        return -1;
    }

    CanRobotOptions options;
    options.plugin = bus.plugin;
    options.interface = interface;
    options.nodes = defaultNodeList(model->dof());
    options.syncPeriod = scenario.controller.samplePeriod;
    setSyncTimeoutMs(options, bus.syncTimeoutMs);
    std::printf("\n### %s: %d joints over %s %s, SYNC every %.0f ms, bus load %s; %d samples per "
                "trial; no SYNC for %d ms stops a trial\n",
                qPrintable(title), model->dof(), qPrintable(bus.plugin), qPrintable(interface),
                1000 * scenario.controller.samplePeriod,
                qPrintable(configuredBusLoad(options).text(options.bitrate)), check.plan.samples(),
                effectiveSyncTimeoutMs(options));
    CanRobot robot(model, options);
    const QString startLoad = loadAverage();
    std::vector<double> latency;
    int completed = 0, lost = 0, late = 0;
    std::printf("\n| trial | status | samples | lost | late set-points | SYNC->RPDO median us | "
                "p99 us |\n|---|---|---|---|---|---|---|\n");
    for (int t = 0; t < trials; ++t) {
        const TrialRecord r = robot.runTrial(check.plan, {});
        const TrialStreamStatistics s = robot.lastTrialStatistics();
        const std::vector<double> us(s.syncToRpdoUs.begin(), s.syncToRpdoUs.end());
        latency.insert(latency.end(), us.begin(), us.end());
        completed += r.completed() ? 1 : 0;
        lost += check.plan.samples() - r.samples();
        late += s.lateSetpoints;
        std::printf("| %d | %s | %d | %d | %d | %.0f | %.0f |\n", t,
                    qPrintable(trialStatusName(r.status)), r.samples(),
                    check.plan.samples() - r.samples(), s.lateSetpoints, percentile(us, 0.5),
                    percentile(us, 0.99));
        if (!r.completed())
            std::printf("|   | %s |||||\n", qPrintable(r.message));
        std::fflush(stdout);
    }
    std::printf("\n%s: %d of %d trials completed, %d samples lost, %d late set-points; SYNC to "
                "RPDO over %zu SYNCs: median %.1f us, 99th percentile %.1f us, max %.1f us; "
                "load average %s at the start, %s at the end\n",
                qPrintable(title), completed, trials, lost, late, latency.size(),
                percentile(latency, 0.5), percentile(latency, 0.99), percentile(latency, 1.0),
                qPrintable(startLoad), qPrintable(loadAverage()));
    sim.terminate();
    sim.waitForFinished(5000);
    return lost;
}

QString option(const QStringList &args, const QString &name, const QString &fallback)
{
    const qsizetype at = args.indexOf(name);
    return at >= 0 && at + 1 < args.size() ? args.at(at + 1) : fallback;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const int trials = option(args, QStringLiteral("--trials"), QStringLiteral("20")).toInt();
    const QString simPath =
        option(args, QStringLiteral("--sim"), QStringLiteral(LEARNID_ROBOT_SIM_PATH));
    const QString arm = option(args, QStringLiteral("--arm"), QStringLiteral("all"));
    Bus bus;
    bus.syncTimeoutMs =
        option(args, QStringLiteral("--can-sync-timeout"), QStringLiteral("0")).toInt();
    bus.plugin = option(args, QStringLiteral("--can-plugin"), bus.plugin);
    bus.interface = option(args, QStringLiteral("--can-interface"), QStringLiteral("vcan0"));
    const int lwrPeriodMs =
        option(args, QStringLiteral("--lwr4-period-ms"), QStringLiteral("4")).toInt();
    if (bus.plugin != QLatin1String("virtualcan") && bus.plugin != QLatin1String("socketcan")) {
        std::fprintf(stderr, "learnid-bench-can: --can-plugin is virtualcan or socketcan\n");
        return 1;
    }
    if (lwrPeriodMs != 4 && lwrPeriodMs != 5 && lwrPeriodMs != 10) {
        std::fprintf(stderr, "learnid-bench-can: --lwr4-period-ms is 4, 5 or 10\n");
        return 1;
    }
    const QString data = qEnvironmentVariable("LEARNID_DATA", QStringLiteral(LEARNID_SHARED_DATA));
    const QString urdf = option(args, QStringLiteral("--urdf"),
                                QDir(data).filePath(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf")));
    busLoadTable();

    int lost = 0;
    if (arm == QLatin1String("paper") || arm == QLatin1String("all")) {
        const int l = runTrials(simPath, QStringLiteral("paper arm"), {}, trials, bus);
        if (l < 0)
            return 1;
        lost += l;
    }
    if (arm == QLatin1String("lwr4") || arm == QLatin1String("all")) {
        if (!QFileInfo::exists(urdf)) {
            std::fprintf(stderr, "learnid-bench-can: no URDF at %s (--urdf FILE or LEARNID_DATA)\n",
                         qPrintable(urdf));
            return 1;
        }
        QTemporaryDir dir;
        const QString scenario = dir.filePath(QStringLiteral("lwr4-%1ms.json").arg(lwrPeriodMs));
        QFile f(scenario);
        if (!f.open(QIODevice::WriteOnly) || f.write(lwrScenarioJson(urdf, lwrPeriodMs)) < 0)
            return 1;
        f.close();
        const int l = runTrials(simPath, QStringLiteral("KUKA LWR4+"), scenario, trials, bus);
        if (l < 0)
            return 1;
        lost += l;
    }
    return lost == 0 ? 0 : 2;
}
