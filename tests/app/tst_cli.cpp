// End-to-end tests of the learnid-cli executable: what a user types, what it prints and writes.
#include "../support/ToolRun.h"
#include "io/ParameterFile.h"
#include "io/ScenarioFile.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

class TestCli : public QObject
{
    Q_OBJECT

private slots:
    void printedScenario_runsLikeTheDefault();
    void run_writesReportParameterFileAndTrialCsv();
    void urdfRobot_warnsAboutItsModelAndExportsItsStandardParameters();
    void paperEstimator_showsTableOneShape();
    void badInput_exitsWithMessageAndWritesNothing_data();
    void badInput_exitsWithMessageAndWritesNothing();
    void unstableController_isRefusedAndWritesNothing();
    void abortedSession_writesItsOutputsMarkedEndedEarly();
    void unknownOption_printsUsage();
    void commandHelp_listsThatCommandsOptions_data();
    void commandHelp_listsThatCommandsOptions();
    void outputPaths_anywhereTheUserChooses();

private:
    using Result = learnid::test::ToolRun;
    Result cli(const QStringList &args, const QString &dir) const
    {
        return learnid::test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, dir);
    }
    static QJsonObject readJson(const QString &path)
    {
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            return {};
        return QJsonDocument::fromJson(f.readAll()).object();
    }
    static void write(const QString &path, const QByteArray &data)
    {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
    }
    static QList<double> numbers(const QJsonValue &v)
    {
        QList<double> out;
        for (const QJsonValue &x : v.toArray())
            out << x.toDouble();
        return out;
    }
};

void TestCli::printedScenario_runsLikeTheDefault()
{
    QTemporaryDir dir;
    const Result printed = cli({QStringLiteral("scenario"), QStringLiteral("--print")}, dir.path());
    QCOMPARE(printed.exitCode, 0);
    QJsonParseError error;
    QJsonDocument::fromJson(printed.out.toUtf8(), &error);
    QCOMPARE(error.error, QJsonParseError::NoError);
    write(dir.filePath(QStringLiteral("paper.json")), printed.out.toUtf8());

    const Result a =
        cli({QStringLiteral("run"), QStringLiteral("--iterations"), QStringLiteral("2"),
             QStringLiteral("--report"), QStringLiteral("a.json"), QStringLiteral("--quiet")},
            dir.path());
    const Result b =
        cli({QStringLiteral("run"), QStringLiteral("--scenario"), QStringLiteral("paper.json"),
             QStringLiteral("--iterations"), QStringLiteral("2"), QStringLiteral("--report"),
             QStringLiteral("b.json"), QStringLiteral("--quiet")},
            dir.path());
    QCOMPARE(a.exitCode, 0);
    QCOMPARE(b.exitCode, 0);
    QCOMPARE(a.out, b.out);
    QCOMPARE(readJson(dir.filePath(QStringLiteral("a.json"))).value(QStringLiteral("final")),
             readJson(dir.filePath(QStringLiteral("b.json"))).value(QStringLiteral("final")));
}

