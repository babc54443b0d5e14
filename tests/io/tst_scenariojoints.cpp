// The scenario's realistic-joint keys under simulation (docs/scenario.md): read, written back
// bit-exactly, and every bad value refused with its key path; estimator.jointTorqueSensor, the
// identification's side of such joints, the same.
#include "../support/RotorScenario.h"
#include "IoTestSupport.h"
#include "io/ScenarioFile.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <limits>

using namespace learnid;
using learnid::test::bitEqual;

namespace {

const QString source = QStringLiteral("scenario.json");

// The default scenario with simulation.<name> = value (index >= 0: entry index of the array
// [1, 2], set to value).
QByteArray withSimulationKey(const QString &name, const QJsonValue &value)
{
    QJsonObject root = QJsonDocument::fromJson(scenarioToJson(Scenario{})).object();
    QJsonObject simulation = root.value(QStringLiteral("simulation")).toObject();
    simulation.insert(name, value);
    root.insert(QStringLiteral("simulation"), simulation);
    return QJsonDocument(root).toJson();
}

} // namespace

class TestScenarioJoints : public QObject
{
    Q_OBJECT

private slots:
    void allKeys_readAndWriteBackBitExactly();
    void defaults_areOffAndNotWritten();
    void badValue_isRejectedWithKeyPath_data();
    void badValue_isRejectedWithKeyPath();
    void nanInCode_isRejectedWithKeyPath();
    void estimatorSensorKeys_areReadWrittenAndChecked();
};

void TestScenarioJoints::allKeys_readAndWriteBackBitExactly()
{
    Scenario s;
    s.simulation.staticFriction = Eigen::Vector2d(0.3, 1.0 / 3.0);
    s.simulation.stribeckVelocity = 0.07;
    s.simulation.armature = Eigen::Vector2d(0.1, 0.0);
    s.simulation.armatureFactor = Eigen::Vector2d(0.5, 2.0);
    s.simulation.jointStiffness = Eigen::Vector2d(5000, 15000);
    s.simulation.jointDamping = Eigen::Vector2d(2.5, 0.0);
    s.simulation.linkSideEncoder = false;
    s.simulation.torqueSensorOffset = Eigen::Vector2d(-0.25, 0.1);
    s.simulation.torqueSensorLag = 0.001;
    const Scenario back = scenarioFromJson(scenarioToJson(s), source);
    const SimulationSettings &a = s.simulation, &b = back.simulation;
    QVERIFY(bitEqual(a.staticFriction, b.staticFriction));
    QVERIFY(bitEqual(a.stribeckVelocity, b.stribeckVelocity));
    QVERIFY(bitEqual(a.armature, b.armature));
    QVERIFY(bitEqual(a.armatureFactor, b.armatureFactor));
    QVERIFY(bitEqual(a.jointStiffness, b.jointStiffness));
    QVERIFY(bitEqual(a.jointDamping, b.jointDamping));
    QCOMPARE(b.linkSideEncoder, false);
    QVERIFY(bitEqual(a.torqueSensorOffset, b.torqueSensorOffset));
    QVERIFY(bitEqual(a.torqueSensorLag, b.torqueSensorLag));

    Scenario ratio;
    ratio.simulation.staticFrictionRatio = 1.5;
    QVERIFY(bitEqual(scenarioFromJson(scenarioToJson(ratio), source).simulation.staticFrictionRatio,
                     1.5));
}

void TestScenarioJoints::defaults_areOffAndNotWritten()
{
    const QJsonObject simulation = QJsonDocument::fromJson(scenarioToJson(Scenario{}))
                                       .object()
                                       .value(QStringLiteral("simulation"))
                                       .toObject();
    for (const char *name :
         {"staticFriction", "staticFrictionRatio", "stribeckVelocity", "armature", "armatureFactor",
          "jointStiffness", "jointDamping", "encoderSide", "torqueSensorOffset", "torqueSensorLag"})
        QVERIFY2(!simulation.contains(QLatin1String(name)), name);
    const Scenario s = scenarioFromJson(scenarioToJson(Scenario{}), source);
    QCOMPARE(s.simulation.staticFriction.size(), 0);
    QCOMPARE(s.simulation.jointStiffness.size(), 0);
    QCOMPARE(s.simulation.linkSideEncoder, true);
    QCOMPARE(s.simulation.torqueSensorLag, 0.0);
}

