// End-to-end tests of `learnid-cli plan` and `learnid-cli learn`, the learning loop through files:
// the simulated robot plays "another controller" that only exchanges plan and log files.
#include "../support/OtherController.h"
#include "../support/ToolRun.h"
#include "io/AtomicFile.h"
#include "io/LoopHistory.h"
#include "io/ParameterFile.h"
#include "io/PlanCsv.h"
#include "io/ScenarioFile.h"
#include "service/FileLoop.h"
#include "session/CommissioningSession.h"
#include "session/ScenarioRobot.h"

#include <QDir>
#include <QFile>
#include <QLocale>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using namespace learnid;

class TestCliLoop : public QObject
{
    Q_OBJECT

private slots:
    void trialsThroughFiles_equalTheSession_data();
    void trialsThroughFiles_equalTheSession();
    void refusedPlan_writesNothing();
    void estimateOption_startsTheHistoryWithIt();
    void badLogs_areRefusedAndChangeNothing_data();
    void badLogs_areRefusedAndChangeNothing();
    void changedScenario_isRefusedNamingBothPlans();
    void trackingLimitLog_isLearnedAsTheSessionLearnsIt();
    void usageErrorsAndHelp_nameTheCommandsOptions();

private:
    using Result = learnid::test::ToolRun;
    static Result cli(const QStringList &args, const QString &dir)
    {
        return learnid::test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, dir);
    }
    static void write(const QString &path, const QByteArray &data)
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
    }
};

namespace {

using test::logCsv;
using test::planFromCsv;

QByteArray number(double v)
{
    return test::shortestNumber(v);
}

double relativeDifference(const Eigen::VectorXd &a, const Eigen::VectorXd &b)
{
    return a.size() == b.size()
               ? (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff())
               : HUGE_VAL;
}

QStringList allFiles(const QString &dir)
{
    QStringList out;
    for (const QFileInfo &f :
         QDir(dir).entryInfoList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot))
        out << f.fileName() + QLatin1Char(':') + QString::number(f.size());
    return out;
}

} // namespace

void TestCliLoop::trialsThroughFiles_equalTheSession_data()
{
    QTest::addColumn<QByteArray>("scenario"); // empty: the built-in paper scenario
    QTest::addColumn<int>("trials");
    QTest::newRow("paper scenario, 3 trials") << QByteArray() << 3;
    // Measurement noise drawn per run, and two runs averaged per trial: one log per run.
    QTest::newRow("noise, 2 runs per trial") << QByteArray(R"({"estimator": {"repetitions": 2},
                          "simulation": {"torqueNoise": 0.005, "encoderCounts": 65536}})")
                                             << 2;
}

