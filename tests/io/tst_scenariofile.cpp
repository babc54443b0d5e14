#include "IoTestSupport.h"
#include "io/AtomicFile.h"
#include "io/ScenarioFile.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;
using learnid::test::bitEqual;

namespace {

const QString source = QStringLiteral("scenario.json");

QJsonObject defaultObject()
{
    return QJsonDocument::fromJson(scenarioToJson(Scenario{})).object();
}

// Sets (or with an undefined value removes) the member at a key path such as "controller.kp[1]".
QJsonObject withValue(QJsonObject object, const QStringList &parts, const QJsonValue &value)
{
    static const QRegularExpression indexed(QStringLiteral("^(\\w+)\\[(\\d+)\\]$"));
    const QString head = parts.first();
    const QRegularExpressionMatch m = indexed.match(head);
    if (m.hasMatch()) {
        QJsonArray a = object.value(m.captured(1)).toArray();
        a[m.captured(2).toInt()] = value;
        object.insert(m.captured(1), a);
    } else if (parts.size() == 1) {
        if (value.isUndefined())
            object.remove(head);
        else
            object.insert(head, value);
    } else {
        object.insert(head, withValue(object.value(head).toObject(), parts.mid(1), value));
    }
    return object;
}

QByteArray defaultWith(const QString &path, const QJsonValue &value)
{
    return QJsonDocument(withValue(defaultObject(), path.split(QLatin1Char('.')), value)).toJson();
}

void compareScenarios(const Scenario &a, const Scenario &b)
{
    QCOMPARE(a.model, b.model);
    QVERIFY(bitEqual(a.linkLengths, b.linkLengths));
    QCOMPARE(a.elbowSign, b.elbowSign);
    QVERIFY(bitEqual(a.torqueLimits, b.torqueLimits));
    QVERIFY(bitEqual(a.initialParameters, b.initialParameters));
    QVERIFY(bitEqual(a.line.start, b.line.start));
    QVERIFY(bitEqual(a.line.length, b.line.length));
    QVERIFY(bitEqual(a.line.directionDeg, b.line.directionDeg));
    QVERIFY(bitEqual(a.restBefore, b.restBefore));
    QVERIFY(bitEqual(a.restAfter, b.restAfter));
    QVERIFY(bitEqual(a.planningFraction, b.planningFraction));
    QCOMPARE(a.gentleTrials, b.gentleTrials);
    QVERIFY(bitEqual(a.gentleSpeed, b.gentleSpeed));
    QVERIFY(bitEqual(a.controller.samplePeriod, b.controller.samplePeriod));
    QVERIFY(bitEqual(a.controller.kp, b.controller.kp));
    QVERIFY(bitEqual(a.controller.ki, b.controller.ki));
    QVERIFY(bitEqual(a.controller.kd, b.controller.kd));
    QVERIFY(bitEqual(a.controller.lambda, b.controller.lambda));
    QCOMPARE(a.controller.feedforwardTime, b.controller.feedforwardTime);
    QCOMPARE(a.law, b.law);
    QVERIFY(bitEqual(a.estimator.rho, b.estimator.rho));
    QVERIFY(bitEqual(a.estimator.rankTolerance, b.estimator.rankTolerance));
    QVERIFY(bitEqual(a.estimator.partialMaxRelativeStd, b.estimator.partialMaxRelativeStd));
    QCOMPARE(a.estimator.accumulate, b.estimator.accumulate);
    QCOMPARE(a.iterations, b.iterations);
    QCOMPARE(a.repetitions, b.repetitions);
    QVERIFY(bitEqual(a.simulation.trueParameters, b.simulation.trueParameters));
    QCOMPARE(a.simulation.encoderCounts, b.simulation.encoderCounts);
    QVERIFY(bitEqual(a.simulation.torqueNoise, b.simulation.torqueNoise));
    QCOMPARE(a.simulation.seed, b.simulation.seed);
    QCOMPARE(a.simulation.substeps, b.simulation.substeps);
    QVERIFY(bitEqual(a.maxTrackingErrorDeg, b.maxTrackingErrorDeg));
    QVERIFY(bitEqual(a.stabilityMargin, b.stabilityMargin));
}

} // namespace

