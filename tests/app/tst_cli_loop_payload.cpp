// `learnid-cli plan` and `learn` with a payload section: the payload's learning loop through
// files on the simulated Panda carrying 1.5 kg 5 cm off the flange axis (PayloadScenarios.h), the
// simulated robot playing the robot's own controller that only exchanges plan and log files.
// Its payload estimates, plans and tracking errors are held against a PayloadSession that runs
// the same trials on the simulated robot itself; bad input is refused naming it, and changes
// nothing.
#include "../session/PayloadScenarios.h"
#include "../support/OtherController.h"
#include "../support/ToolRun.h"
#include "io/AtomicFile.h"
#include "io/LoopHistory.h"
#include "io/ParameterFile.h"
#include "io/PlanCsv.h"
#include "io/ScenarioFile.h"
#include "service/FileLoop.h"
#include "session/PayloadSession.h"
#include "session/ScenarioRobot.h"

#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

using Result = test::ToolRun;

Result cli(const QStringList &args, const QString &dir)
{
    return test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, dir);
}

void write(const QString &path, const QByteArray &data)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(data);
}

// Every file below dir with a hash of its content, to see that nothing changed.
QStringList snapshot(const QString &dir)
{
    QStringList out;
    for (QDirIterator it(dir, QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot,
                         QDirIterator::Subdirectories);
         it.hasNext();) {
        const QString path = it.next();
        const QByteArray hash =
            it.fileInfo().isDir()
                ? QByteArray("dir")
                : QCryptographicHash::hash(readFile(path), QCryptographicHash::Sha256).toHex();
        out << QDir(dir).relativeFilePath(path) + QLatin1Char(':') + QString::fromLatin1(hash);
    }
    out.sort();
    return out;
}

void copyTree(const QString &from, const QString &to)
{
    QDir().mkpath(to);
    for (const QFileInfo &f :
         QDir(from).entryInfoList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot)) {
        const QString target = QDir(to).filePath(f.fileName());
        if (f.isDir())
            copyTree(f.filePath(), target);
        else
            QVERIFY(QFile::copy(f.filePath(), target));
    }
}

// The trial table's rows `run` and `learn` print for a payload session, each as printed but
// for the update's CPU time (masked: the only field that is not the session's).
QStringList tableRows(const QString &out)
{
    static const QRegularExpression cpu(QStringLiteral("\\)\\s+\\d+\\.\\d\\s+"));
    const QStringList lines = out.split(QLatin1Char('\n'));
    QStringList rows;
    int at = lines.indexOf(QRegularExpression(QStringLiteral(".*\\[ms\\]")));
    if (at < 0)
        return rows;
    for (++at; at < lines.size() && !lines.at(at).trimmed().isEmpty(); ++at)
        rows << QString(lines.at(at)).replace(cpu, QStringLiteral(")  -  "));
    return rows;
}

ParameterFilePayload payloadOf(const QString &path)
{
    const ParameterFileContent c = readParameterFile(path);
    return c.payload.value_or(ParameterFilePayload());
}

} // namespace

class TestCliLoopPayload : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void trialsThroughFiles_equalThePayloadSession_data();
    void trialsThroughFiles_equalThePayloadSession();
    void badInput_isRefusedNamingItAndChangesNothing_data();
    void badInput_isRefusedNamingItAndChangesNothing();
    void stoppedAtTheTrackingLimit_isLearnedUpToTheStop();

private:
    QTemporaryDir m_base; // s.json and ex/: one trial learned, the next planned and logged
    LoopScenario m_s;
    QString m_planId1;
    TrialRecord m_record1;
};

