// `learnid-cli scenario --print --robot R`: a complete starter scenario for any arm, as a CLI user
// gets it. For each built-in robot and for URDF files, the printed JSON reads back through the
// scenario reader to the same JSON, its gains and path are the window's (scenarioForRobot), its
// waypoints lie within the joint limits, the pre-trial check passes, and a simulated session with
// it completes trial 0 within the scenario's abort limit. Bad robot names and URDFs are named.
#include "../support/SharedData.h"
#include "../support/ToolRun.h"
#include "io/ScenarioFile.h"
#include "model/ModelFactory.h"
#include "session/CommissioningSession.h"
#include "session/RobotScenario.h"
#include "session/ScenarioRobot.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

class TestCliScenario : public QObject
{
    Q_OBJECT

private slots:
    void printedScenario_runsItsFirstTrial_data();
    void printedScenario_runsItsFirstTrial();
    void badRobot_isNamed_data();
    void badRobot_isNamed();
    void payload_printsItsSectionAndTheGainsForIt();
    void samplePeriod_designsForTheRobotsClock();

private:
    using Result = learnid::test::ToolRun;
    static Result cli(const QStringList &args)
    {
        return learnid::test::runTool(QStringLiteral(LEARNID_CLI_PATH), args);
    }
    QTemporaryDir m_dir;
    // A URDF file outside the tool: the built-in double pendulum's, copied.
    QString urdfCopy()
    {
        const QString path = m_dir.filePath(QStringLiteral("my pendulum.urdf"));
        QFile::remove(path);
        QFile::copy(QStringLiteral(":/robots/double-pendulum.urdf"), path);
        return path;
    }
};

void TestCliScenario::printedScenario_runsItsFirstTrial_data()
{
    QTest::addColumn<QString>("robot");
    QTest::addColumn<QString>("model");
    QTest::newRow("paper") << "paper"
                           << "paper-2link";
    QTest::newRow("panda") << "panda"
                           << "panda";
    QTest::newRow("puma560") << "puma560"
                             << "puma560";
    QTest::newRow("double-pendulum") << "double-pendulum"
                                     << "double-pendulum";
    QTest::newRow("URDF file") << urdfCopy() << "urdf";
    const QString kuka = learnid::test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (!kuka.isEmpty())
        QTest::newRow("KUKA LWR4+ URDF") << kuka << "urdf";
}

void TestCliScenario::printedScenario_runsItsFirstTrial()
{
    QFETCH(QString, robot);
    QFETCH(QString, model);
    const Result printed = cli(
        {QStringLiteral("scenario"), QStringLiteral("--print"), QStringLiteral("--robot"), robot});
    QVERIFY2(printed.exitCode == 0, qPrintable(printed.err));
    QVERIFY(printed.err.isEmpty());
    const QByteArray json = printed.out.toUtf8();
    // Read as a scenario file anywhere (the URDF's path is absolute), and written back the same.
    const Scenario read = scenarioFromJson(json, QStringLiteral("printed"), QDir::rootPath());
    QCOMPARE(read.model, model);
    QCOMPARE(QString::fromUtf8(scenarioToJson(read)), printed.out);
    // The window's starter for that robot: its gains and path.
    const Scenario window = model == QLatin1String("urdf") ? scenarioForRobot(model, read.urdf)
                                                           : scenarioForRobot(model);
    QCOMPARE(read.controller.kp, window.controller.kp);
    QCOMPARE(read.controller.ki, window.controller.ki);
    QCOMPARE(read.controller.kd, window.controller.kd);
    QCOMPARE(read.path.waypoints, window.path.waypoints);
    const auto robotModel = makeRobotModel(read.model, read.urdf);
    QCOMPARE(waypointLimitError(*robotModel, read.path.waypoints), QString());
    if (model != QLatin1String("paper-2link")) {
        QCOMPARE(read.path.kind, PathKind::Waypoints);
        QCOMPARE(int(read.controller.kp.size()), robotModel->dof());
        QCOMPARE(read.gentleTrials, 1); // a robot new to the tool starts gently
    }

    Scenario s = withRobotDefaults(read, *robotModel);
    s.iterations = 1;
    CommissioningSession session(s, robotModel, makeSimulatedRobot(s, robotModel));
    const PreTrialCheck check = session.checkNextTrial();
    QVERIFY2(check.passed(), qPrintable(check.reason()));
    const TrialResult &trial = session.runTrial();
    QVERIFY2(trial.record.completed(), qPrintable(trial.message));
    const double error = trial.maxTrackingErrorDeg.maxCoeff();
    qInfo("%s: trial 0 in %.2f s, max tracking error %.3f deg (limit %g deg)", qPrintable(model),
          trial.plan().motionDuration, error, s.maxTrackingErrorDeg);
    QVERIFY(error > 0.0 && error < s.maxTrackingErrorDeg);
}