void TestCli::run_writesReportParameterFileAndTrialCsv()
{
    QTemporaryDir dir;
    const Result r = cli({QStringLiteral("run"), QStringLiteral("--iterations"),
                          QStringLiteral("3"), QStringLiteral("--report"),
                          QStringLiteral("out/report.json"), QStringLiteral("--export"),
                          QStringLiteral("out/params.json"), QStringLiteral("--trial-csv"),
                          QStringLiteral("out/trials"), QStringLiteral("--apply")},
                         dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(r.err.contains(QStringLiteral("trial 2"))); // progress on stderr
    QVERIFY(r.out.contains(QStringLiteral("trial")));   // the table on stdout

    const QJsonObject report = readJson(dir.filePath(QStringLiteral("out/report.json")));
    QCOMPARE(report.value(QStringLiteral("estimator")).toString(), QStringLiteral("improved"));
    QCOMPARE(numbers(report.value(QStringLiteral("truth"))), (QList<double>{20, 5, 8}));
    const QJsonArray trials = report.value(QStringLiteral("trials")).toArray();
    QCOMPARE(trials.size(), 3);
    QCOMPARE(numbers(trials.at(0).toObject().value(QStringLiteral("phi"))),
             (QList<double>{40, 20, 30}));
    for (int k = 0; k < 3; ++k) {
        const QJsonObject t = trials.at(k).toObject();
        QCOMPARE(t.value(QStringLiteral("index")).toInt(), k);
        QCOMPARE(t.value(QStringLiteral("maxTrackingErrorDeg")).toArray().size(), 2);
        QCOMPARE(t.value(QStringLiteral("rank")).toInt(), 3);
        QVERIFY(t.value(QStringLiteral("samples")).toInt() > 1000);
        QVERIFY(t.value(QStringLiteral("durationS")).toDouble() > 3.0);
        QCOMPARE(t.value(QStringLiteral("phiStd")).toArray().size(), 3);
    }
    const QList<double> final =
        numbers(report.value(QStringLiteral("final")).toObject().value(QStringLiteral("phi")));
    const QList<double> truth{20, 5, 8};
    for (int i = 0; i < 3; ++i)
        QVERIFY2(std::abs(final[i] / truth[i] - 1.0) < 5e-4, qPrintable(QString::number(final[i])));

    QFile params(dir.filePath(QStringLiteral("out/params.json")));
    QVERIFY(params.open(QIODevice::ReadOnly));
    const learnid::ParameterFileContent content =
        learnid::parameterFileFromJson(params.readAll(), QStringLiteral("params.json"));
    for (int i = 0; i < 3; ++i)
        QCOMPARE(content.values[i], final[i]);
    QVERIFY(QFile::exists(dir.filePath(QStringLiteral("out/params.dcf"))));

    for (int k = 0; k < 3; ++k) {
        QFile csv(dir.filePath(
            QStringLiteral("out/trials/trial-%1.csv").arg(k, 3, 10, QLatin1Char('0'))));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const int lines = csv.readAll().count('\n');
        QCOMPARE(lines, trials.at(k).toObject().value(QStringLiteral("samples")).toInt() + 1);
    }
}

void TestCli::urdfRobot_warnsAboutItsModelAndExportsItsStandardParameters()
{
    // The double pendulum, a URDF robot whose published link 2 has a negative inertia.
    learnid::Scenario s;
    s.model = QStringLiteral("double-pendulum");
    s.torqueLimits.resize(0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.path.kind = learnid::PathKind::Waypoints;
    s.path.waypoints = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1.2, -0.8), Eigen::Vector2d(0, 0)};
    s.planningFraction = 0.5;
    s.controller.kp = Eigen::Vector2d(20, 8);
    s.controller.ki = Eigen::Vector2d(2, 1);
    s.controller.kd = Eigen::Vector2d(1.5, 0.6);
    s.controller.lambda = 1000;
    s.maxTrackingErrorDeg = 5;
    QTemporaryDir dir;
    write(dir.filePath(QStringLiteral("pendulum.json")), learnid::scenarioToJson(s));
    const Result r =
        cli({QStringLiteral("run"), QStringLiteral("--scenario"), QStringLiteral("pendulum.json"),
             QStringLiteral("--iterations"), QStringLiteral("1"), QStringLiteral("--report"),
             QStringLiteral("r.json"), QStringLiteral("--export"), QStringLiteral("p.json")},
            dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    // A warning, not a refusal (docs/robots.md §7).
    QVERIFY2(r.err.contains(QStringLiteral("learnid-cli: warning: the URDF as a real robot: link 2 "
                                           "(link2): no mass distribution has its inertia")),
             qPrintable(r.err));

    // The report and the parameter file list the same standard parameters: 10 per link, then
    // viscous and Coulomb friction per joint, each with where it came from.
    const QJsonArray standard = readJson(dir.filePath(QStringLiteral("r.json")))
                                    .value(QStringLiteral("final"))
                                    .toObject()
                                    .value(QStringLiteral("standardParameters"))
                                    .toArray();
    QCOMPARE(standard.size(), 24);
    QFile params(dir.filePath(QStringLiteral("p.json")));
    QVERIFY(params.open(QIODevice::ReadOnly));
    const learnid::ParameterFileContent content =
        learnid::parameterFileFromJson(params.readAll(), QStringLiteral("p.json"));
    QCOMPARE(content.standardParameters.size(), 24);
    for (int i = 0; i < 24; ++i) {
        const QJsonObject o = standard.at(i).toObject();
        QCOMPARE(o.value(QStringLiteral("name")).toString(), content.standardParameters.at(i).name);
        QCOMPARE(o.value(QStringLiteral("value")).toDouble(), content.standardValues[i]);
        const QJsonValue determined = o.value(QStringLiteral("determined"));
        const QString source = o.value(QStringLiteral("source")).toString();
        QCOMPARE(source, determined.isNull()            ? QStringLiteral("unknown")
                         : determined.toDouble() >= 0.5 ? QStringLiteral("data")
                                                        : QStringLiteral("prior"));
    }
    QCOMPARE(content.standardParameters.at(0).name.left(1), QStringLiteral("m"));
    QVERIFY(content.standardValues[0] > 0.0);
}

// docs/method.md §2.1 and paper Table 1: after one learning, a within ~1 %, b about -25 %,
// c about -10 %.
void TestCli::paperEstimator_showsTableOneShape()
{
    QTemporaryDir dir;
    const Result r =
        cli({QStringLiteral("run"), QStringLiteral("--estimator"), QStringLiteral("paper"),
             QStringLiteral("--iterations"), QStringLiteral("1"), QStringLiteral("--report"),
             QStringLiteral("r.json"), QStringLiteral("--quiet")},
            dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QJsonObject report = readJson(dir.filePath(QStringLiteral("r.json")));
    QCOMPARE(report.value(QStringLiteral("estimator")).toString(), QStringLiteral("paper"));
    const QList<double> phi =
        numbers(report.value(QStringLiteral("final")).toObject().value(QStringLiteral("phi")));
    QVERIFY(std::abs(phi[0] / 20.0 - 1.0) < 0.02);
    QVERIFY(phi[1] / 5.0 - 1.0 > -0.30 && phi[1] / 5.0 - 1.0 < -0.20);
    QVERIFY(phi[2] / 8.0 - 1.0 > -0.14 && phi[2] / 8.0 - 1.0 < -0.06);
    // The table's last row is estimate 1 with its error against the truth.
    QVERIFY(r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts).size() == 3);
}

void TestCli::badInput_exitsWithMessageAndWritesNothing_data()
{
    QTest::addColumn<QByteArray>("scenario"); // written to s.json when not empty
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("expected"); // must appear in the error message
    const QStringList run{QStringLiteral("run"), QStringLiteral("--scenario"),
                          QStringLiteral("s.json")};
    QTest::newRow("missing file") << QByteArray()
                                  << QStringList{QStringLiteral("run"),
                                                 QStringLiteral("--scenario"),
                                                 QStringLiteral("nope.json")}
                                  << QStringLiteral("nope.json");
    QTest::newRow("malformed json")
        << QByteArray("{\n  \"robot\": {\n    \"model\": \n}\n") << run << QStringLiteral("line");
    QTest::newRow("unknown key") << QByteArray(R"({"controller": {"kpp": [1, 2]}})") << run
                                 << QStringLiteral("controller.kpp");
    QTest::newRow("wrong array length") << QByteArray(R"({"robot": {"torqueLimits": [8]}})") << run
                                        << QStringLiteral("robot.torqueLimits");
    QTest::newRow("infinite gain") << QByteArray(R"({"controller": {"kp": [1e999, 5000]}})") << run
                                   << QStringLiteral("controller.kp[0]");
    QTest::newRow("negative gain") << QByteArray(R"({"controller": {"kp": [4500, -5]}})") << run
                                   << QStringLiteral("controller.kp[1]");
    QTest::newRow("non-positive limit") << QByteArray(R"({"robot": {"torqueLimits": [8, 0]}})")
                                        << run << QStringLiteral("robot.torqueLimits[1]");
    QTest::newRow("string for number") << QByteArray(R"({"controller": {"lambda": "nan"}})") << run
                                       << QStringLiteral("controller.lambda");
    QTest::newRow("unknown law") << QByteArray()
                                 << QStringList{QStringLiteral("run"),
                                                QStringLiteral("--estimator"),
                                                QStringLiteral("magic")}
                                 << QStringLiteral("magic");
    QTest::newRow("zero iterations")
        << QByteArray()
        << QStringList{QStringLiteral("run"), QStringLiteral("--iterations"), QStringLiteral("0")}
        << QStringLiteral("--iterations");
    QTest::newRow("empty report path")
        << QByteArray() << QStringList{QStringLiteral("run"), QStringLiteral("--report"), QString()}
        << QStringLiteral("--report: no path given");
}

void TestCli::badInput_exitsWithMessageAndWritesNothing()
{
    QFETCH(QByteArray, scenario);
    QFETCH(QStringList, args);
    QFETCH(QString, expected);
    QTemporaryDir parent;
    const QString ws = parent.filePath(QStringLiteral("ws"));
    QVERIFY(QDir().mkpath(ws));
    if (!scenario.isEmpty())
        write(QDir(ws).filePath(QStringLiteral("s.json")), scenario);
    const Result r =
        cli(args + QStringList{QStringLiteral("--export"), QStringLiteral("p.json")}, ws);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(expected), qPrintable(r.err));
    QVERIFY(!QFile::exists(QDir(ws).filePath(QStringLiteral("p.json"))));
}