void TestCliLoop::trialsThroughFiles_equalTheSession()
{
    QFETCH(QByteArray, scenario);
    QFETCH(int, trials);
    QTemporaryDir dir;
    QStringList scenarioOption;
    if (!scenario.isEmpty()) {
        write(dir.filePath(QStringLiteral("s.json")), scenario);
        scenarioOption << QStringLiteral("--scenario") << QStringLiteral("s.json");
    }
    const LoopScenario s = loopScenario(
        scenario.isEmpty() ? Scenario{} : readScenarioFile(dir.filePath(QStringLiteral("s.json"))));
    const int runs = s.scenario.repetitions;
    // The other controller: the simulated robot, its runs numbered as the session numbers them
    // (each run draws its own noise).
    const auto controller = makeSimulatedRobot(s.scenario, s.model);
    Result learned;
    for (int k = 0; k < trials; ++k) {
        const Result planned = cli(QStringList{QStringLiteral("plan"), QStringLiteral("--out"),
                                               QStringLiteral("exchange")} +
                                       scenarioOption,
                                   dir.path());
        QCOMPARE(planned.exitCode, 0);
        QVERIFY2(planned.out.contains(QStringLiteral("trial %1: check passed").arg(k)),
                 qPrintable(planned.out));
        const QString exchange = dir.filePath(QStringLiteral("exchange"));
        const QByteArray check = readFile(exchange + QStringLiteral("/check.txt"));
        QVERIFY(planned.out.startsWith(QString::fromUtf8(check)));
        const PlanCsv plan = readPlanCsvFile(exchange + QStringLiteral("/plan.csv"));
        QVERIFY(planned.out.contains(plan.planId));

        QStringList args{QStringLiteral("learn")};
        for (int r = 0; r < runs; ++r) {
            const TrialRecord record = controller->runTrial(planFromCsv(plan, s.scenario), {});
            QVERIFY2(record.completed(), qPrintable(record.message));
            const QString log = QStringLiteral("exchange/run-%1-%2.csv").arg(k).arg(r);
            write(dir.filePath(log), logCsv(plan.planId, record));
            args << QStringLiteral("--trial-log") << log;
        }
        learned = cli(args + scenarioOption, dir.path());
        QCOMPARE(learned.exitCode, 0);
        QVERIFY2(learned.err.contains(
                     QStringLiteral("trial %1 (plan %2) learned").arg(k).arg(plan.planId)),
                 qPrintable(learned.err));
    }
    // The convergence table of `run`: a row per estimate, no truth on another controller.
    QVERIFY2(learned.out.contains(QStringLiteral("max|e|1 deg")), qPrintable(learned.out));
    QVERIFY(!learned.out.contains(QStringLiteral("vs truth")));
    QCOMPARE(learned.out.trimmed().split(QLatin1Char('\n')).size(), 1 + trials + 1);

    // The session that runs the same trials on the simulated robot itself.
    CommissioningSession session(s.scenario, s.model, makeSimulatedRobot(s.scenario, s.model));
    QVERIFY(session.runTrials(trials));
    const QDir history(dir.filePath(QStringLiteral("exchange/learnid-history")));
    const LoopHistory index =
        loopHistoryFromJson(readFile(history.filePath(QStringLiteral("history.json"))), {});
    QCOMPARE(index.trials.size(), trials);
    QCOMPARE(index.estimates.size(), trials + 1);
    QVERIFY(index.pendingPlans.isEmpty());
    for (int k = 0; k <= trials; ++k) {
        const Eigen::VectorXd phi =
            readParameterFile(history.filePath(QStringLiteral("estimate-%1.json").arg(k))).values;
        QVERIFY2(relativeDifference(phi, session.estimates().at(k)) < 1e-12,
                 qPrintable(QStringLiteral("estimate %1").arg(k)));
    }
    for (int k = 0; k < trials; ++k) {
        const TrialResult &t = session.history().at(k);
        QVERIFY(relativeDifference(index.trials.at(k).maxTrackingErrorDeg, t.maxTrackingErrorDeg) <
                1e-12);
        QVERIFY(relativeDifference(index.trials.at(k).rmsTrackingErrorDeg, t.rmsTrackingErrorDeg) <
                1e-12);
        QCOMPARE(index.trials.at(k).planId, planIdOf(t.plan()));
    }
    // Learning works: the last trial tracks better than the first.
    QVERIFY(index.trials.constLast().maxTrackingErrorDeg.maxCoeff() <
            0.5 * index.trials.constFirst().maxTrackingErrorDeg.maxCoeff());
}

void TestCliLoop::refusedPlan_writesNothing()
{
    QTemporaryDir dir;
    // The paper's lambda = 40 with an estimate near the truth: the closed loop is unstable.
    write(dir.filePath(QStringLiteral("s.json")),
          R"({"controller": {"lambda": 40}, "robot": {"initialParameters": [20, 5, 8]}})");
    const Result r = cli({QStringLiteral("plan"), QStringLiteral("--scenario"),
                          QStringLiteral("s.json"), QStringLiteral("--out"), QStringLiteral("out")},
                         dir.path());
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains(QStringLiteral("trial 0 refused")), qPrintable(r.err));
    QVERIFY(r.err.contains(QStringLiteral("unstable")));
    QVERIFY(r.err.contains(QStringLiteral("no files written")));
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("out"))));
}

void TestCliLoop::estimateOption_startsTheHistoryWithIt()
{
    QTemporaryDir dir;
    const Result run =
        cli({QStringLiteral("run"), QStringLiteral("--iterations"), QStringLiteral("1"),
             QStringLiteral("--export"), QStringLiteral("phi.json"), QStringLiteral("--quiet")},
            dir.path());
    QCOMPARE(run.exitCode, 0);
    const Eigen::VectorXd phi = readParameterFile(dir.filePath(QStringLiteral("phi.json"))).values;
    const QStringList args{QStringLiteral("plan"),     QStringLiteral("--estimate"),
                           QStringLiteral("phi.json"), QStringLiteral("--out"),
                           QStringLiteral("ex"),       QStringLiteral("--quiet")};
    QCOMPARE(cli(args, dir.path()).exitCode, 0);
    const PlanCsv plan = readPlanCsvFile(dir.filePath(QStringLiteral("ex/plan.csv")));
    QVERIFY(plan.estimate == phi);
    const QString history = dir.filePath(QStringLiteral("ex/learnid-history"));
    QVERIFY(readParameterFile(history + QStringLiteral("/estimate-0.json")).values == phi);

    // Once the history has learned, its next trial runs with its newest estimate.
    const LoopScenario s = loopScenario(Scenario{});
    const TrialRecord record =
        makeSimulatedRobot(s.scenario, s.model)->runTrial(planFromCsv(plan, s.scenario), {});
    write(dir.filePath(QStringLiteral("ex/run.csv")), logCsv(plan.planId, record));
    QCOMPARE(
        cli({QStringLiteral("learn"), QStringLiteral("--trial-log"), QStringLiteral("ex/run.csv")},
            dir.path())
            .exitCode,
        0);
    const Result again = cli(args, dir.path());
    QCOMPARE(again.exitCode, 2);
    QVERIFY2(again.err.contains(QStringLiteral("has learned from 1 trials")),
             qPrintable(again.err));
}