void TestCliLoopPayload::initTestCase()
{
    QVERIFY(m_base.isValid());
    writeScenarioFile(m_base.filePath(QStringLiteral("s.json")), test::pandaWithPayload());
    m_s = loopScenario(readScenarioFile(m_base.filePath(QStringLiteral("s.json"))));
    const QStringList scenario{QStringLiteral("--scenario"), QStringLiteral("s.json")};
    const auto controller = makeSimulatedRobot(m_s.scenario, m_s.model);
    for (int k = 0; k < 2; ++k) {
        const Result planned = cli(QStringList{QStringLiteral("plan"), QStringLiteral("--out"),
                                               QStringLiteral("ex"), QStringLiteral("--quiet")} +
                                       scenario,
                                   m_base.path());
        QVERIFY2(planned.exitCode == 0, qPrintable(planned.err));
        const PlanCsv plan = readPlanCsvFile(m_base.filePath(QStringLiteral("ex/plan.csv")));
        const TrialRecord record = controller->runTrial(test::planFromCsv(plan, m_s.scenario), {});
        QVERIFY(record.completed());
        const QString log = QStringLiteral("ex/run-%1.csv").arg(k);
        write(m_base.filePath(log), test::logCsv(plan.planId, record));
        if (k == 1) {
            m_planId1 = plan.planId;
            m_record1 = record;
            break;
        }
        const Result learned =
            cli(QStringList{QStringLiteral("learn"), QStringLiteral("--trial-log"), log,
                            QStringLiteral("--quiet")} +
                    scenario,
                m_base.path());
        QVERIFY2(learned.exitCode == 0, qPrintable(learned.err));
    }
}

void TestCliLoopPayload::trialsThroughFiles_equalThePayloadSession_data()
{
    QTest::addColumn<int>("baselineTrials");
    QTest::newRow("3 payload trials") << 0;
    // The controller runs trial 0 on the robot without the payload (payload.baselineTrials).
    QTest::newRow("a baseline trial, then 2 payload trials") << 1;
}

