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

// The trial rows `run` and `learn` print for a payload session: the update's CPU time (field 8)
// left out, it is the only field that is not the session's.
QStringList trialRows(const QString &out)
{
    static const QRegularExpression row(
        QStringLiteral("^\\s+(\\d+)\\s+(\\S+)\\s+(\\S+)\\s+(\\S+)\\s+(\\(\\S+, \\S+, \\S+\\))"
                       "\\s+(\\S+)\\s+(.+)$"),
        QRegularExpression::MultilineOption);
    QStringList rows;
    for (auto it = row.globalMatch(out); it.hasNext();) {
        const auto m = it.next();
        rows << QStringList{m.captured(1), m.captured(2), m.captured(3),
                            m.captured(4), m.captured(5), m.captured(7).trimmed()}
                    .join(QLatin1Char(' '));
    }
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
    void trialsThroughFiles_equalThePayloadSession();
    void badInput_isRefusedNamingItAndChangesNothing_data();
    void badInput_isRefusedNamingItAndChangesNothing();

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

void TestCliLoopPayload::trialsThroughFiles_equalThePayloadSession()
{
    QTemporaryDir dir;
    write(dir.filePath(QStringLiteral("s.json")),
          readFile(m_base.filePath(QStringLiteral("s.json"))));
    const QStringList scenario{QStringLiteral("--scenario"), QStringLiteral("s.json")};
    const int trials = 3;
    const auto controller = makeSimulatedRobot(m_s.scenario, m_s.model);
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
        QVERIFY(planned.out.contains(
            k == 0 ? QStringLiteral("the payload's prior")
                   : QStringLiteral("learned from trials 0 to %1").arg(k - 1)));
        const QByteArray check = readFile(dir.filePath(QStringLiteral("exchange/check.txt")));
        QVERIFY(planned.out.startsWith(QString::fromUtf8(check)));
        const PlanCsv plan = readPlanCsvFile(dir.filePath(QStringLiteral("exchange/plan.csv")));
        const TrialRecord record = controller->runTrial(test::planFromCsv(plan, m_s.scenario), {});
        QVERIFY2(record.completed(), qPrintable(record.message));
        const QString log = QStringLiteral("exchange/run-%1.csv").arg(k);
        write(dir.filePath(log), test::logCsv(plan.planId, record));
        learned =
            cli(QStringList{QStringLiteral("learn"), QStringLiteral("--trial-log"), log} + scenario,
                dir.path());
        QVERIFY2(learned.exitCode == 0, qPrintable(learned.err));
        QVERIFY2(learned.err.contains(
                     QStringLiteral("trial %1 (plan %2) learned").arg(k).arg(plan.planId)),
                 qPrintable(learned.err));
    }

    // The session that runs the same trials on the simulated robot itself.
    PayloadSession session(m_s.scenario, m_s.model, makeSimulatedRobot(m_s.scenario, m_s.model));
    QVERIFY(session.runTrials(trials));
    const QDir history(dir.filePath(QStringLiteral("exchange/learnid-history")));
    const LoopHistory index =
        loopHistoryFromJson(readFile(history.filePath(QStringLiteral("history.json"))), {});
    QCOMPARE(index.payloadLink, QStringLiteral("panda_link7"));
    QCOMPARE(index.trials.size(), trials);
    QVERIFY(index.pendingPlans.isEmpty());
    for (int k = 0; k < trials; ++k) {
        const PayloadTrial &t = session.history().at(size_t(k));
        QCOMPARE(index.trials.at(k).planId, planIdOf(t.plan()));
        // Bit for bit: the logs answer exactly as the simulated robot did.
        QVERIFY(index.trials.at(k).maxTrackingErrorDeg == t.maxTrackingErrorDeg);
        QVERIFY(index.trials.at(k).rmsTrackingErrorDeg == t.rmsTrackingErrorDeg);
    }
    // Estimate k: the arm held fixed plus the payload the session had before trial k.
    const PayloadBody prior = payloadBody(session.prior().parameters());
    for (int k = 0; k <= trials; ++k) {
        const QString path = history.filePath(QStringLiteral("estimate-%1.json").arg(k));
        QVERIFY(readParameterFile(path).values == m_s.scenario.initialParameters);
        const ParameterFilePayload p = payloadOf(path);
        const PayloadBody &b =
            k == 0 ? prior : session.history().at(size_t(k - 1)).fit->estimate.body;
        QCOMPARE(p.link, QStringLiteral("panda_link7"));
        QVERIFY2(p.mass == b.mass && p.com == b.com,
                 qPrintable(QStringLiteral("estimate %1").arg(k)));
        QCOMPARE(p.inertiaAtCom[2], b.inertiaAtCom(1, 1));
        for (size_t i = 0; i < 10; ++i)
            QCOMPARE(p.identified[i],
                     k > 0 && session.history().at(size_t(k - 1)).fit->estimate.bodyIdentified[i]);
    }

    // learn prints what run prints: a row per trial, then the payload learned.
    const Result run = cli(QStringList{QStringLiteral("run")} + scenario, dir.path());
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    const QStringList rows = trialRows(learned.out);
    QCOMPARE(rows.size(), trials);
    QCOMPARE(rows, trialRows(run.out));
    QVERIFY(learned.out.contains(QStringLiteral("The payload after trial 2")));
    qInfo("%s", qPrintable(learned.out));
    // Learning works: trial 2 ran with a mass within 1 % and tracks far better than trial 0.
    const PayloadTrial &last = session.history().back();
    QVERIFY(std::abs(last.payloadUsed[0] - 1.5) < 0.015);
    QVERIFY(index.trials.at(2).maxTrackingErrorDeg.maxCoeff() <
            0.1 * index.trials.at(0).maxTrackingErrorDeg.maxCoeff());
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
    QTest::newRow("learn: stopped at the tracking limit")
        << "tracking limit" << 3 << QStringLiteral("trial 1 did not complete");
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
    } else if (kind == QLatin1String("tracking limit")) {
        write(path("ex/run-1.csv"),
              "# stopped-by: tracking-limit\n" +
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

QTEST_GUILESS_MAIN(TestCliLoopPayload)
#include "tst_cli_loop_payload.moc"