// A log that ends early is learned from when it says the controller stopped the trial at its
// tracking limit (docs/file-formats.md, "Controller trial log"), exactly as a session learns.
void TestCliLoop::trackingLimitLog_isLearnedAsTheSessionLearnsIt()
{
    QTemporaryDir dir;
    const QByteArray scenario = R"({"safety": {"maxTrackingErrorDeg": 0.02}})";
    write(dir.filePath(QStringLiteral("s.json")), scenario);
    const QStringList options{QStringLiteral("--scenario"), QStringLiteral("s.json")};
    QCOMPARE(cli(QStringList{QStringLiteral("plan"), QStringLiteral("--out"), QStringLiteral("."),
                             QStringLiteral("--quiet")} +
                     options,
                 dir.path())
                 .exitCode,
             0);
    const PlanCsv plan = readPlanCsvFile(dir.filePath(QStringLiteral("plan.csv")));
    const LoopScenario s = loopScenario(readScenarioFile(dir.filePath(QStringLiteral("s.json"))));
    const TrialRecord record =
        makeSimulatedRobot(s.scenario, s.model)->runTrial(planFromCsv(plan, s.scenario), {});
    QVERIFY(record.stoppedAtTrackingLimit());
    const QByteArray log = logCsv(plan.planId, record);
    const QStringList learn = QStringList{QStringLiteral("learn"), QStringLiteral("--trial-log"),
                                          QStringLiteral("run.csv")} +
                              options;

    // An unknown cause is refused, naming the line and the known ones.
    write(dir.filePath(QStringLiteral("run.csv")), "# stopped-by: limit\n" + log);
    const Result unknown = cli(learn, dir.path());
    QCOMPARE(unknown.exitCode, 2);
    QVERIFY2(unknown.err.contains(QStringLiteral("line 1: \"# stopped-by:\" says limit; known: "
                                                 "tracking-limit")),
             qPrintable(unknown.err));

    write(dir.filePath(QStringLiteral("run.csv")), "# stopped-by: tracking-limit\n" + log);
    const Result learned = cli(learn, dir.path());
    QCOMPARE(learned.exitCode, 0);
    QVERIFY2(learned.out.contains(QStringLiteral("learned from a partial trial")),
             qPrintable(learned.out));
    CommissioningSession session(s.scenario, s.model, makeSimulatedRobot(s.scenario, s.model));
    QVERIFY(session.runTrial().learnedFromPartial());
    const Eigen::VectorXd phi =
        readParameterFile(dir.filePath(QStringLiteral("learnid-history/estimate-1.json"))).values;
    QVERIFY(relativeDifference(phi, session.estimates().at(1)) < 1e-12);
}

void TestCliLoop::badLogs_areRefusedAndChangeNothing_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown plan-id")
        << QStringLiteral("unknown") << 2 << QStringLiteral("which the history");
    QTest::newRow("no plan-id") << QStringLiteral("no id") << 2
                                << QStringLiteral("no \"# plan-id:\" comment line");
    QTest::newRow("ended early") << QStringLiteral("short") << 3
                                 << QStringLiteral("the trial ended early; nothing learned");
    QTest::newRow("more samples than planned")
        << QStringLiteral("long") << 2 << QStringLiteral("beyond the plan's");
    QTest::newRow("off the grid") << QStringLiteral("grid") << 2
                                  << QStringLiteral("line 14: t = 0.021 s is off the plan's grid");
    QTest::newRow("learned already")
        << QStringLiteral("twice") << 2 << QStringLiteral("has learned from already as trial 0");
}