void TestScenarioJoints::badValue_isRejectedWithKeyPath_data()
{
    QTest::addColumn<QString>("key");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("expected"); // after "scenario.json: "
    const auto row = [](const char *name, const char *key, const QJsonValue &v, const char *msg) {
        QTest::newRow(name) << QString::fromLatin1(key) << v << QString::fromUtf8(msg);
    };
    const QJsonValue three = QJsonArray{1.0, 2.0, 3.0};
    row("staticFriction length", "staticFriction", three,
        "simulation.staticFriction: must have 2 entries (one per joint of paper-2link), got 3");
    row("staticFriction negative", "staticFriction", QJsonArray{1.0, -0.5},
        "simulation.staticFriction[1]: must be zero or a positive number, got -0.5");
    row("staticFriction nan string", "staticFriction", QJsonArray{QStringLiteral("nan"), 1.0},
        "simulation.staticFriction[0]: must be a number, got \"nan\"");
    row("staticFrictionRatio below 1", "staticFrictionRatio", 0.8,
        "simulation.staticFrictionRatio: must be 0 (off) or at least 1 (static friction is not "
        "below Coulomb friction), got 0.8");
    row("staticFrictionRatio negative", "staticFrictionRatio", -2,
        "simulation.staticFrictionRatio: must be 0 (off) or at least 1 (static friction is not "
        "below Coulomb friction), got -2");
    row("stribeckVelocity zero", "stribeckVelocity", 0,
        "simulation.stribeckVelocity: must be a positive number, got 0");
    row("stribeckVelocity string", "stribeckVelocity", QStringLiteral("0.1"),
        "simulation.stribeckVelocity: must be a number, got \"0.1\"");
    row("armature length", "armature", QJsonArray{0.1},
        "simulation.armature: must have 2 entries (one per joint of paper-2link), got 1");
    row("armature negative", "armature", QJsonArray{-0.1, 0.1},
        "simulation.armature[0]: must be zero or a positive number, got -0.1");
    row("armatureFactor negative", "armatureFactor", QJsonArray{1.0, -1.0},
        "simulation.armatureFactor[1]: must be zero or a positive number, got -1");
    row("jointStiffness negative", "jointStiffness", QJsonArray{-5000.0, 5000.0},
        "simulation.jointStiffness[0]: must be a positive number, got -5000");
    row("jointStiffness zero", "jointStiffness", QJsonArray{5000.0, 0.0},
        "simulation.jointStiffness[1]: must be a positive number, got 0");
    row("jointStiffness too stiff", "jointStiffness", QJsonArray{5000.0, 1e8},
        "simulation.jointStiffness[1]: must be greater than 0 and at most 1e+07, got 1e+08");
    row("jointStiffness not array", "jointStiffness", 5000,
        "simulation.jointStiffness: must be an array, got 5000");
    row("jointDamping without stiffness", "jointDamping", QJsonArray{1.0, 1.0},
        "simulation.jointDamping: applies to elastic joints only: give "
        "simulation.jointStiffness");
    row("encoderSide unknown", "encoderSide", QStringLiteral("rotor"),
        "simulation.encoderSide: must be \"motor\" or \"link\", got \"rotor\"");
    row("encoderSide motor without stiffness", "encoderSide", QStringLiteral("motor"),
        "simulation.encoderSide: applies to elastic joints only: give "
        "simulation.jointStiffness");
    row("torqueSensorOffset length", "torqueSensorOffset", three,
        "simulation.torqueSensorOffset: must have 2 entries (one per joint of paper-2link), got 3");
    row("torqueSensorLag negative", "torqueSensorLag", -0.001,
        "simulation.torqueSensorLag: must be from 0 to 1, got -0.001");
    row("torqueSensorLag too long", "torqueSensorLag", 2,
        "simulation.torqueSensorLag: must be from 0 to 1, got 2");
    row("unknown key", "stiffness", QJsonArray{1.0, 1.0}, "simulation.stiffness: unknown key");
}

void TestScenarioJoints::badValue_isRejectedWithKeyPath()
{
    QFETCH(QString, key);
    QFETCH(QJsonValue, value);
    QFETCH(QString, expected);
    const QString message =
        test::errorOf([&] { scenarioFromJson(withSimulationKey(key, value), source); });
    QVERIFY2(message.startsWith(source + QStringLiteral(": ") + expected), qPrintable(message));
}