// The paper's lambda = 40 is unstable for the true inertia (docs/method.md §3): the session
// refuses the trial once the estimate nears the truth and exits non-zero; without outputs asked
// for it writes nothing.
void TestCli::unstableController_isRefusedAndWritesNothing()
{
    QTemporaryDir dir;
    write(dir.filePath(QStringLiteral("s.json")), R"({"controller": {"lambda": 40}})");
    const Result r =
        cli({QStringLiteral("run"), QStringLiteral("--scenario"), QStringLiteral("s.json")},
            dir.path());
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains(QStringLiteral("unstable")), qPrintable(r.err));
    QVERIFY(r.err.contains(QStringLiteral("no files written")));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("s.json")});
}

// A session that ends early writes the outputs asked for, marked so (issue 23, part 5): the
// report says why, the trial CSVs hold the aborted trial's record up to the stop; nothing was
// learned, so no parameter file. A drive fault at sample 400 of trial 0 is not learned from.
void TestCli::abortedSession_writesItsOutputsMarkedEndedEarly()
{
    QTemporaryDir dir;
    write(dir.filePath(QStringLiteral("s.json")), R"({"safety": {"maxTrackingErrorDeg": 0.02}})");
    const Result r =
        cli({QStringLiteral("run"), QStringLiteral("--scenario"), QStringLiteral("s.json"),
             QStringLiteral("--iterations"), QStringLiteral("2"), QStringLiteral("--report"),
             QStringLiteral("r.json"), QStringLiteral("--trial-csv"), QStringLiteral("trials"),
             QStringLiteral("--export"), QStringLiteral("p.json")},
            dir.path());
    // Trial 0 stops at the limit and is learned from; trial 1 completes: exit 0, all written,
    // the row marked.
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains(QStringLiteral("learned from a partial trial")), qPrintable(r.out));
    QVERIFY2(r.err.contains(QStringLiteral("learned from its first")), qPrintable(r.err));
    const QJsonObject report = readJson(dir.filePath(QStringLiteral("r.json")));
    QVERIFY(!report.contains(QStringLiteral("endedEarly")));
    QVERIFY(report.value(QStringLiteral("trials"))
                .toArray()
                .at(0)
                .toObject()
                .value(QStringLiteral("learnedFromPartialTrial"))
                .toBool());
    QVERIFY(QFile::exists(dir.filePath(QStringLiteral("p.json"))));

    // The same with a limit so tight the record is too short to learn from: ended early.
    QTemporaryDir early;
    write(early.filePath(QStringLiteral("s.json")),
          R"({"safety": {"maxTrackingErrorDeg": 0.0001}})");
    const Result e =
        cli({QStringLiteral("run"), QStringLiteral("--scenario"), QStringLiteral("s.json"),
             QStringLiteral("--report"), QStringLiteral("r.json"), QStringLiteral("--trial-csv"),
             QStringLiteral("trials"), QStringLiteral("--export"), QStringLiteral("p.json")},
            early.path());
    QCOMPARE(e.exitCode, 3);
    QVERIFY2(e.err.contains(QStringLiteral("too short to learn from")), qPrintable(e.err));
    QVERIFY2(e.err.contains(QStringLiteral("p.json not written: nothing was learned")),
             qPrintable(e.err));
    QVERIFY(e.err.contains(QStringLiteral("(the session ended early)")));
    const QJsonObject r2 = readJson(early.filePath(QStringLiteral("r.json")));
    QVERIFY2(
        r2.value(QStringLiteral("endedEarly")).toString().contains(QStringLiteral("too short")),
        qPrintable(r2.value(QStringLiteral("endedEarly")).toString()));
    QFile csv(early.filePath(QStringLiteral("trials/trial-000.csv")));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const qsizetype rows = csv.readAll().count('\n') - 1; // the header line
    QVERIFY2(rows > 0 && rows < 100 + 16, qPrintable(QString::number(rows)));
    QVERIFY(!QFile::exists(early.filePath(QStringLiteral("p.json"))));
}