void TestCliScenario::badRobot_isNamed_data()
{
    QTest::addColumn<QString>("robot");
    QTest::addColumn<QString>("expected");
    QTest::newRow("unknown name")
        << "ur5"
        << "learnid-cli: error: --robot ur5: unknown robot \"ur5\"; known: paper, "
           "paper-2link-urdf, double-pendulum, puma560, panda, or a URDF file (FILE.urdf)";
    const QString missing = m_dir.filePath(QStringLiteral("missing.urdf"));
    QTest::newRow("missing URDF") << missing
                                  << QStringLiteral("learnid-cli: error: --robot %1: %1: cannot "
                                                    "read the URDF: No such file or directory")
                                         .arg(missing);
    const QString broken = m_dir.filePath(QStringLiteral("broken.urdf"));
    QFile file(broken);
    if (file.open(QIODevice::WriteOnly))
        file.write("<robot name=\"x\"><link name=\"a\">");
    file.close();
    QTest::newRow("not a URDF") << broken
                                << QStringLiteral("learnid-cli: error: --robot %1: %1").arg(broken);
}

void TestCliScenario::badRobot_isNamed()
{
    QFETCH(QString, robot);
    QFETCH(QString, expected);
    const Result r = cli(
        {QStringLiteral("scenario"), QStringLiteral("--print"), QStringLiteral("--robot"), robot});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.startsWith(expected), qPrintable(r.err));
    QCOMPARE(r.out, QString()); // nothing half-printed
}

void TestCliScenario::payload_printsItsSectionAndTheGainsForIt()
{
    const QStringList base{QStringLiteral("scenario"), QStringLiteral("--print"),
                           QStringLiteral("--robot"), QStringLiteral("panda")};
    const Result r =
        cli(base + QStringList{QStringLiteral("--payload"), QStringLiteral("--payload-mass"),
                               QStringLiteral("1.2"), QStringLiteral("--payload-com"),
                               QStringLiteral("0,0,0.05")});
    QCOMPARE(r.exitCode, 0);
    const Scenario s = scenarioFromJson(r.out.toUtf8(), QStringLiteral("stdout"));
    QVERIFY(s.payload.enabled);
    QCOMPARE(s.payload.mass, 1.2);
    QCOMPARE(s.payload.com, Eigen::Vector3d(0.0, 0.0, 0.05));
    // The same as the starter the library makes for that prior (tst_payloadstarter runs it).
    PayloadSettings prior;
    prior.enabled = true;
    prior.mass = 1.2;
    prior.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    QCOMPARE(r.out.toUtf8(), scenarioToJson(scenarioForRobot(QStringLiteral("panda"), {}, prior)));

    const struct
    {
        QStringList options;
        QString message;
    } bad[] = {
        {{QStringLiteral("--payload-mass"), QStringLiteral("1")},
         QStringLiteral("learnid-cli: error: --payload-mass: needs --payload")},
        {{QStringLiteral("--payload"), QStringLiteral("--payload-mass"), QStringLiteral("-1")},
         QStringLiteral("learnid-cli: error: --payload-mass: the payload's mass must be a "
                        "positive number")},
        {{QStringLiteral("--payload"), QStringLiteral("--payload-mass"), QStringLiteral("1"),
          QStringLiteral("--payload-link"), QStringLiteral("gripper")},
         QStringLiteral("learnid-cli: error: --robot panda: payload.link: payload link 'gripper' "
                        "is not a moving link")},
        {{QStringLiteral("--payload"), QStringLiteral("--payload-mass"), QStringLiteral("1"),
          QStringLiteral("--baseline-log"), QStringLiteral("b.csv")},
         QStringLiteral("learnid-cli: error: Unknown option 'baseline-log'.")},
    };
    for (const auto &b : bad) {
        const Result e = cli(base + b.options);
        QVERIFY2(e.exitCode == 2 || e.exitCode == 1, qPrintable(e.err));
        QVERIFY2(e.err.startsWith(b.message), qPrintable(e.err));
        QCOMPARE(e.out, QString());
    }
    const Result paper =
        cli({QStringLiteral("scenario"), QStringLiteral("--print"), QStringLiteral("--robot"),
             QStringLiteral("paper"), QStringLiteral("--payload"), QStringLiteral("--payload-mass"),
             QStringLiteral("1")});
    QCOMPARE(paper.exitCode, 2);
    QVERIFY2(
        paper.err.startsWith(QStringLiteral("learnid-cli: error: --robot paper: payload: only a "
                                            "URDF robot carries a payload")),
        qPrintable(paper.err));
}

