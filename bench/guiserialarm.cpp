// The GUI targets for a 7-axis arm (see guiserialarm.h): plots, table and chart after 10 trials
// update in <= 50 ms; the GUI thread is never blocked > 16 ms during a trial.
#include "guiserialarm.h"

#include "BenchSupport.h"
#include "model/ChainModel.h"
#include "service/SessionController.h"
#include "service/TrackingErrorData.h"
#include "service/TrialSummary.h"
#include "session/RobotScenario.h"
#include "ui/ConvergenceChart.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/MainWindow.h"
#include "ui/TrackingErrorPlot.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <array>
#include <cstdio>
#include <ctime>

namespace learnid::bench {

namespace {

constexpr int kTrials = 10;

double msSince(const QElapsedTimer &t)
{
    return double(t.nsecsElapsed()) / 1e6;
}

/// What the window's views get after each trial, as the application hands it to them: the
/// trials without their samples (trialSummary), the plot's curves (computed in the session's
/// thread in the application) and the estimates.
struct ArmRun
{
    Scenario scenario;
    QList<ParameterInfo> parameters;
    QStringList jointNames;
    QVector<TrialResult> summaries;
    QList<QList<TrackingErrorCurve>> curves;
    QVector<Eigen::VectorXd> estimates;
    std::vector<double> curveMs; ///< trackingErrorCurves() per trial
};

ArmRun runSession(const QString &modelId)
{
    ArmRun a;
    const Scenario requested = scenarioForRobot(modelId);
    const auto model = makeRobotModel(modelId, requested.urdf);
    a.scenario = withRobotDefaults(requested, *model);
    a.parameters = model->parameters();
    if (const auto *chain = dynamic_cast<const ChainModel *>(model.get()))
        for (const ChainJoint &joint : chain->chain().joints)
            a.jointNames << joint.name;
    CommissioningSession session(a.scenario, model, makeSimulatedRobot(a.scenario, model));
    for (int k = 0; k < kTrials; ++k) {
        const TrialResult &trial = session.runTrial();
        QElapsedTimer t;
        t.start();
        a.curves << trackingErrorCurves(trial);
        a.curveMs.push_back(msSince(t));
        a.summaries << trialSummary(trial);
    }
    a.estimates = QVector<Eigen::VectorXd>(session.estimates().begin(), session.estimates().end());
    return a;
}

/// CPU time of the calling thread [ms].
double threadCpuMs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

struct Views
{
    MainWindow *window;
    TrackingErrorPlot *plot;
    ConvergenceTableModel *table;
    ConvergenceChart *chart;
};

/// The presenter's calls after trial k (trialFinished, then historyChanged), the events they
/// post and a synchronous repaint: cumulative wall time [ms] after plot, table, chart and
/// repaint, then the GUI thread's CPU time for all of it [ms] (the wall time less waiting for a
/// core on a busy machine).
std::array<double, 5> update(const Views &v, const ArmRun &a, int k)
{
    std::array<double, 5> ms{};
    const double cpu = threadCpuMs();
    QElapsedTimer t;
    t.start();
    v.plot->setTrialCurves(a.summaries[k].index, a.curves[k]);
    QCoreApplication::processEvents();
    ms[0] = msSince(t);
    v.table->setHistory(a.summaries.mid(0, k + 1), a.estimates.mid(0, k + 2));
    QCoreApplication::processEvents();
    ms[1] = msSince(t);
    v.chart->setData(a.parameters, a.estimates.mid(0, k + 2), a.scenario.simulation.trueParameters);
    QCoreApplication::processEvents();
    ms[2] = msSince(t);
    v.window->repaint();
    ms[3] = msSince(t);
    ms[4] = threadCpuMs() - cpu;
    return ms;
}

/// The views as after trial k - 1 (untimed): the plot cleared and given trials 0 .. k-1 in the
/// chosen view, table and chart with their estimates.
void restoreBefore(const Views &v, const ArmRun &a, int k, bool overlay)
{
    v.plot->clear();
    if (overlay)
        v.plot->setSelectedTrial(-1);
    for (int i = 0; i < k; ++i)
        v.plot->setTrialCurves(a.summaries[i].index, a.curves[i]);
    v.table->setHistory(a.summaries.mid(0, k), a.estimates.mid(0, k + 1));
    v.chart->setData(a.parameters, a.estimates.mid(0, k + 1), a.scenario.simulation.trueParameters);
    QCoreApplication::processEvents();
    v.window->repaint();
}

void updateTimes(const ArmRun &a, int repetitions)
{
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    MainWindow window(&settings);
    window.resize(1400, 900);
    window.show();
    QCoreApplication::processEvents();
    const Views v{&window, window.plot(), window.tableModel(),
                  window.findChild<ConvergenceChart *>()};
    v.table->setParameters(a.parameters, a.scenario.simulation.trueParameters);
    v.plot->setJointNames(a.jointNames); // as the window does when a session opens
    std::printf("| trial | samples | curves* [ms] | plot [ms] | table [ms] | chart [ms] | "
                "repaint [ms] | total [ms] |\n|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < kTrials; ++k) {
        const std::array<double, 5> ms = update(v, a, k);
        std::printf("| %d | %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", a.summaries[k].index,
                    a.summaries[k].record.samples(), a.curveMs[size_t(k)], ms[0], ms[1] - ms[0],
                    ms[2] - ms[1], ms[3] - ms[2], ms[3]);
    }
    std::printf(
        "\n\\* computed in the session's thread in the application, not in the update.\n\n");

    // The update after trial 10 again and again, from the views as after trial 9: the newest
    // trial's 7 joints (what the window shows), and the overlay of all trials and joints.
    std::printf("| after trial 10, %d repetitions | plot median [ms] | total median [ms] | "
                "total max [ms] | GUI-thread CPU median / max [ms] | target |\n"
                "|---|---|---|---|---|---|\n",
                repetitions);
    for (const bool overlay : {false, true}) {
        std::vector<double> plot, total, cpu;
        int series = 0, points = 0;
        for (int r = 0; r < repetitions; ++r) {
            restoreBefore(v, a, kTrials - 1, overlay);
            const std::array<double, 5> ms = update(v, a, kTrials - 1);
            plot.push_back(ms[0]);
            total.push_back(ms[3]);
            cpu.push_back(ms[4]);
            series = v.plot->seriesCount();
            points = v.plot->pointCount();
        }
        const double worst = *std::max_element(total.begin(), total.end());
        std::printf("| %s (%d series, %d points) | %.1f | %.1f | %.1f | %.1f / %.1f | %s |\n",
                    overlay ? "overlay, all trials and joints" : "newest trial, all joints", series,
                    points, median(plot), median(total), worst, median(cpu),
                    *std::max_element(cpu.begin(), cpu.end()),
                    worst <= 50.0 ? "met (<= 50 ms)" : "NOT met (> 50 ms)");
    }
    std::printf("\n");
}

/// A gap between two ticks of the probe: wall time, and the GUI thread's CPU time in it (the
/// work that blocked the event loop; the rest is waiting for a core on a busy machine) [ms].
struct Gap
{
    double wall = 0.0;
    double cpu = 0.0;
};

/// What a 1 ms timer on the GUI thread saw while the window's controller ran a series of
/// trials, by when each gap ended.
struct Gaps
{
    std::vector<Gap> inTrial;    ///< between trialStarted and trialFinished
    std::vector<Gap> perTrial;   ///< each trial's largest (wall, CPU)
    std::vector<Gap> afterTrial; ///< the gap holding the window's update after a trial
    std::vector<Gap> between;    ///< the rest: learning step, pre-trial check
};

/// One session of `scenario` in a fresh window: open, runTrials(kTrials), the probe's gaps.
/// trialFinished is connected after the window's presenter: the gap in which the presenter's
/// update runs ends after it, and counts as afterTrial.
Gaps probeSession(const Scenario &scenario)
{
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    MainWindow window(&settings);
    window.resize(1400, 900);
    window.show();
    QCoreApplication::processEvents();
    SessionController *c = window.controller();

    Gaps g;
    QElapsedTimer clock;
    clock.start();
    qint64 last = 0;
    double lastCpu = 0.0;
    bool inTrial = false, finished = false;
    Gap trialWorst;
    QTimer probe;
    probe.setTimerType(Qt::PreciseTimer);
    probe.setInterval(1);
    QObject::connect(&probe, &QTimer::timeout, [&] {
        const qint64 now = clock.nsecsElapsed();
        const double cpu = threadCpuMs();
        const Gap gap{double(now - last) / 1e6, cpu - lastCpu};
        last = now;
        lastCpu = cpu;
        if (finished) {
            g.afterTrial.push_back(gap);
            finished = false;
        } else if (inTrial) {
            g.inTrial.push_back(gap);
            trialWorst = {std::max(trialWorst.wall, gap.wall), std::max(trialWorst.cpu, gap.cpu)};
        } else {
            g.between.push_back(gap);
        }
    });
    QObject::connect(c, &SessionController::trialStarted, [&] {
        inTrial = true;
        trialWorst = {};
    });
    QObject::connect(c, &SessionController::trialFinished, [&] {
        inTrial = false;
        finished = true;
        g.perTrial.push_back(trialWorst);
    });
    QEventLoop loop;
    QObject::connect(c, &SessionController::opened, [&] {
        last = clock.nsecsElapsed();
        lastCpu = threadCpuMs();
        probe.start();
        c->runTrials(kTrials);
    });
    QObject::connect(c, &SessionController::openFailed, &loop, [&](const QString &message) {
        std::printf("cannot open the session: %s\n", qPrintable(message));
        loop.quit();
    });
    QObject::connect(c, &SessionController::runFinished, &loop, [&] {
        probe.stop();
        loop.quit();
    });
    c->open(scenario);
    loop.exec();
    return g;
}

Gap maxOf(const std::vector<Gap> &v)
{
    Gap m;
    for (const Gap &x : v)
        m = {std::max(m.wall, x.wall), std::max(m.cpu, x.cpu)};
    return m;
}

/// The GUI thread's gaps between the ticks of a 1 ms timer while the window's controller runs
/// 10 trials of `scenario` on the simulated robot in its worker thread, in `sessions` fresh
/// windows.
void responsiveness(const Scenario &scenario, int sessions)
{
    std::printf("| session | ticks in trials | largest gap in trial 0, 1, ... 9: wall [ms] | "
                "largest GUI-thread CPU in a gap during the trials [ms] | gaps > 16 ms: wall, "
                "CPU | update after a trial, largest gap: wall / CPU [ms] | between trials: "
                "wall / CPU [ms] |\n|---|---|---|---|---|---|---|\n");
    std::vector<double> wall;
    Gap worst, worstUpdate, worstBetween;
    int overWall = 0, overCpu = 0;
    for (int r = 0; r < sessions; ++r) {
        const Gaps g = probeSession(scenario);
        QStringList perTrial;
        for (const Gap &t : g.perTrial)
            perTrial << QString::number(t.wall, 'f', 1);
        int w = 0, cpu = 0;
        for (const Gap &x : g.inTrial) {
            w += x.wall > 16.0;
            cpu += x.cpu > 16.0;
            wall.push_back(x.wall);
        }
        const Gap in = maxOf(g.inTrial), up = maxOf(g.afterTrial), bt = maxOf(g.between);
        std::printf("| %d | %d | %s | %.1f | %d, %d | %.1f / %.1f | %.1f / %.1f |\n", r + 1,
                    int(g.inTrial.size()), qPrintable(perTrial.join(QStringLiteral(", "))), in.cpu,
                    w, cpu, up.wall, up.cpu, bt.wall, bt.cpu);
        worst = maxOf({worst, in});
        worstUpdate = maxOf({worstUpdate, up});
        worstBetween = maxOf({worstBetween, bt});
        overWall += w;
        overCpu += cpu;
    }
    std::sort(wall.begin(), wall.end());
    const double p999 = wall.empty() ? 0.0 : wall[size_t(0.999 * double(wall.size() - 1))];
    std::printf(
        "\nDuring the trials (%d ticks): the GUI thread's work between two ticks at most %.1f ms "
        "of CPU (target: never blocked > 16 ms, %s); wall-clock gaps at most %.1f ms, 99.9th "
        "percentile %.1f ms, median %.2f ms, %d of them > 16 ms. The window's update after a "
        "trial: largest gap %.1f ms wall, %.1f ms CPU; between trials (learning step, pre-trial "
        "check): %.1f ms wall, %.1f ms CPU.\n\n",
        int(wall.size()), worst.cpu, worst.cpu <= 16.0 && overCpu == 0 ? "met" : "NOT met",
        worst.wall, p999, median(wall), overWall, worstUpdate.wall, worstUpdate.cpu,
        worstBetween.wall, worstBetween.cpu);
}

} // namespace

void serialArmGui(const QString &modelId, int repetitions, int sessions)
{
    QElapsedTimer t;
    t.start();
    const ArmRun a = runSession(modelId);
    std::printf("### %s: %d joints, %d parameters, %d trials (simulated in %.1f s)\n\n",
                qPrintable(modelId), int(a.scenario.controller.kp.size()), int(a.parameters.size()),
                kTrials, msSince(t) / 1000.0);
    updateTimes(a, repetitions);
    responsiveness(scenarioForRobot(modelId), sessions);
}

} // namespace learnid::bench