void TestCli::unknownOption_printsUsage()
{
    QTemporaryDir dir;
    const Result r = cli({QStringLiteral("run"), QStringLiteral("--frobnicate")}, dir.path());
    QCOMPARE(r.exitCode, 1);
    QVERIFY(r.err.contains(QStringLiteral("frobnicate")));
    QVERIFY(r.err.contains(QStringLiteral("Usage")));
}

void TestCli::commandHelp_listsThatCommandsOptions_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QStringList>("options"); // each must be listed
    QTest::addColumn<QStringList>("absent");  // other commands' options, not listed
    QTest::newRow("run --help") << QStringList{QStringLiteral("run"), QStringLiteral("--help")}
                                << QStringList{QStringLiteral("--scenario"),
                                               QStringLiteral("--robot"),
                                               QStringLiteral("--can-sync-timeout"),
                                               QStringLiteral("--workspace")}
                                << QStringList{QStringLiteral("--candump"),
                                               QStringLiteral("--print")};
    QTest::newRow("replay -h") << QStringList{QStringLiteral("replay"), QStringLiteral("-h")}
                               << QStringList{QStringLiteral("--candump"),
                                              QStringLiteral("--nodes")}
                               << QStringList{QStringLiteral("--robot"), QStringLiteral("--print")};
    QTest::newRow("scenario --help")
        << QStringList{QStringLiteral("scenario"), QStringLiteral("--help")}
        << QStringList{QStringLiteral("--print"), QStringLiteral("--robot")}
        << QStringList{QStringLiteral("--scenario"), QStringLiteral("--estimator")};
}