void TestCliLoopPayload::trialsThroughFiles_equalThePayloadSession()
{
    QFETCH(int, baselineTrials);
    const int trials = 3;
    QTemporaryDir dir;
    Scenario scenarioFile = test::pandaWithPayload();
    scenarioFile.payload.baselineTrials = baselineTrials;
    scenarioFile.iterations = trials - baselineTrials;
    writeScenarioFile(dir.filePath(QStringLiteral("s.json")), scenarioFile);
    const LoopScenario s = loopScenario(readScenarioFile(dir.filePath(QStringLiteral("s.json"))));
    const QStringList scenario{QStringLiteral("--scenario"), QStringLiteral("s.json")};
    const auto controller = makeSimulatedRobot(s.scenario, s.model);
    const auto bareController = makeSimulatedBareRobot(s.scenario, s.model); // as `run` makes it
    Result learned;
    for (int k = 0; k < trials; ++k) {
        const Result planned = cli(QStringList{QStringLiteral("plan"), QStringLiteral("--out"),
                                               QStringLiteral("exchange")} +
                                       scenario,
                                   dir.path());
        QVERIFY2(planned.exitCode == 0, qPrintable(planned.err));
        QVERIFY2(planned.out.contains(QStringLiteral("trial %1: check passed").arg(k)),
                 qPrintable(planned.out));
        QVERIFY(planned.out.contains(QStringLiteral(
            "the path determines 10 of the payload's 10 parameters on panda_link7")));
        const bool baseline = k < baselineTrials;
        const int payloadTrials = k - baselineTrials; // learned from before trial k
        QVERIFY2(planned.out.contains(
                     baseline
                         ? QStringLiteral("trial %1 is a baseline trial (payload.baselineTrials), "
                                          "run it WITHOUT the payload mounted")
                               .arg(k)
                     : payloadTrials <= 0
                         ? QStringLiteral("the payload's prior")
                         : QStringLiteral("learned from the trials up to trial %1").arg(k - 1)),
                 qPrintable(planned.out));
        const QByteArray check = readFile(dir.filePath(QStringLiteral("exchange/check.txt")));
        QVERIFY(planned.out.startsWith(QString::fromUtf8(check)));
        const PlanCsv plan = readPlanCsvFile(dir.filePath(QStringLiteral("exchange/plan.csv")));
        const TrialRecord record = (baseline ? bareController : controller)
                                       ->runTrial(test::planFromCsv(plan, s.scenario), {});
        QVERIFY2(record.completed(), qPrintable(record.message));
        const QString log = QStringLiteral("exchange/run-%1.csv").arg(k);
        write(dir.filePath(log), test::logCsv(plan.planId, record));
        learned =
            cli(QStringList{QStringLiteral("learn"), QStringLiteral("--trial-log"), log} + scenario,
                dir.path());
        QVERIFY2(learned.exitCode == 0, qPrintable(learned.err));
        QVERIFY2(learned.err.contains(
                     baseline
                         ? QStringLiteral("baseline trial %1 (plan %2) kept; mount the payload "
                                          "before the next trial")
                               .arg(k)
                               .arg(plan.planId)
                         : QStringLiteral("trial %1 (plan %2) learned").arg(k).arg(plan.planId)),
                 qPrintable(learned.err));
    }

    // The session that runs the same trials on the simulated robot itself, the baseline on the
    // robot without its payload.
    PayloadSession session(s.scenario, s.model, makeSimulatedRobot(s.scenario, s.model),
                           makeSimulatedBareRobot(s.scenario, s.model));
    QVERIFY(session.runTrials(trials - baselineTrials));
    QCOMPARE(int(session.history().size()), trials);
    const QDir history(dir.filePath(QStringLiteral("exchange/learnid-history")));
    const LoopHistory index =
        loopHistoryFromJson(readFile(history.filePath(QStringLiteral("history.json"))), {});
    QCOMPARE(index.payloadLink, QStringLiteral("panda_link7"));
    QCOMPARE(index.trials.size(), trials);
    QVERIFY(index.pendingPlans.isEmpty());
    for (int k = 0; k < trials; ++k) {
        const PayloadTrial &t = session.history().at(size_t(k));
        QCOMPARE(t.baseline, k < baselineTrials);
        QCOMPARE(index.trials.at(k).planId, planIdOf(t.plan()));
        // Bit for bit: the logs answer exactly as the simulated robot did.
        QVERIFY(index.trials.at(k).maxTrackingErrorDeg == t.maxTrackingErrorDeg);
        QVERIFY(index.trials.at(k).rmsTrackingErrorDeg == t.rmsTrackingErrorDeg);
    }
    // Estimate k: the arm held fixed plus the payload the session had before trial k: the prior
    // until a payload trial is learned from, then its fit.
    const PayloadBody prior = payloadBody(session.prior().parameters());
    for (int k = 0; k <= trials; ++k) {
        const QString path = history.filePath(QStringLiteral("estimate-%1.json").arg(k));
        QVERIFY(readParameterFile(path).values == s.scenario.initialParameters);
        const ParameterFilePayload p = payloadOf(path);
        const PayloadEstimate *fit =
            k - 1 >= baselineTrials ? &session.history().at(size_t(k - 1)).fit->estimate : nullptr;
        const PayloadBody &b = fit ? fit->body : prior;
        QCOMPARE(p.link, QStringLiteral("panda_link7"));
        QVERIFY2(p.mass == b.mass && p.com == b.com,
                 qPrintable(QStringLiteral("estimate %1").arg(k)));
        QCOMPARE(p.inertiaAtCom[2], b.inertiaAtCom(1, 1));
        for (size_t i = 0; i < 10; ++i)
            QCOMPARE(p.identified[i], fit && fit->bodyIdentified[i]);
    }

    // learn prints what run prints: a row per trial, then the payload learned.
    const Result run = cli(QStringList{QStringLiteral("run")} + scenario, dir.path());
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    const QStringList rows = tableRows(learned.out);
    QCOMPARE(rows.size(), trials);
    QCOMPARE(rows, tableRows(run.out));
    QCOMPARE(rows.first().contains(QStringLiteral("baseline: the same path without the payload")),
             baselineTrials > 0);
    QVERIFY(learned.out.contains(QStringLiteral("The payload after trial 2")));
    qInfo("%s", qPrintable(learned.out));
    // Learning works: the last trial ran with a mass within 1 % and tracks far better than the
    // first payload trial.
    QVERIFY(std::abs(session.history().back().payloadUsed[0] - 1.5) < 0.015);
    QVERIFY(index.trials.at(2).maxTrackingErrorDeg.maxCoeff() <
            0.1 * index.trials.at(baselineTrials).maxTrackingErrorDeg.maxCoeff());
}

