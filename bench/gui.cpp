// GUI benchmark (issue 3 targets): start-up to the first painted window, the update of the plots,
// table and chart after each of 10 trials, and memory over 100 trials; then the same update and
// the GUI thread's responsiveness during trials for a 7-axis arm (guiserialarm.cpp). Prints
// Markdown. Usage: learnid-bench-gui [startups] (QT_QPA_PLATFORM=offscreen without a display);
// `learnid-bench-gui --arm [model] [repetitions]` runs the 7-axis part alone (default: panda, 20;
// the responsiveness probe runs 5 sessions of 10 trials).
// Internally it starts copies of itself: `--startup-child` and `--memory-child gui|headless`.
#include "BenchSupport.h"
#include "guiserialarm.h"
#include "service/SessionController.h"
#include "service/SessionInfo.h"
#include "service/TrackingErrorData.h"
#include "ui/ConvergenceChart.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/MainWindow.h"
#include "ui/TrackingErrorPlot.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <cstdio>
#include <unistd.h>
#include <vector>

using namespace learnid;

namespace {

/// Resident set size of this process [MiB] (/proc/self/statm).
double rssMiB()
{
    QFile f(QStringLiteral("/proc/self/statm"));
    if (!f.open(QIODevice::ReadOnly))
        return 0.0;
    const QList<QByteArray> fields = f.readAll().split(' ');
    return fields.size() > 1 ? fields[1].toDouble() * double(sysconf(_SC_PAGESIZE)) / 1048576.0
                             : 0.0;
}

/// Child: shows the main window and prints when its first paint is done.
int startupChild(QApplication &app)
{
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    MainWindow window(&settings);
    window.show();
    QTimer::singleShot(0, &app, [&] {
        window.repaint(); // the first frame, synchronously
        std::printf("shown\n");
        std::fflush(stdout);
        app.quit();
    });
    return app.exec();
}

/// Wall time from QProcess::start to the child's "shown" [ms], median of `runs`.
double startupMs(const QString &self, int runs)
{
    std::vector<double> ms;
    for (int r = 0; r < runs; ++r) {
        QProcess child;
        QElapsedTimer timer;
        timer.start();
        child.start(self, {QStringLiteral("--startup-child")});
        while (child.waitForReadyRead(10000))
            if (child.readAll().contains("shown"))
                break;
        ms.push_back(double(timer.nsecsElapsed()) / 1e6);
        child.waitForFinished(10000);
    }
    return bench::median(ms);
}

/// The presenter's work after trial k of a 10-trial session, timed with the repaint.
void updateTimes()
{
    Scenario s;
    auto session = bench::makeSession(s);
    session->runTrials(10);
    const QVector<TrialResult> history(session->history().begin(), session->history().end());
    const QVector<Eigen::VectorXd> estimates(session->estimates().begin(),
                                             session->estimates().end());
    QList<ParameterInfo> parameters;
    for (int i = 0; i < int(s.simulation.trueParameters.size()); ++i)
        parameters << makeRobotModel(s.model, s.urdf)->parameters()[i];

    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    MainWindow window(&settings);
    window.resize(1400, 900);
    window.show();
    QCoreApplication::processEvents();
    window.tableModel()->setParameters(parameters, s.simulation.trueParameters);
    auto *chart = window.findChild<ConvergenceChart *>();
    std::printf("| trial | samples | plot [ms] | table [ms] | chart [ms] | repaint [ms] | "
                "total [ms] |\n|---|---|---|---|---|---|---|\n");
    double worst = 0.0;
    for (int k = 0; k < history.size(); ++k) {
        QElapsedTimer t;
        t.start();
        window.plot()->setTrialCurves(history[k].index, trackingErrorCurves(history[k]));
        QCoreApplication::processEvents();
        const double a = double(t.nsecsElapsed()) / 1e6;
        window.tableModel()->setHistory(history.mid(0, k + 1), estimates.mid(0, k + 2));
        QCoreApplication::processEvents();
        const double b = double(t.nsecsElapsed()) / 1e6;
        chart->setData(parameters, estimates.mid(0, k + 2), s.simulation.trueParameters);
        QCoreApplication::processEvents();
        const double d = double(t.nsecsElapsed()) / 1e6;
        window.repaint();
        const double ms = double(t.nsecsElapsed()) / 1e6;
        worst = std::max(worst, ms);
        std::printf("| %d | %d | %.1f | %.1f | %.1f | %.1f | %.1f |\n", history[k].index,
                    history[k].record.samples(), a, b - a, d - b, ms - d, ms);
    }
    std::printf("\nWorst update: %.1f ms (target < 50 ms).\n\n", worst);

    // The overlay of all trials, the plot's heaviest view: the 10 trials' curves again as
    // trials 10, 11, ... up to 100, each added with the overlay shown.
    window.plot()->setSelectedTrial(-1);
    std::printf("| trials overlaid | plot + repaint [ms] |\n|---|---|\n");
    for (int k = 10; k < 100; ++k) {
        QList<TrackingErrorCurve> curves = trackingErrorCurves(history[k % 10]);
        for (TrackingErrorCurve &c : curves)
            c.trial = k;
        QElapsedTimer t;
        t.start();
        window.plot()->setTrialCurves(k, curves);
        QCoreApplication::processEvents();
        window.repaint();
        if ((k + 1) % 30 == 0 || k == 10)
            std::printf("| %d | %.1f |\n", k + 1, double(t.nsecsElapsed()) / 1e6);
    }
    std::printf("\n");
}

/// The samples a history keeps: every trial's plan (q_d, qd_d, qdd_d, tau_f) and record (q,
/// tau) [MiB].
double samplesMiB(const QVector<TrialResult> &history)
{
    double doubles = 0;
    for (const TrialResult &t : history) {
        const TrialPlan &p = t.plan();
        for (const Eigen::MatrixXd *m : {&p.desired.q, &p.desired.qd, &p.desired.qdd,
                                         &p.feedforward, &t.record.q, &t.record.tau})
            doubles += double(m->size());
    }
    return doubles * sizeof(double) / (1024.0 * 1024.0);
}

/// Child: 100 trials through the window's controller (gui) or a bare session (headless);
/// prints "trials rss" every 10 trials (headless: and the samples the history keeps).
int memoryChild(QApplication &app, bool gui)
{
    Scenario s;
    if (!gui) {
        auto session = bench::makeSession(s);
        for (int k = 10; k <= 100; k += 10) {
            session->runTrials(10);
            std::printf("%d %.1f %.1f\n", k, rssMiB(), samplesMiB(session->history()));
        }
        return 0;
    }
    QTemporaryDir dir;
    QSettings settings(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    MainWindow window(&settings);
    window.show();
    SessionController *c = window.controller();
    QObject::connect(c, &SessionController::opened, c, [c] { c->runTrials(100); });
    QObject::connect(c, &SessionController::historyChanged, c, [c] {
        if (c->history().size() % 10 == 0 && !c->history().isEmpty())
            std::printf("%d %.1f\n", int(c->history().size()), rssMiB());
        std::fflush(stdout);
    });
    QObject::connect(c, &SessionController::runFinished, &app, &QApplication::quit);
    QObject::connect(c, &SessionController::openFailed, &app, [&app] { app.exit(1); });
    c->open(s);
    return app.exec();
}

void memory(const QString &self)
{
    std::printf(
        "| trials | RSS with the GUI [MiB] | RSS headless session [MiB] | samples kept [MiB] | "
        "GUI RSS - samples [MiB] | headless RSS - samples [MiB] |\n|---|---|---|---|---|---|\n");
    QProcess gui, headless;
    gui.start(self, {QStringLiteral("--memory-child"), QStringLiteral("gui")});
    headless.start(self, {QStringLiteral("--memory-child"), QStringLiteral("headless")});
    gui.waitForFinished(600000);
    headless.waitForFinished(600000);
    const QList<QByteArray> a = gui.readAllStandardOutput().trimmed().split('\n');
    const QList<QByteArray> b = headless.readAllStandardOutput().trimmed().split('\n');
    // Both children run the same deterministic trials: the headless history's samples are the
    // samples the window's session keeps in its worker thread too.
    std::vector<double> guiBeyond, headlessBeyond;
    for (int i = 0; i < std::min(a.size(), b.size()); ++i) {
        const QList<QByteArray> x = a[i].split(' '), y = b[i].split(' ');
        if (x.size() != 2 || y.size() != 3)
            continue;
        const double gui = x[1].toDouble(), bare = y[1].toDouble(), kept = y[2].toDouble();
        guiBeyond.push_back(gui - kept);
        headlessBeyond.push_back(bare - kept);
        std::printf("| %s | %.1f | %.1f | %.1f | %.1f | %.1f |\n", x[0].constData(), gui, bare,
                    kept, gui - kept, bare - kept);
    }
    if (guiBeyond.size() > 1) {
        const double trials = 10.0 * double(guiBeyond.size() - 1);
        std::printf("\nBeyond the samples kept, from trial 10 to %d: GUI %+.3f MiB per trial, "
                    "headless %+.3f MiB per trial.\n",
                    int(10 * guiBeyond.size()), (guiBeyond.back() - guiBeyond.front()) / trials,
                    (headlessBeyond.back() - headlessBeyond.front()) / trials);
    }
    std::printf("\n");
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    registerSessionMetaTypes();
    const QStringList args = app.arguments();
    if (args.contains(QStringLiteral("--startup-child")))
        return startupChild(app);
    const int mem = int(args.indexOf(QStringLiteral("--memory-child")));
    if (mem > 0 && mem + 1 < args.size())
        return memoryChild(app, args[mem + 1] == QStringLiteral("gui"));

    const int arm = int(args.indexOf(QStringLiteral("--arm")));
    const QString armModel =
        arm > 0 && arm + 1 < args.size() ? args[arm + 1] : QStringLiteral("panda");
    const int armRepetitions =
        arm > 0 && arm + 2 < args.size() ? std::max(1, args[arm + 2].toInt()) : 20;
    if (arm > 0) {
        std::printf("Platform: %s\n\n", qPrintable(QGuiApplication::platformName()));
        bench::serialArmGui(armModel, armRepetitions, 5);
        return 0;
    }
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    const QString self = QCoreApplication::applicationFilePath();
    std::printf("Platform: %s\n\n", qPrintable(QGuiApplication::platformName()));
    std::printf("Start-up to the first painted main window: median %.0f ms over %d runs "
                "(target < 1000 ms).\n\n",
                startupMs(self, runs), runs);
    updateTimes();
    memory(self);
    bench::serialArmGui(armModel, armRepetitions, 5);
    return 0;
}
