// Scenario format 2: URDF robots, joint paths and the simulated real robot. Round trips, paths
// relative to the scenario file, version 1 still read, and every bad input named by its key.

#include "../support/ErrorOf.h"
#include "../support/NumericAssert.h"
#include "io/ScenarioFile.h"
#include "model/Error.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

const QString source = QStringLiteral("scenario.json");

void writeText(const QString &path, const QByteArray &text)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
}

QString errorOf(const QByteArray &json)
{
    return test::errorOf([&] { scenarioFromJson(json, source); });
}

const QByteArray pendulum = R"({"robot": {"model": "double-pendulum"},
  "path": {"kind": "waypoints", "waypoints": [[0, 0], [1, -0.5]]}})";

} // namespace

class TestScenarioChain : public QObject
{
    Q_OBJECT

private slots:
    void urdfScenario_roundTripsItsKeys();
    void omittedVectors_areLeftToTheRobot();
    void relativePaths_areRelativeToTheScenarioFile();
    void version1File_isStillRead();
    void badInput_isNamedByItsKey_data();
    void badInput_isNamedByItsKey();
};

void TestScenarioChain::urdfScenario_roundTripsItsKeys()
{
    Scenario s;
    s.model = QStringLiteral("puma560");
    s.urdf.baseLink = QStringLiteral("base_link");
    s.urdf.gravity = Eigen::Vector3d(0.1, 0, -9.8);
    s.urdf.jointTerms.armature = true;
    s.urdf.jointTerms.coulomb = false;
    s.urdf.jointTerms.coulombVelocity = 0.02;
    s.torqueLimits = Eigen::VectorXd::Constant(6, 20.0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.path.kind = PathKind::Waypoints;
    s.path.waypoints = {Eigen::VectorXd::Zero(6), Eigen::VectorXd::Constant(6, 0.5)};
    s.controller.kp = s.controller.ki = s.controller.kd = Eigen::VectorXd::Constant(6, 10.0);
    s.simulation.inertiaPerturbation = 0.25;
    s.controller.feedforwardTime = FeedforwardTime::MidSample;
    const QByteArray json = scenarioToJson(s);
    QVERIFY(json.contains("\"feedforwardTime\": \"midSample\""));
    QVERIFY(json.contains("\"schema\": \"learnid-scenario/2\""));
    QVERIFY(!json.contains("linkLengths")); // the line's keys are the paper arm's
    const Scenario r = scenarioFromJson(json, source);
    QCOMPARE(r.model, s.model);
    QCOMPARE(r.urdf.baseLink, s.urdf.baseLink);
    LEARNID_COMPARE_MATRIX(r.urdf.gravity, s.urdf.gravity, 0.0);
    QCOMPARE(r.urdf.jointTerms.armature, true);
    QCOMPARE(r.urdf.jointTerms.coulomb, false);
    QCOMPARE(r.urdf.jointTerms.coulombVelocity, 0.02);
    QCOMPARE(r.path.kind, PathKind::Waypoints);
    QCOMPARE(r.path.waypoints.size(), size_t(2));
    LEARNID_COMPARE_MATRIX(r.path.waypoints[1], s.path.waypoints[1], 0.0);
    LEARNID_COMPARE_MATRIX(r.torqueLimits, s.torqueLimits, 0.0);
    QCOMPARE(r.simulation.inertiaPerturbation, 0.25);
    QCOMPARE(r.controller.feedforwardTime, FeedforwardTime::MidSample);
    QCOMPARE(scenarioToJson(r), json);
    // Left out, the feedforward is the paper's, at the sample instant.
    QCOMPARE(scenarioFromJson(pendulum, source).controller.feedforwardTime,
             FeedforwardTime::SampleInstant);
    QVERIFY(scenarioToJson(Scenario()).contains("\"feedforwardTime\": \"sample\""));
}

void TestScenarioChain::omittedVectors_areLeftToTheRobot()
{
    const QByteArray json = R"({"robot": {"model": "double-pendulum"},
      "path": {"kind": "waypoints", "waypoints": [[0, 0], [1, -0.5]]}})";
    const Scenario s = scenarioFromJson(json, source);
    QCOMPARE(s.torqueLimits.size(), Eigen::Index(0));
    QCOMPARE(s.initialParameters.size(), Eigen::Index(0));
    QCOMPARE(s.simulation.trueParameters.size(), Eigen::Index(0));
}

void TestScenarioChain::relativePaths_areRelativeToTheScenarioFile()
{
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("robots")));
    QFile::copy(QStringLiteral(":/robots/double-pendulum.urdf"),
                dir.filePath(QStringLiteral("robots/arm.urdf")));
    writeText(dir.filePath(QStringLiteral("robots/path.csv")),
              "t,q1,q2\n0,0,0\n0.5,0.2,0.1\n1,0.5,0.3\n1.5,0.6,0.2\n2,0.6,0.2\n");
    writeText(dir.filePath(QStringLiteral("job.json")), R"({"robot": {"model": "urdf",
      "urdf": {"file": "robots/arm.urdf"}}, "path": {"kind": "file", "file": "robots/path.csv"}})");
    const Scenario s = readScenarioFile(dir.filePath(QStringLiteral("job.json")));
    QCOMPARE(s.urdf.file, dir.filePath(QStringLiteral("robots/arm.urdf")));
    QCOMPARE(s.path.file, dir.filePath(QStringLiteral("robots/path.csv")));
    QCOMPARE(s.path.fileAngles.cols(), Eigen::Index(5));
    LEARNID_COMPARE_NEAR(s.path.fileAngles(0, 2), 0.5, 0.0);
}