void TestCliLoopPayload::badInput_isRefusedNamingItAndChangesNothing_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QString mixed = QStringLiteral("learns the payload on panda_link7 (a scenario with a "
                                         "payload section); the scenario learns the arm");
    QTest::newRow("plan: arm scenario, payload history") << "plan arm" << 2 << mixed;
    QTest::newRow("learn: arm scenario, payload history") << "learn arm" << 2 << mixed;
    QTest::newRow("plan: payload scenario, arm history")
        << "arm history" << 2
        << QStringLiteral("was made by the arm's learning loop (a scenario without a payload "
                          "section); the scenario learns a payload");
    QTest::newRow("plan: --estimate") << "estimate" << 2
                                      << QStringLiteral("--estimate: a scenario with a payload "
                                                        "section plans with the arm's model");
    QTest::newRow("plan: another link")
        << "link" << 2
        << QStringLiteral("learns the payload on panda_link7, the scenario's payload.link is "
                          "panda_link6");
    QTest::newRow("plan: another arm")
        << "arm model" << 2
        << QStringLiteral("estimate-0.json holds another arm model than the scenario's "
                          "robot.initialParameters");
    QTest::newRow("learn: another prior")
        << "prior" << 2
        << QStringLiteral("estimate-0.json holds another payload prior than the scenario's "
                          "payload section");
    QTest::newRow("learn: another path")
        << "path" << 2 << QStringLiteral("the scenario is not the one the plan was made with");
    QTest::newRow("learn: six joints logged")
        << "six joints" << 2
        << QStringLiteral("run-1.csv: line 3: the log has 6 joints (q1..q6), the robot 7");
    QTest::newRow("learn: two logs")
        << "two logs" << 2 << QStringLiteral("a payload's learning loop runs every trial once");
    QTest::newRow("learn: ended early")
        << "short" << 3
        << QStringLiteral("trial 1 did not complete (the log ends after 1160 of the "
                          "plan's 1170 samples");
    QTest::newRow("plan: refused by the check")
        << "refused" << 3 << QStringLiteral("trial 0 refused by the pre-trial check");
}

void TestCliLoopPayload::badInput_isRefusedNamingItAndChangesNothing()
{
    QFETCH(QString, kind);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    QTemporaryDir dir;
    copyTree(m_base.path(), dir.path());
    const auto path = [&](const char *name) {
        return dir.filePath(QLatin1String(name));
    };
    Scenario changed = test::pandaWithPayload();
    QStringList args{QStringLiteral("learn"), QStringLiteral("--trial-log"),
                     QStringLiteral("ex/run-1.csv"), QStringLiteral("--scenario"),
                     QStringLiteral("s.json")};
    const QStringList plan{QStringLiteral("plan"), QStringLiteral("--out"), QStringLiteral("ex"),
                           QStringLiteral("--scenario"), QStringLiteral("s.json")};
    if (kind == QLatin1String("plan arm")) {
        changed.payload.enabled = false; // the same Panda, its arm learned
        args = plan;
    } else if (kind == QLatin1String("learn arm")) {
        changed.payload.enabled = false;
    } else if (kind == QLatin1String("arm history")) {
        Scenario arm = changed;
        arm.payload.enabled = false;
        writeScenarioFile(path("arm.json"), arm);
        const Result armPlan = cli({QStringLiteral("plan"), QStringLiteral("--out"),
                                    QStringLiteral("arm"), QStringLiteral("--scenario"),
                                    QStringLiteral("arm.json"), QStringLiteral("--quiet")},
                                   dir.path());
        QVERIFY2(armPlan.exitCode == 0, qPrintable(armPlan.err));
        args = plan;
        args[2] = QStringLiteral("arm");
    } else if (kind == QLatin1String("estimate")) {
        args = plan + QStringList{QStringLiteral("--estimate"),
                                  QStringLiteral("ex/learnid-history/estimate-1.json")};
    } else if (kind == QLatin1String("link")) {
        changed.payload.link = QStringLiteral("panda_link6");
        args = plan;
    } else if (kind == QLatin1String("arm model")) {
        changed.initialParameters = m_s.scenario.initialParameters;
        changed.initialParameters[3] *= 1.01;
        args = plan;
    } else if (kind == QLatin1String("prior")) {
        changed.payload.mass = 1.3;
    } else if (kind == QLatin1String("path")) {
        changed.restAfter += 0.2;
    } else if (kind == QLatin1String("six joints")) {
        write(path("ex/run-1.csv"), test::logCsv(m_planId1, m_record1, -1, 6));
    } else if (kind == QLatin1String("two logs")) {
        args << QStringLiteral("--trial-log") << QStringLiteral("ex/run-1.csv");
    } else if (kind == QLatin1String("short")) {
        write(path("ex/run-1.csv"),
              test::logCsv(m_planId1, m_record1, int(m_record1.samples()) - 10));
    } else if (kind == QLatin1String("refused")) {
        changed.torqueLimits = Eigen::VectorXd::Constant(7, 1.0); // far below the planned peaks
        args = plan;
        args[2] = QStringLiteral("fresh");
    }
    writeScenarioFile(path("s.json"), changed);
    const QStringList before = snapshot(dir.path());
    const Result r = cli(args, dir.path());
    QCOMPARE(r.exitCode, exitCode);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    if (exitCode == 3)
        QVERIFY(r.err.contains(QStringLiteral("no files written")));
    QCOMPARE(snapshot(dir.path()), before);
    // The unchanged base learns the log as given.
    if (kind == QLatin1String("two logs")) {
        const Result ok = cli(args.mid(0, 5), dir.path());
        QVERIFY2(ok.exitCode == 0, qPrintable(ok.err));
        QVERIFY(ok.out.contains(QStringLiteral("The payload after trial 1")));
    }
}