class TestScenarioFile : public QObject
{
    Q_OBJECT

private slots:
    void defaultScenario_roundTripsFieldByField();
    void defaultScenario_printsEveryKeyInDocumentedOrder();
    void changedScenario_roundTripsBitExactly();
    void emptyObject_takesTheDefaults();
    void partialSection_keepsTheOtherDefaults();
    void boundaryValues_areAccepted_data();
    void boundaryValues_areAccepted();
    void badValue_isRejectedWithKeyPath_data();
    void badValue_isRejectedWithKeyPath();
    void negativeGain_messageNamesSourceKeyAndValue();
    void unknownKey_isRejectedWithKeyPath();
    void unknownTopLevelKey_isRejected();
    void scenarioFile_writesAndReadsBack();
};

void TestScenarioFile::defaultScenario_roundTripsFieldByField()
{
    const Scenario read = scenarioFromJson(scenarioToJson(Scenario{}), source);
    compareScenarios(read, Scenario{});
}

void TestScenarioFile::defaultScenario_printsEveryKeyInDocumentedOrder()
{
    const QByteArray json = scenarioToJson(Scenario{});
    const QStringList keys = {"schema",
                              "robot",
                              "model",
                              "linkLengths",
                              "elbow",
                              "torqueLimits",
                              "initialParameters",
                              "path",
                              "kind",
                              "start",
                              "length",
                              "directionDeg",
                              "restBefore",
                              "restAfter",
                              "planningFraction",
                              "gentleTrials",
                              "gentleSpeed",
                              "controller",
                              "samplePeriod",
                              "kp",
                              "ki",
                              "kd",
                              "lambda",
                              "estimator",
                              "law",
                              "rho",
                              "rankTolerance",
                              "accumulate",
                              "iterations",
                              "repetitions",
                              "simulation",
                              "trueParameters",
                              "encoderCounts",
                              "torqueNoise",
                              "seed",
                              "substeps",
                              "safety",
                              "maxTrackingErrorDeg",
                              "stabilityMargin"};
    qsizetype position = -1;
    for (const QString &key : keys) {
        const qsizetype at = json.indexOf('"' + key.toUtf8() + "\":");
        QVERIFY2(at > position, qPrintable(key));
        position = at;
    }
    QVERIFY(json.startsWith("{\n    \"schema\": \"learnid-scenario/2\",\n"));
    QVERIFY(json.contains("\"kp\": [4500, 5000]"));
    QVERIFY(json.contains("\"samplePeriod\": 0.002"));
    QVERIFY(json.endsWith("}\n"));
    QCOMPARE(json, scenarioToJson(Scenario{})); // stable
}

void TestScenarioFile::changedScenario_roundTripsBitExactly()
{
    Scenario s;
    s.linkLengths << 0.7123456789012345, 1.0 / 3.0;
    s.elbowSign = -1;
    s.torqueLimits << 12.5, 3.0000000000000004;
    s.initialParameters << -1e-300, 2.5e10, 0.1 + 0.2;
    s.line.start << -0.25, 0.6;
    s.line.length = 0.33;
    s.line.directionDeg = -17.5;
    s.restBefore = 0.0;
    s.restAfter = 2.0;
    s.planningFraction = 1.0;
    s.gentleTrials = 3;
    s.gentleSpeed = 0.3 + 0.1;
    s.controller.samplePeriod = 0.001;
    s.controller.kp << 1e4, 2e4;
    s.controller.ki << 0.0, 1.5;
    s.controller.kd << 100, 0.0;
    s.controller.lambda = 250.0;
    s.controller.feedforwardTime = FeedforwardTime::MidSample;
    s.law = QStringLiteral("paper");
    s.estimator.rho = 33.3;
    s.estimator.rankTolerance = 1e-6;
    s.estimator.partialMaxRelativeStd = 0.125;
    s.estimator.accumulate = false;
    s.iterations = 100;
    s.repetitions = 20;
    s.simulation.trueParameters << 19.9, 5.05, 7.95;
    s.simulation.encoderCounts = qint64(1) << 20;
    s.simulation.torqueNoise = 0.01;
    s.simulation.seed = (quint64(1) << 53) - 1;
    s.simulation.substeps = 1000;
    s.maxTrackingErrorDeg = 0.25;
    s.stabilityMargin = 2.0;
    compareScenarios(scenarioFromJson(scenarioToJson(s), source), s);
}

void TestScenarioFile::emptyObject_takesTheDefaults()
{
    compareScenarios(scenarioFromJson("{}", source), Scenario{});
}