void TestScenarioChain::version1File_isStillRead()
{
    const QByteArray json = R"({"schema": "learnid-scenario/1", "robot": {"model": "paper-2link",
      "torqueLimits": [7, 3]}, "path": {"length": 0.4}})";
    const Scenario s = scenarioFromJson(json, source);
    QCOMPARE(s.path.kind, PathKind::Line);
    LEARNID_COMPARE_MATRIX(s.torqueLimits, Eigen::Vector2d(7, 3), 0.0);
    QCOMPARE(s.line.length, 0.4);
}

void TestScenarioChain::badInput_isNamedByItsKey_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");
    QTest::newRow("line on a URDF robot")
        << QByteArray(R"({"robot": {"model": "puma560"}})")
        << QStringLiteral("scenario.json: path.kind: the Cartesian line is the paper-2link arm's");
    QTest::newRow("waypoints on the paper arm")
        << QByteArray(R"({"path": {"kind": "waypoints", "waypoints": [[0, 0], [1, 1]]}})")
        << QStringLiteral("scenario.json: path.kind: the paper-2link arm runs the Cartesian");
    QTest::newRow("unknown kind") << QByteArray(R"({"path": {"kind": "circle"}})")
                                  << QStringLiteral("scenario.json: path.kind: must be \"line\", "
                                                    "\"waypoints\" or \"file\", got \"circle\"");
    QTest::newRow("short waypoint")
        << QByteArray(R"({"robot": {"model": "double-pendulum"},
             "path": {"kind": "waypoints", "waypoints": [[0, 0], [1]]}})")
        << QStringLiteral("scenario.json: path.waypoints[1]: must have 2 entries");
    QTest::newRow("one waypoint")
        << QByteArray(R"({"robot": {"model": "double-pendulum"},
             "path": {"kind": "waypoints", "waypoints": [[0, 0]]}})")
        << QStringLiteral("scenario.json: path.waypoints: needs at least 2 waypoints, got 1");
    QTest::newRow("urdf without file") << QByteArray(R"({"robot": {"model": "urdf"}})")
                                       << QStringLiteral("scenario.json: robot.urdf.file: the "
                                                         "\"urdf\" model needs a URDF file");
    QTest::newRow("missing urdf file")
        << QByteArray(R"({"robot": {"model": "urdf", "urdf": {"file": "/nonexistent/a.urdf"}}})")
        << QStringLiteral("scenario.json: robot.urdf.file: /nonexistent/a.urdf: cannot read");
    QTest::newRow("unknown joint term")
        << QByteArray(R"({"robot": {"model": "puma560", "jointTerms": {"stiction": true}}})")
        << QStringLiteral("scenario.json: robot.jointTerms.stiction: unknown key");
    QTest::newRow("gravity of 2") << QByteArray(R"({"robot": {"model": "puma560",
             "urdf": {"gravity": [0, -9.81]}}})")
                                  << QStringLiteral("scenario.json: robot.urdf.gravity: must have "
                                                    "3 entries");
    QTest::newRow("coulomb velocity 0") << QByteArray(R"({"robot": {"model": "puma560",
             "jointTerms": {"coulombVelocity": 0}}})")
                                        << QStringLiteral("scenario.json: "
                                                          "robot.jointTerms.coulombVelocity: must "
                                                          "be a positive number, got 0");
    QTest::newRow("perturbation 2")
        << QByteArray(R"({"robot": {"model": "double-pendulum"},
             "path": {"kind": "waypoints", "waypoints": [[0, 0], [1, 1]]},
             "simulation": {"inertiaPerturbation": 2}})")
        << QStringLiteral("scenario.json: simulation.inertiaPerturbation: must be");
    QTest::newRow("path file missing") << QByteArray(R"({"robot": {"model": "double-pendulum"},
             "path": {"kind": "file", "file": "/nonexistent/path.csv"}})")
                                       << QStringLiteral("scenario.json: path.file: ");
    QTest::newRow("unknown feedforward time")
        << QByteArray(R"({"controller": {"feedforwardTime": "late"}})")
        << QStringLiteral("scenario.json: controller.feedforwardTime: must be \"sample\" or "
                          "\"midSample\", got \"late\"");
    QTest::newRow("feedforward time not a string")
        << QByteArray(R"({"controller": {"feedforwardTime": 0.5}})")
        << QStringLiteral("scenario.json: controller.feedforwardTime: ");
    QTest::newRow("wrong initial parameter count")
        << QByteArray(R"({"robot": {"model": "double-pendulum", "initialParameters": [1, 2]},
             "path": {"kind": "waypoints", "waypoints": [[0, 0], [1, 1]]}})")
        << QStringLiteral("scenario.json: robot.initialParameters: must have 10 entries");
}

void TestScenarioChain::badInput_isNamedByItsKey()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    const QString message = errorOf(json);
    QVERIFY2(message.startsWith(expected), qPrintable(message));
}

QTEST_GUILESS_MAIN(TestScenarioChain)
#include "tst_scenariochain.moc"