void TestCliLoop::badLogs_areRefusedAndChangeNothing()
{
    QFETCH(QString, kind);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QCOMPARE(cli({QStringLiteral("plan"), QStringLiteral("--out"), QStringLiteral("."),
                  QStringLiteral("--quiet")},
                 dir.path())
                 .exitCode,
             0);
    const PlanCsv plan = readPlanCsvFile(dir.filePath(QStringLiteral("plan.csv")));
    const LoopScenario s = loopScenario(Scenario{});
    const TrialRecord record =
        makeSimulatedRobot(s.scenario, s.model)->runTrial(planFromCsv(plan, s.scenario), {});
    QByteArray log = logCsv(plan.planId, record);
    if (kind == QLatin1String("unknown")) {
        log = logCsv(QString(64, QLatin1Char('a')), record);
    } else if (kind == QLatin1String("no id")) {
        log.replace("# plan-id:", "# plan:");
    } else if (kind == QLatin1String("short")) {
        log = logCsv(plan.planId, record, record.samples() - 10);
    } else if (kind == QLatin1String("long")) {
        log += number(record.samples() * record.samplePeriod) + ",ok,0,0,0,0\n";
    } else if (kind == QLatin1String("grid")) {
        log.replace("\n0.02,ok", "\n0.021,ok"); // sample 10 on line 14
    } else if (kind == QLatin1String("twice")) {
        write(dir.filePath(QStringLiteral("run.csv")), log);
        QCOMPARE(cli({QStringLiteral("learn"), QStringLiteral("--trial-log"),
                      QStringLiteral("run.csv"), QStringLiteral("--quiet")},
                     dir.path())
                     .exitCode,
                 0);
    }
    write(dir.filePath(QStringLiteral("run.csv")), log);
    const QString history = dir.filePath(QStringLiteral("learnid-history"));
    const QStringList before = allFiles(history);
    const QByteArray index = readFile(history + QStringLiteral("/history.json"));
    const Result r =
        cli({QStringLiteral("learn"), QStringLiteral("--trial-log"), QStringLiteral("run.csv")},
            dir.path());
    QCOMPARE(r.exitCode, exitCode);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QCOMPARE(allFiles(history), before);
    QCOMPARE(readFile(history + QStringLiteral("/history.json")), index);
}

void TestCliLoop::changedScenario_isRefusedNamingBothPlans()
{
    QTemporaryDir dir;
    QCOMPARE(cli({QStringLiteral("plan"), QStringLiteral("--out"), QStringLiteral("."),
                  QStringLiteral("--quiet")},
                 dir.path())
                 .exitCode,
             0);
    const PlanCsv plan = readPlanCsvFile(dir.filePath(QStringLiteral("plan.csv")));
    const LoopScenario s = loopScenario(Scenario{});
    const TrialRecord record =
        makeSimulatedRobot(s.scenario, s.model)->runTrial(planFromCsv(plan, s.scenario), {});
    write(dir.filePath(QStringLiteral("run.csv")), logCsv(plan.planId, record));
    // A longer rest after the motion: the same estimate plans another trial.
    Scenario changed;
    changed.restAfter = 0.6;
    changed.iterations = 1;
    write(dir.filePath(QStringLiteral("s.json")), R"({"path": {"restAfter": 0.6}})");
    const Result r =
        cli({QStringLiteral("learn"), QStringLiteral("--trial-log"), QStringLiteral("run.csv"),
             QStringLiteral("--scenario"), QStringLiteral("s.json")},
            dir.path());
    QCOMPARE(r.exitCode, 2);
    const LoopScenario c = loopScenario(changed);
    const CommissioningSession session(c.scenario, c.model,
                                       makeSimulatedRobot(c.scenario, c.model));
    const QString now = planIdOf(session.checkNextTrial().plan);
    QVERIFY2(r.err.contains(plan.planId) && r.err.contains(now), qPrintable(r.err));
    QVERIFY(r.err.contains(QStringLiteral("the scenario is not the one the plan was made with")));
}

void TestCliLoop::usageErrorsAndHelp_nameTheCommandsOptions()
{
    QTemporaryDir dir;
    const Result noOut = cli({QStringLiteral("plan")}, dir.path());
    QCOMPARE(noOut.exitCode, 1);
    QVERIFY2(noOut.err.contains(QStringLiteral("'plan' needs --out DIR")), qPrintable(noOut.err));
    const Result noLog = cli({QStringLiteral("learn")}, dir.path());
    QCOMPARE(noLog.exitCode, 1);
    QVERIFY(noLog.err.contains(QStringLiteral("'learn' needs --trial-log FILE")));
    const Result wrong =
        cli({QStringLiteral("learn"), QStringLiteral("--out"), QStringLiteral("x")}, dir.path());
    QCOMPARE(wrong.exitCode, 1);
    QVERIFY(wrong.err.contains(QStringLiteral("out")));

    const Result plan = cli({QStringLiteral("plan"), QStringLiteral("--help")}, dir.path());
    QCOMPARE(plan.exitCode, 0);
    for (const char *option : {"--out", "--estimate", "--history", "--scenario", "--workspace"})
        QVERIFY2(plan.out.contains(QLatin1String(option)), option);
    QVERIFY(!plan.out.contains(QStringLiteral("--trial-log")));
    const Result learn = cli({QStringLiteral("learn"), QStringLiteral("--help")}, dir.path());
    QCOMPARE(learn.exitCode, 0);
    QVERIFY(learn.out.contains(QStringLiteral("--trial-log")));
    QVERIFY(!learn.out.contains(QStringLiteral("--estimate")));
    QVERIFY(QDir(dir.path()).isEmpty());
}

QTEST_GUILESS_MAIN(TestCliLoop)
#include "tst_cli_loop.moc"