void TestCli::commandHelp_listsThatCommandsOptions()
{
    QFETCH(QStringList, args);
    QFETCH(QStringList, options);
    QFETCH(QStringList, absent);
    QTemporaryDir dir;
    const Result r = cli(args, dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.startsWith(QStringLiteral("Usage: learnid-cli %1 [options]").arg(args.first())),
             qPrintable(r.out));
    for (const QString &o : options)
        QVERIFY2(r.out.contains(o), qPrintable(o + QStringLiteral(" missing in:\n") + r.out));
    for (const QString &o : absent)
        QVERIFY2(!r.out.contains(o), qPrintable(o + QStringLiteral(" listed in:\n") + r.out));
    QVERIFY(r.err.isEmpty());
    QCOMPARE(QDir(dir.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries).size(), 0);
}

// A path typed on the command line is the user's choice: outside the current folder, absolute,
// or through "..", it is written there (all files or none, as ever).
void TestCli::outputPaths_anywhereTheUserChooses()
{
    QTemporaryDir parent;
    const QString cwd = parent.filePath(QStringLiteral("cwd"));
    const QString elsewhere = parent.filePath(QStringLiteral("elsewhere"));
    QVERIFY(QDir().mkpath(cwd) && QDir().mkpath(elsewhere));
    const QString report = QDir(elsewhere).filePath(QStringLiteral("r.json"));
    const Result r =
        cli({QStringLiteral("run"), QStringLiteral("--iterations"), QStringLiteral("1"),
             QStringLiteral("--report"), report, QStringLiteral("--export"),
             QStringLiteral("../p.json"), QStringLiteral("--quiet")},
            cwd);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(readJson(report).value(QStringLiteral("estimator")).toString(),
             QStringLiteral("improved"));
    QVERIFY(QFile::exists(parent.filePath(QStringLiteral("p.json"))));
    QVERIFY(QFile::exists(parent.filePath(QStringLiteral("p.dcf"))));
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