void TestCliLoopPayload::stoppedAtTheTrackingLimit_isLearnedUpToTheStop()
{
    // The controller stopped trial 1 at its tracking limit 10 samples before its end: the
    // session learns from the record up to the stop (as `run` does), and says so.
    QTemporaryDir dir;
    copyTree(m_base.path(), dir.path());
    write(dir.filePath(QStringLiteral("ex/run-1.csv")),
          "# stopped-by: tracking-limit\n" +
              test::logCsv(m_planId1, m_record1, int(m_record1.samples()) - 10));
    const Result r =
        cli({QStringLiteral("learn"), QStringLiteral("--trial-log"), QStringLiteral("ex/run-1.csv"),
             QStringLiteral("--scenario"), QStringLiteral("s.json")},
            dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains(QStringLiteral("(stopped at the limit: learned up to the stop)")),
             qPrintable(r.out));
    QVERIFY(r.out.contains(QStringLiteral("The payload after trial 1")));

    // Trial 2 stops too: learning from the records did not help, the gains must; the series
    // ends (exit 3) and nothing is written.
    const QStringList scenario{QStringLiteral("--scenario"), QStringLiteral("s.json")};
    const Result planned = cli(QStringList{QStringLiteral("plan"), QStringLiteral("--out"),
                                           QStringLiteral("ex"), QStringLiteral("--quiet")} +
                                   scenario,
                               dir.path());
    QVERIFY2(planned.exitCode == 0, qPrintable(planned.err));
    const PlanCsv plan = readPlanCsvFile(dir.filePath(QStringLiteral("ex/plan.csv")));
    const TrialRecord record = makeSimulatedRobot(m_s.scenario, m_s.model)
                                   ->runTrial(test::planFromCsv(plan, m_s.scenario), {});
    write(dir.filePath(QStringLiteral("ex/run-2.csv")),
          "# stopped-by: tracking-limit\n" +
              test::logCsv(plan.planId, record, int(record.samples()) - 10));
    const QStringList before = snapshot(dir.path());
    const Result again = cli(QStringList{QStringLiteral("learn"), QStringLiteral("--trial-log"),
                                         QStringLiteral("ex/run-2.csv")} +
                                 scenario,
                             dir.path());
    QCOMPARE(again.exitCode, 3);
    QVERIFY2(again.err.contains(QStringLiteral("the second stop in a row: the gains do not hold "
                                               "the payload")),
             qPrintable(again.err));
    QCOMPARE(snapshot(dir.path()), before);
}

QTEST_GUILESS_MAIN(TestCliLoopPayload)
#include "tst_cli_loop_payload.moc"