void TestScenarioFile::partialSection_keepsTheOtherDefaults()
{
    const Scenario s =
        scenarioFromJson(R"({"controller": {"lambda": 80}, "estimator": {}})", source);
    Scenario expected;
    expected.controller.lambda = 80.0;
    compareScenarios(s, expected);
}

void TestScenarioFile::boundaryValues_areAccepted_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QJsonValue>("value");
    QTest::newRow("encoderCounts 0") << "simulation.encoderCounts" << QJsonValue(0);
    QTest::newRow("encoderCounts 16") << "simulation.encoderCounts" << QJsonValue(16);
    QTest::newRow("encoderCounts 2^31")
        << "simulation.encoderCounts" << QJsonValue(qint64(1) << 31);
    QTest::newRow("iterations 1") << "estimator.iterations" << QJsonValue(1);
    QTest::newRow("repetitions 20") << "estimator.repetitions" << QJsonValue(20);
    QTest::newRow("substeps 1") << "simulation.substeps" << QJsonValue(1);
    QTest::newRow("planningFraction 1") << "path.planningFraction" << QJsonValue(1.0);
    QTest::newRow("gentleTrials 0") << "path.gentleTrials" << QJsonValue(0);
    QTest::newRow("gentleTrials 100") << "path.gentleTrials" << QJsonValue(100);
    QTest::newRow("gentleSpeed 1") << "path.gentleSpeed" << QJsonValue(1.0);
    QTest::newRow("samplePeriod 0.1") << "controller.samplePeriod" << QJsonValue(0.1);
    QTest::newRow("restBefore 0") << "path.restBefore" << QJsonValue(0.0);
    QTest::newRow("ki 0") << "controller.ki[0]" << QJsonValue(0.0);
    QTest::newRow("kd 0") << "controller.kd[1]" << QJsonValue(0.0);
    QTest::newRow("elbow -1") << "robot.elbow" << QJsonValue(-1);
    QTest::newRow("integral as 6.0") << "estimator.iterations" << QJsonValue(6.0);
    QTest::newRow("seed 2^53") << "simulation.seed" << QJsonValue(qint64(1) << 53);
    QTest::newRow("initial parameter negative") << "robot.initialParameters[1]" << QJsonValue(-3.0);
}

void TestScenarioFile::boundaryValues_areAccepted()
{
    QFETCH(QString, path);
    QFETCH(QJsonValue, value);
    const QString message =
        test::errorOf([&] { scenarioFromJson(defaultWith(path, value), source); });
    QCOMPARE(message, QStringLiteral("<no error>"));
}

