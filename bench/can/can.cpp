// CAN benchmark (docs/benchmarks.md, "CAN"): the computed bus load of 2- and 6-joint
// configurations, and 2 joints at 500 Hz over virtualcan against learnid-robot-sim: consecutive
// trials of one plan, lost samples, late set-points, and the time from a SYNC's arrival in the
// tool to its RPDOs written (median, 99th percentile).
//   learnid-bench-can [--trials N] [--sim PATH]
#include "BenchSupport.h"
#include "canrobot/CanRobot.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QTcpServer>
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

void busLoadTable()
{
    std::printf("| configuration | frames/s | bit/s (worst case) | load of 1 Mbit/s | tool |\n"
                "|---|---|---|---|---|\n");
    for (const int joints : {2, 6}) {
        CanRobotOptions o;
        o.nodes.clear();
        for (int j = 1; j <= joints; ++j)
            o.nodes << j;
        const BusLoad load = configuredBusLoad(o);
        const QString error = canRobotOptionsError(o);
        // The percent as the tool prints it (Qt rounds 30.25 up, printf's %.1f to even).
        std::printf("| %d joints, 500 Hz | %.0f | %.0f | %s %% | %s |\n", joints,
                    load.framesPerSecond, load.bitsPerSecond,
                    qPrintable(QString::number(load.percent, 'f', 1)),
                    error.isEmpty() ? "accepted" : "refused (above 70 %)");
    }
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    const int trials = args.contains(QStringLiteral("--trials"))
                           ? args.value(args.indexOf(QStringLiteral("--trials")) + 1).toInt()
                           : 20;
    const QString simPath = args.contains(QStringLiteral("--sim"))
                                ? args.value(args.indexOf(QStringLiteral("--sim")) + 1)
                                : QStringLiteral(LEARNID_ROBOT_SIM_PATH);
    busLoadTable();

    QTcpServer probe;
    probe.listen(QHostAddress::LocalHost, 0);
    const quint16 port = probe.serverPort();
    probe.close();
    const QString interface = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
    QProcess sim;
    sim.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    sim.start(simPath, {QStringLiteral("--can-plugin"), QStringLiteral("virtualcan"),
                        QStringLiteral("--can-interface"), interface});
    QElapsedTimer wait;
    wait.start();
    bool ready = false;
    while (!ready && wait.elapsed() < 10000 && sim.waitForReadyRead(500))
        ready = sim.readAll().contains("ready");
    if (!ready) {
        std::fprintf(stderr, "learnid-bench-can: %s did not get ready\n", qPrintable(simPath));
        return 1;
    }

    const Scenario scenario;
    const auto model = makeRobotModel(scenario.model, scenario.urdf);
    const PreTrialCheck check = bench::makeSession(scenario)->checkNextTrial();
    CanRobotOptions options;
    options.plugin = QStringLiteral("virtualcan");
    options.interface = interface;
    CanRobot robot(model, options);
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
    std::printf("\n%d of %d trials completed, %d samples lost, %d late set-points; SYNC to RPDO "
                "over %zu SYNCs: median %.1f us, 99th percentile %.1f us, max %.1f us\n",
                completed, trials, lost, late, latency.size(), percentile(latency, 0.5),
                percentile(latency, 0.99), percentile(latency, 1.0));
    sim.terminate();
    sim.waitForFinished(5000);
    return lost == 0 ? 0 : 2;
}