void TestCliScenario::samplePeriod_designsForTheRobotsClock()
{
    // The Panda with 3 kg on a 4 ms bus: the starter the library designs for that clock
    // (tst_payloadstarter runs it), its period in the scenario, its pre-trial check passed.
    const QStringList args{QStringLiteral("scenario"),  QStringLiteral("--print"),
                           QStringLiteral("--robot"),   QStringLiteral("panda"),
                           QStringLiteral("--payload"), QStringLiteral("--payload-mass"),
                           QStringLiteral("3"),         QStringLiteral("--payload-com"),
                           QStringLiteral("0,0,0.05"),  QStringLiteral("--sample-period"),
                           QStringLiteral("4")};
    const Result r = cli(args);
    QCOMPARE(r.exitCode, 0);
    const Scenario s = scenarioFromJson(r.out.toUtf8(), QStringLiteral("stdout"));
    QCOMPARE(s.controller.samplePeriod, 0.004);
    PayloadSettings prior;
    prior.enabled = true;
    prior.mass = 3.0;
    prior.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    QCOMPARE(r.out.toUtf8(),
             scenarioToJson(scenarioForRobot(QStringLiteral("panda"), {}, prior, 0.004)));
    const Result at2ms = cli(args.mid(0, 9));
    QCOMPARE(at2ms.exitCode, 0);
    QVERIFY(r.out != at2ms.out);

    for (const QString &bad : {QStringLiteral("0"), QStringLiteral("-2"), QStringLiteral("fast"),
                               QStringLiteral("nan"), QStringLiteral("1000")}) {
        const Result e = cli(args.mid(0, 4) + QStringList{QStringLiteral("--sample-period"), bad});
        QCOMPARE(e.exitCode, 2);
        QVERIFY2(e.err.startsWith(QStringLiteral("learnid-cli: error: --sample-period: the "
                                                 "robot's clock must be a number of ms above 0 "
                                                 "and at most 100, not '%1'")
                                      .arg(bad)),
                 qPrintable(e.err));
        QCOMPARE(e.out, QString());
    }
    const Result paper = cli({QStringLiteral("scenario"), QStringLiteral("--print"),
                              QStringLiteral("--sample-period"), QStringLiteral("4")});
    QCOMPARE(paper.exitCode, 2);
    QVERIFY2(paper.err.contains(QStringLiteral("controller.samplePeriod: the paper scenario")),
             qPrintable(paper.err));
}

QTEST_GUILESS_MAIN(TestCliScenario)
#include "tst_cli_scenario.moc"