void TestScenarioFile::badValue_isRejectedWithKeyPath_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("expected"); // after "scenario.json: "

    const auto row = [](const char *name, const char *path, const QJsonValue &v, const char *msg) {
        QTest::newRow(name) << QString::fromLatin1(path) << v << QString::fromUtf8(msg);
    };
    const QJsonValue list3 = QJsonArray{1.0, 2.0, 3.0};
    const QJsonValue list2 = QJsonArray{1.0, 2.0};
    // types
    row("schema", "schema", QStringLiteral("learnid-scenario/3"),
        "schema: this version of learnid reads \"learnid-scenario/2\" and "
        "\"learnid-scenario/1\", got \"learnid-scenario/3\"");
    row("section not object", "robot", 5, "robot: must be an object, got 5");
    row("model not string", "robot.model", 3, "robot.model: must be a string, got 3");
    row("vector not array", "controller.kp", QStringLiteral("4500"),
        "controller.kp: must be an array, got \"4500\"");
    row("nan string", "controller.kp[1]", QStringLiteral("nan"),
        "controller.kp[1]: must be a number, got \"nan\"");
    row("inf string", "path.length", QStringLiteral("inf"),
        "path.length: must be a number, got \"inf\"");
    row("null", "controller.lambda", QJsonValue(QJsonValue::Null),
        "controller.lambda: must be a number, got null");
    row("bool not bool", "estimator.accumulate", QStringLiteral("yes"),
        "estimator.accumulate: must be true or false, got \"yes\"");
    row("integer as text", "estimator.iterations", QStringLiteral("6"),
        "estimator.iterations: must be an integer from 1 to 100, got \"6\"");
    // lengths
    row("kp length", "controller.kp", list3,
        "controller.kp: must have 2 entries (one per joint), got 3");
    row("torqueLimits length", "robot.torqueLimits", QJsonArray{8.0},
        "robot.torqueLimits: must have 2 entries (one per joint of paper-2link), got 1");
    row("linkLengths length", "robot.linkLengths", QJsonArray{},
        "robot.linkLengths: must have 2 entries (one per joint of paper-2link), got 0");
    row("initialParameters length", "robot.initialParameters", list2,
        "robot.initialParameters: must have 3 entries (one per parameter of paper-2link), got 2");
    row("trueParameters length", "simulation.trueParameters", QJsonArray{1, 2, 3, 4},
        "simulation.trueParameters: must have 3 entries (one per parameter of paper-2link), got 4");
    row("start length", "path.start", list3, "path.start: must have 2 entries (x and y), got 3");
    // ranges
    row("kp zero", "controller.kp[0]", 0, "controller.kp[0]: must be a positive number, got 0");
    row("ki negative", "controller.ki[1]", -1,
        "controller.ki[1]: must be zero or a positive number, got -1");
    row("kd negative", "controller.kd[0]", -600,
        "controller.kd[0]: must be zero or a positive number, got -600");
    row("lambda negative", "controller.lambda", -1,
        "controller.lambda: must be a positive number, got -1");
    row("samplePeriod zero", "controller.samplePeriod", 0,
        "controller.samplePeriod: must be greater than 0 and at most 0.1, got 0");
    row("samplePeriod large", "controller.samplePeriod", 0.2,
        "controller.samplePeriod: must be greater than 0 and at most 0.1, got 0.2");
    row("link zero", "robot.linkLengths[1]", 0,
        "robot.linkLengths[1]: must be a positive number, got 0");
    row("torque limit negative", "robot.torqueLimits[0]", -8,
        "robot.torqueLimits[0]: must be a positive number, got -8");
    row("elbow 0", "robot.elbow", 0, "robot.elbow: must be 1 or -1, got 0");
    row("elbow 2", "robot.elbow", 2, "robot.elbow: must be 1 or -1, got 2");
    row("unknown model", "robot.model", QStringLiteral("puma600"),
        "robot.model: unknown model \"puma600\"; known models: paper-2link, urdf, "
        "paper-2link-urdf, double-pendulum, puma560, panda");
    row("unknown law", "estimator.law", QStringLiteral("magic"),
        "estimator.law: unknown learning law \"magic\"; known laws: paper, improved");
    row("length zero", "path.length", 0, "path.length: must be a positive number, got 0");
    row("restBefore negative", "path.restBefore", -0.1,
        "path.restBefore: must be from 0 to 60, got -0.1");
    row("restAfter negative", "path.restAfter", -1, "path.restAfter: must be from 0 to 60, got -1");
    row("planningFraction zero", "path.planningFraction", 0,
        "path.planningFraction: must be greater than 0 and at most 1, got 0");
    row("planningFraction above 1", "path.planningFraction", 1.5,
        "path.planningFraction: must be greater than 0 and at most 1, got 1.5");
    row("gentleTrials negative", "path.gentleTrials", -1,
        "path.gentleTrials: must be an integer from 0 to 100, got -1");
    row("gentleTrials fraction", "path.gentleTrials", 1.5,
        "path.gentleTrials: must be an integer from 0 to 100, got 1.5");
    row("gentleTrials 101", "path.gentleTrials", 101,
        "path.gentleTrials: must be an integer from 0 to 100, got 101");
    row("gentleSpeed zero", "path.gentleSpeed", 0,
        "path.gentleSpeed: must be greater than 0 and at most 1, got 0");
    row("gentleSpeed above 1", "path.gentleSpeed", 2,
        "path.gentleSpeed: must be greater than 0 and at most 1, got 2");
    row("gentleSpeed string", "path.gentleSpeed", QStringLiteral("0.5"),
        "path.gentleSpeed: must be a number, got \"0.5\"");
    row("rho zero", "estimator.rho", 0, "estimator.rho: must be a positive number, got 0");
    row("rankTolerance 1", "estimator.rankTolerance", 1,
        "estimator.rankTolerance: must be greater than 0 and less than 1, got 1");
    row("rankTolerance 0", "estimator.rankTolerance", 0,
        "estimator.rankTolerance: must be greater than 0 and less than 1, got 0");
    row("partialMaxRelativeStd zero", "estimator.partialMaxRelativeStd", 0,
        "estimator.partialMaxRelativeStd: must be a positive number, got 0");
    row("partialMaxRelativeStd string", "estimator.partialMaxRelativeStd", QStringLiteral("a"),
        "estimator.partialMaxRelativeStd: must be a number, got \"a\"");
    row("iterations 0", "estimator.iterations", 0,
        "estimator.iterations: must be an integer from 1 to 100, got 0");
    row("iterations 101", "estimator.iterations", 101,
        "estimator.iterations: must be an integer from 1 to 100, got 101");
    row("iterations fraction", "estimator.iterations", 6.5,
        "estimator.iterations: must be an integer from 1 to 100, got 6.5");
    row("iterations huge", "estimator.iterations", 1e300,
        "estimator.iterations: must be an integer from 1 to 100, got 1e+300");
    row("repetitions 21", "estimator.repetitions", 21,
        "estimator.repetitions: must be an integer from 1 to 20, got 21");
    row("substeps 0", "simulation.substeps", 0,
        "simulation.substeps: must be an integer from 1 to 1000, got 0");
    row("substeps 1001", "simulation.substeps", 1001,
        "simulation.substeps: must be an integer from 1 to 1000, got 1001");
    row("encoderCounts 15", "simulation.encoderCounts", 15,
        "simulation.encoderCounts: must be 0 (an ideal encoder) or an integer from 16 to "
        "2147483648, got 15");
    row("encoderCounts negative", "simulation.encoderCounts", -1,
        "simulation.encoderCounts: must be 0 (an ideal encoder) or an integer from 16 to "
        "2147483648, got -1");
    row("encoderCounts 2^31+1", "simulation.encoderCounts", QJsonValue((qint64(1) << 31) + 1),
        "simulation.encoderCounts: must be 0 (an ideal encoder) or an integer from 16 to "
        "2147483648, got 2147483649");
    row("torqueNoise negative", "simulation.torqueNoise", -0.01,
        "simulation.torqueNoise: must be from 0 to 1, got -0.01");
    row("seed negative", "simulation.seed", -1,
        "simulation.seed: must be an integer from 0 to 9007199254740992, got -1");
    row("seed fraction", "simulation.seed", 1.5,
        "simulation.seed: must be an integer from 0 to 9007199254740992, got 1.5");
    row("maxTrackingErrorDeg zero", "safety.maxTrackingErrorDeg", 0,
        "safety.maxTrackingErrorDeg: must be a positive number, got 0");
    row("stabilityMargin negative", "safety.stabilityMargin", -1,
        "safety.stabilityMargin: must be zero or a positive number, got -1");
    row("missing schema is fine but empty robot.model is not", "robot.model", QString(),
        "robot.model: unknown model \"\"");
}