void TestScenarioJoints::nanInCode_isRejectedWithKeyPath()
{
    // A number beyond a double in the file (JSON has no NaN or inf).
    QCOMPARE(test::errorOf([] {
                 scenarioFromJson("{\"simulation\": {\"jointStiffness\": [1e999, 1]}}", source);
             }),
             QStringLiteral("scenario.json: simulation.jointStiffness[0]: must be a finite number, "
                            "got 1e999, which is beyond the range of a double"));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Scenario s;
    s.simulation.torqueSensorOffset = Eigen::Vector2d(0.0, nan);
    QCOMPARE(test::errorOf([&] { validateScenario(s); }),
             QStringLiteral("simulation.torqueSensorOffset[1]: must be a finite number, got nan"));
    s = Scenario{};
    s.simulation.staticFrictionRatio = nan;
    QCOMPARE(test::errorOf([&] { validateScenario(s); }),
             QStringLiteral("simulation.staticFrictionRatio: must be a finite number, got nan"));
    s = Scenario{};
    s.simulation.staticFriction = Eigen::Vector2d(1, 1);
    s.simulation.staticFrictionRatio = 1.5;
    QCOMPARE(test::errorOf([&] { validateScenario(s); }),
             QStringLiteral("simulation.staticFrictionRatio: give static friction either as "
                            "simulation.staticFriction or as this ratio, not both"));
    s = Scenario{};
    s.simulation.jointStiffness = Eigen::Vector2d(nan, 1000);
    QCOMPARE(test::errorOf([&] { validateScenario(s); }),
             QStringLiteral("simulation.jointStiffness[0]: must be a positive number, got nan"));
}

void TestScenarioJoints::estimatorSensorKeys_areReadWrittenAndChecked()
{
    // Off by default and then not written; on, it is written and read back.
    const QJsonObject defaults = QJsonDocument::fromJson(scenarioToJson(Scenario{}))
                                     .object()
                                     .value(QStringLiteral("estimator"))
                                     .toObject();
    QVERIFY(!defaults.contains(QStringLiteral("jointTorqueSensor")));
    QVERIFY(!defaults.contains(QStringLiteral("torqueSensorLag")));
    Scenario s = test::rotorDoublePendulum();
    s.estimator.jointTorqueSensor = true;
    s.estimator.torqueSensorLag = 1.0 / 3000.0;
    const Scenario back = scenarioFromJson(scenarioToJson(s), source);
    QVERIFY(back.estimator.jointTorqueSensor);
    QVERIFY(bitEqual(back.estimator.torqueSensorLag, s.estimator.torqueSensorLag));

    const auto errorWith = [&](const char *estimator, bool armature) {
        QJsonObject root = QJsonDocument::fromJson(scenarioToJson(s)).object();
        QJsonObject robot = root.value(QStringLiteral("robot")).toObject();
        QJsonObject terms = robot.value(QStringLiteral("jointTerms")).toObject();
        terms.insert(QStringLiteral("armature"), armature);
        robot.insert(QStringLiteral("jointTerms"), terms);
        root.insert(QStringLiteral("robot"), robot);
        QJsonObject e = root.value(QStringLiteral("estimator")).toObject();
        const QJsonObject change = QJsonDocument::fromJson(estimator).object();
        for (auto it = change.begin(); it != change.end(); ++it)
            e.insert(it.key(), it.value());
        root.insert(QStringLiteral("estimator"), e);
        return test::errorOf([&] { scenarioFromJson(QJsonDocument(root).toJson(), source); });
    };
    QCOMPARE(errorWith("{\"jointTorqueSensor\": \"yes\"}", true),
             QStringLiteral("scenario.json: estimator.jointTorqueSensor: must be true or false, "
                            "got \"yes\""));
    QCOMPARE(errorWith("{\"torqueSensorLag\": -0.001}", true),
             QStringLiteral("scenario.json: estimator.torqueSensorLag: must be from 0 to 1, got "
                            "-0.001"));
    QCOMPARE(errorWith("{\"torqueSensorLag\": \"1 ms\"}", true),
             QStringLiteral("scenario.json: estimator.torqueSensorLag: must be a number, got "
                            "\"1 ms\""));
    QCOMPARE(errorWith("{\"law\": \"paper\", \"jointTorqueSensor\": false}", true),
             QStringLiteral("scenario.json: estimator.torqueSensorLag: needs the improved law "
                            "(estimator.law \"improved\"), got \"paper\""));
    QCOMPARE(errorWith("{\"law\": \"paper\"}", true),
             QStringLiteral("scenario.json: estimator.jointTorqueSensor: needs the improved law "
                            "(estimator.law \"improved\"), got \"paper\""));
    const QString needsArmature =
        QStringLiteral("estimator.jointTorqueSensor: needs a URDF robot with "
                       "robot.jointTerms.armature true: the rotor inertia the sensor does not "
                       "see is learned as the armature term");
    QCOMPARE(errorWith("{}", false), source + QStringLiteral(": ") + needsArmature);
    Scenario paper; // the paper's arm has no joint terms
    paper.estimator.jointTorqueSensor = true;
    QCOMPARE(test::errorOf([&] { validateScenario(paper); }), needsArmature);
}

QTEST_GUILESS_MAIN(TestScenarioJoints)
#include "tst_scenariojoints.moc"
