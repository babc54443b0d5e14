// Scenario input refused outside the reading of its keys: JSON syntax errors named by line,
// column and byte offset, numbers beyond a double named by key, what is not a JSON object or not
// a file at all, and validateScenario() on a scenario built in code (as the window's form does).
// (tst_scenariofile: the scenario file's keys and values.)

#include "IoTestSupport.h"
#include "io/ScenarioFile.h"

#include <QTemporaryDir>
#include <QTest>
#include <limits>

using namespace learnid;

namespace {

const QString source = QStringLiteral("scenario.json");

} // namespace

class TestScenarioInput : public QObject
{
    Q_OBJECT

private slots:
    void malformedJson_reportsLineAndByteOffset();
    void hugeNumber_isRejectedWithKeyPath();
    void syntaxErrorAfterHugeNumber_reportsTheOriginalOffset();
    void emptyDocument_isRejected();
    void topLevelArray_isRejected();
    void missingFile_reportsPathAndReason();
    void validateScenario_onStruct_namesKeyPath();
    void validateScenario_onStruct_catchesNonFinite();
};

void TestScenarioInput::malformedJson_reportsLineAndByteOffset()
{
    const QByteArray text = "{\n  \"robot\": {\n    \"model\": \"paper-2link\",,\n  }\n}\n";
    const QString message = test::errorOf([&] { scenarioFromJson(text, source); });
    QVERIFY2(message.startsWith(QStringLiteral("scenario.json: invalid JSON at line 3, column ")),
             qPrintable(message));
    // The second comma is byte 42; Qt's parser stops just after it.
    QVERIFY2(message.contains(QStringLiteral("(byte offset 43)")), qPrintable(message));
}

void TestScenarioInput::hugeNumber_isRejectedWithKeyPath()
{
    // 1e999 would be inf. Qt's parser refuses it as a syntax error; the reader still names the key.
    QCOMPARE(test::errorOf([] { scenarioFromJson(R"({"path": {"length": 1e999}})", source); }),
             QStringLiteral("scenario.json: path.length: must be a finite number, got 1e999, "
                            "which is beyond the range of a double"));
    LEARNID_VERIFY_ERROR(scenarioFromJson(R"({"controller": {"kp": [4500, -1E+400]}})", source),
                         QStringLiteral("scenario.json: controller.kp[1]: must be a finite number, "
                                        "got -1E+400"));
    LEARNID_VERIFY_ERROR(scenarioFromJson(R"({"estimator": {"iterations": 1e999}})", source),
                         QStringLiteral("scenario.json: estimator.iterations: must be an integer "
                                        "from 1 to 100, got 1e999 (beyond the range of a double)"));
}

void TestScenarioInput::syntaxErrorAfterHugeNumber_reportsTheOriginalOffset()
{
    const QByteArray text = "{\"path\": {\"length\": 1e999,\n \"restAfter\": 1e999}},}";
    const QString message = test::errorOf([&] { scenarioFromJson(text, source); });
    const int offset = int(text.lastIndexOf(",}")); // the garbage after the document
    QVERIFY2(message.startsWith(QStringLiteral("scenario.json: invalid JSON at line 2, column %1 "
                                               "(byte offset %2)")
                                    .arg(offset - int(text.indexOf('\n')))
                                    .arg(offset)),
             qPrintable(message));
}

void TestScenarioInput::emptyDocument_isRejected()
{
    LEARNID_VERIFY_ERROR(scenarioFromJson("  \n", source),
                         QStringLiteral("scenario.json: the file is empty"));
}

void TestScenarioInput::topLevelArray_isRejected()
{
    LEARNID_VERIFY_ERROR(scenarioFromJson("[1, 2]", source),
                         QStringLiteral("scenario.json: the top level must be a JSON object"));
}

void TestScenarioInput::missingFile_reportsPathAndReason()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("missing/scenario.json"));
    const QString message = test::errorOf([&] { readScenarioFile(path); });
    QVERIFY2(message.contains(path), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("No such file or directory")), qPrintable(message));
}

void TestScenarioInput::validateScenario_onStruct_namesKeyPath()
{
    Scenario s;
    s.controller.kp[1] = -5.0;
    QCOMPARE(test::errorOf([&] { validateScenario(s); }),
             QStringLiteral("controller.kp[1]: must be a positive number, got -5"));
    s = Scenario{};
    s.simulation.trueParameters.resize(2);
    LEARNID_VERIFY_ERROR(validateScenario(s),
                         QStringLiteral("simulation.trueParameters: must have 3"));
    s = Scenario{};
    s.simulation.seed = quint64(1) << 60;
    LEARNID_VERIFY_ERROR(validateScenario(s),
                         QStringLiteral("simulation.seed: must be an integer"));
    QCOMPARE(test::errorOf([] { validateScenario(Scenario{}); }), QStringLiteral("<no error>"));
}

void TestScenarioInput::validateScenario_onStruct_catchesNonFinite()
{
    Scenario s;
    s.torqueLimits[0] = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(test::errorOf([&] { validateScenario(s); }),
             QStringLiteral("robot.torqueLimits[0]: must be a positive number, got nan"));
    s = Scenario{};
    s.initialParameters[2] = std::numeric_limits<double>::infinity();
    QCOMPARE(test::errorOf([&] { validateScenario(s); }),
             QStringLiteral("robot.initialParameters[2]: must be a finite number, got inf"));
    s = Scenario{};
    s.line.directionDeg = -std::numeric_limits<double>::infinity();
    LEARNID_VERIFY_ERROR(validateScenario(s),
                         QStringLiteral("path.directionDeg: must be a finite"));
    s = Scenario{};
    s.planningFraction = std::numeric_limits<double>::quiet_NaN();
    LEARNID_VERIFY_ERROR(validateScenario(s),
                         QStringLiteral("path.planningFraction: must be greater"));

    // A scenario with NaN is still printable: the value becomes null, which reads back as an error.
    s = Scenario{};
    s.estimator.rho = std::numeric_limits<double>::quiet_NaN();
    LEARNID_VERIFY_ERROR(
        scenarioFromJson(scenarioToJson(s), source),
        QStringLiteral("scenario.json: estimator.rho: must be a number, got null"));
}

QTEST_GUILESS_MAIN(TestScenarioInput)
#include "tst_scenarioinput.moc"