void TestScenarioFile::badValue_isRejectedWithKeyPath()
{
    QFETCH(QString, path);
    QFETCH(QJsonValue, value);
    QFETCH(QString, expected);
    const QString message =
        test::errorOf([&] { scenarioFromJson(defaultWith(path, value), source); });
    QVERIFY2(message.startsWith(QStringLiteral("scenario.json: ") + expected), qPrintable(message));
}

void TestScenarioFile::negativeGain_messageNamesSourceKeyAndValue()
{
    const QString message = test::errorOf(
        [&] { scenarioFromJson(defaultWith(QStringLiteral("controller.kp[1]"), -5), source); });
    QCOMPARE(message,
             QStringLiteral("scenario.json: controller.kp[1]: must be a positive number, got -5"));
}

void TestScenarioFile::unknownKey_isRejectedWithKeyPath()
{
    const QString message = test::errorOf(
        [&] { scenarioFromJson(defaultWith(QStringLiteral("robot.colour"), 1), source); });
    QVERIFY2(message.startsWith(QStringLiteral("scenario.json: robot.colour: unknown key")),
             qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("torqueLimits")),
             qPrintable(message)); // lists allowed
}

void TestScenarioFile::unknownTopLevelKey_isRejected()
{
    LEARNID_VERIFY_ERROR(scenarioFromJson(R"({"controler": {"lambda": 80}})", source),
                         QStringLiteral("scenario.json: controler: unknown key"));
}

void TestScenarioFile::scenarioFile_writesAndReadsBack()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("s.json"));
    Scenario s;
    s.iterations = 3;
    writeScenarioFile(path, s);
    compareScenarios(readScenarioFile(path), s);

    writeFileAtomically(path, defaultWith(QStringLiteral("controller.kp[1]"), -5));
    LEARNID_VERIFY_ERROR(readScenarioFile(path), path + QStringLiteral(": controller.kp[1]: "));
}

QTEST_GUILESS_MAIN(TestScenarioFile)
#include "tst_scenariofile.moc"
