#include "IoTestSupport.h"
#include "ParameterFileSample.h"
#include "io/AtomicFile.h"
#include "io/ParameterFile.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <limits>
#include <random>

using namespace learnid;
using learnid::test::bitEqual;
using learnid::test::sampleParameterFile;

namespace {

const QString source = QStringLiteral("robot.params.json");
constexpr double inf = std::numeric_limits<double>::infinity();

void compareContent(const ParameterFileContent &a, const ParameterFileContent &b)
{
    QCOMPARE(a.robotModel, b.robotModel);
    QCOMPARE(a.robotDescription, b.robotDescription);
    QCOMPARE(a.nodes(), b.nodes());
    QVERIFY(bitEqual(a.controller.samplePeriod, b.controller.samplePeriod));
    QVERIFY(bitEqual(a.controller.kp, b.controller.kp));
    QVERIFY(bitEqual(a.controller.ki, b.controller.ki));
    QVERIFY(bitEqual(a.controller.kd, b.controller.kd));
    QVERIFY(bitEqual(a.controller.lambda, b.controller.lambda));
    QCOMPARE(a.created, b.created);
    QCOMPARE(a.toolVersion, b.toolVersion);
    QCOMPARE(a.law, b.law);
    QCOMPARE(a.sourceTrial, b.sourceTrial);
    QCOMPARE(a.parameters.size(), b.parameters.size());
    for (int i = 0; i < int(a.parameters.size()); ++i) {
        QCOMPARE(a.parameters.at(i).name, b.parameters.at(i).name);
        QCOMPARE(a.parameters.at(i).unit, b.parameters.at(i).unit);
        QCOMPARE(a.parameters.at(i).description, b.parameters.at(i).description);
    }
    QVERIFY(bitEqual(a.values, b.values));
    QVERIFY(bitEqual(a.standardDeviations, b.standardDeviations));
    QVERIFY(bitEqual(a.maxTrackingErrorDeg, b.maxTrackingErrorDeg));
    QVERIFY(bitEqual(a.rmsTrackingErrorDeg, b.rmsTrackingErrorDeg));
    QVERIFY(bitEqual(a.residualRms, b.residualRms));
    QVERIFY(bitEqual(a.condition, b.condition));
    QCOMPARE(a.rank, b.rank);
    QCOMPARE(a.canWrites.size(), b.canWrites.size());
    for (int i = 0; i < int(a.canWrites.size()); ++i) {
        const SdoWrite &x = a.canWrites.at(i), &y = b.canWrites.at(i);
        QCOMPARE(x.node, y.node);
        QCOMPARE(x.index, y.index);
        QCOMPARE(x.subIndex, y.subIndex);
        QCOMPARE(x.dataType, y.dataType);
        QVERIFY(bitEqual(x.value, y.value));
        QCOMPARE(x.raw, y.raw);
    }
}

QJsonObject sampleObject()
{
    return QJsonDocument::fromJson(parameterFileToJson(sampleParameterFile())).object();
}

// The object with a new, correct checksum: what a careful forger (or another tool) would write.
QByteArray withChecksum(QJsonObject o)
{
    o.remove(QStringLiteral("checksum"));
    o.insert(QStringLiteral("checksum"), QString::fromLatin1(parameterFileChecksum(o)));
    return QJsonDocument(o).toJson();
}

QString readError(const QByteArray &json)
{
    return test::errorOf([&] { parameterFileFromJson(json, source); });
}

} // namespace

class TestParameterFile : public QObject
{
    Q_OBJECT

private slots:
    void roundTrip_givesIdenticalContent();
    void roundTrip_randomValues_areBitExact();
    void infiniteStandardDeviation_isNullAndReadsBackAsInf();
    void missingFigures_roundTrip();
    void largeIntegralNumbers_keepAValidChecksum();
    void file_listsKeysInDocumentedOrder();
    void checksum_followsTheDocumentedRule();
    void reformattedFile_keepsAValidChecksum();
    void changedValue_failsTheChecksum();
    void missingChecksum_isRejected();
    void missingSchema_isRejected();
    void missingField_isRejectedWithKeyPath_data();
    void missingField_isRejectedWithKeyPath();
    void badField_isRejectedWithKeyPath_data();
    void badField_isRejectedWithKeyPath();
    void inconsistentContent_isRefusedOnWrite_data();
    void inconsistentContent_isRefusedOnWrite();
    void parameterFile_writesAndReadsBackThroughAFile();
};

void TestParameterFile::roundTrip_givesIdenticalContent()
{
    const ParameterFileContent c = sampleParameterFile();
    compareContent(parameterFileFromJson(parameterFileToJson(c), source), c);
}

void TestParameterFile::roundTrip_randomValues_areBitExact()
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> e(-60, 60);
    for (int trial = 0; trial < 200; ++trial) {
        ParameterFileContent c = sampleParameterFile();
        for (int i = 0; i < 3; ++i) {
            c.values[i] = std::ldexp(u(rng), e(rng));
            c.standardDeviations[i] = std::abs(std::ldexp(u(rng), e(rng)));
        }
        c.condition = std::ldexp(std::abs(u(rng)), e(rng));
        c.controller.kp[0] = std::ldexp(std::abs(u(rng)) + 0.5, e(rng));
        compareContent(parameterFileFromJson(parameterFileToJson(c), source), c);
    }
}

void TestParameterFile::infiniteStandardDeviation_isNullAndReadsBackAsInf()
{
    ParameterFileContent c = sampleParameterFile();
    c.condition = inf;
    c.maxTrackingErrorDeg[1] = inf;
    const QByteArray json = parameterFileToJson(c);
    const QJsonObject o = QJsonDocument::fromJson(json).object();
    QVERIFY(o.value("parameters").toArray().at(1).toObject().value("standardDeviation").isNull());
    QVERIFY(o.value("quality").toObject().value("condition").isNull());
    const ParameterFileContent back = parameterFileFromJson(json, source);
    QCOMPARE(back.standardDeviations[1], inf);
    QCOMPARE(back.condition, inf);
    QCOMPARE(back.maxTrackingErrorDeg[1], inf);
}

void TestParameterFile::missingFigures_roundTrip()
{
    // As a session writes an estimate that no trial has verified yet.
    ParameterFileContent c = sampleParameterFile();
    c.standardDeviations.resize(0);
    c.maxTrackingErrorDeg.resize(0);
    c.rmsTrackingErrorDeg.resize(0);
    c.residualRms.resize(0);
    c.canWrites.clear();
    c.sourceTrial = -1;
    c.jointNodes = {3, 7};
    const QByteArray json = parameterFileToJson(c);
    QVERIFY(!json.contains("standardDeviation"));
    compareContent(parameterFileFromJson(json, source), c);
}

void TestParameterFile::largeIntegralNumbers_keepAValidChecksum()
{
    // Qt's parser reads an integral 1e+17 as the integer 100000000000000000, which its compact
    // form prints differently; the checksum must be of the parsed form.
    ParameterFileContent c = sampleParameterFile();
    c.condition = 1e17;
    c.values[0] = std::ldexp(1.0, 60);
    c.values[1] = -1e15;
    c.standardDeviations[2] = 0.0004;
    compareContent(parameterFileFromJson(parameterFileToJson(c), source), c);
}

void TestParameterFile::file_listsKeysInDocumentedOrder()
{
    const QByteArray json = parameterFileToJson(sampleParameterFile());
    qsizetype position = -1;
    for (const char *key :
         {"schema", "created", "toolVersion", "robot", "controller", "identification", "parameters",
          "standardParameters", "quality", "canWrites", "checksum"}) {
        const qsizetype at = json.indexOf(QByteArray("\n    \"") + key + "\":");
        QVERIFY2(at > position, key);
        position = at;
    }
    QVERIFY(json.contains("\"schema\": \"learnid-parameters/2\""));
    QVERIFY(json.contains("\"created\": \"2024-05-01T12:34:56.789Z\""));
    QVERIFY(json.contains("\"index\": \"0x2100\""));
    QVERIFY(json.contains("\"raw\": \"00a08c45\""));
}

void TestParameterFile::checksum_followsTheDocumentedRule()
{
    // docs/file-formats.md: SHA-256, lower-case hex, of the compact JSON (keys sorted) of the
    // top-level object without "checksum".
    QJsonObject o = sampleObject();
    const QString stored = o.take(QStringLiteral("checksum")).toString();
    const QByteArray compact = QJsonDocument(o).toJson(QJsonDocument::Compact);
    QVERIFY(compact.startsWith("{\"canWrites\":[{\"index\":\"0x2100\","));
    QCOMPARE(stored.toLatin1(),
             QCryptographicHash::hash(compact, QCryptographicHash::Sha256).toHex());
    QCOMPARE(stored.size(), 64);
}

void TestParameterFile::reformattedFile_keepsAValidChecksum()
{
    const QByteArray compact = QJsonDocument(sampleObject()).toJson(QJsonDocument::Compact);
    compareContent(parameterFileFromJson(compact, source), sampleParameterFile());
}

void TestParameterFile::changedValue_failsTheChecksum()
{
    QByteArray json = parameterFileToJson(sampleParameterFile());
    const QByteArray original = "\"value\": 20.000123456789012";
    QVERIFY(json.contains(original));
    json.replace(original, "\"value\": 21.000123456789012");
    QCOMPARE(readError(json),
             QStringLiteral("robot.params.json: checksum: does not match the content: the file "
                            "was changed after learnid wrote it, or is damaged"));
}

void TestParameterFile::missingChecksum_isRejected()
{
    QJsonObject o = sampleObject();
    o.remove(QStringLiteral("checksum"));
    QVERIFY(readError(QJsonDocument(o).toJson())
                .startsWith(QStringLiteral("robot.params.json: checksum: is missing")));
}

void TestParameterFile::missingSchema_isRejected()
{
    QJsonObject o = sampleObject();
    o.remove(QStringLiteral("schema"));
    QVERIFY(readError(withChecksum(o))
                .startsWith(QStringLiteral("robot.params.json: schema: is missing")));
}

void TestParameterFile::missingField_isRejectedWithKeyPath_data()
{
    QTest::addColumn<QString>("section");
    QTest::addColumn<QString>("key");
    for (const char *top : {"created", "toolVersion", "robot", "controller", "identification",
                            "parameters", "quality", "canWrites"})
        QTest::newRow(top) << QString() << QString::fromLatin1(top);
    QTest::newRow("robot.model") << "robot"
                                 << "model";
    QTest::newRow("robot.jointNodes") << "robot"
                                      << "jointNodes";
    QTest::newRow("controller.kd") << "controller"
                                   << "kd";
    QTest::newRow("identification.law") << "identification"
                                        << "law";
    QTest::newRow("quality.rank") << "quality"
                                  << "rank";
    QTest::newRow("quality.residualRms") << "quality"
                                         << "residualRms";
}

void TestParameterFile::missingField_isRejectedWithKeyPath()
{
    QFETCH(QString, section);
    QFETCH(QString, key);
    QJsonObject o = sampleObject();
    if (section.isEmpty()) {
        o.remove(key);
    } else {
        QJsonObject s = o.value(section).toObject();
        s.remove(key);
        o.insert(section, s);
    }
    const QString path = section.isEmpty() ? key : section + QLatin1Char('.') + key;
    const QString message = readError(withChecksum(o));
    QVERIFY2(message.startsWith(QStringLiteral("robot.params.json: %1: is missing").arg(path)),
             qPrintable(message));
}

void TestParameterFile::badField_isRejectedWithKeyPath_data()
{
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");

    const auto edit = [](const std::function<void(QJsonObject &)> &change) {
        QJsonObject o = sampleObject();
        change(o);
        return withChecksum(o);
    };
    const auto inSection = [](QJsonObject &o, const char *section, const char *key,
                              const QJsonValue &v) {
        QJsonObject s = o.value(section).toObject();
        s.insert(key, v);
        o.insert(section, s);
    };
    const auto inListEntry = [](QJsonObject &o, const char *list, int index, const char *key,
                                const QJsonValue &v) {
        QJsonArray a = o.value(list).toArray();
        QJsonObject e = a.at(index).toObject();
        if (v.isUndefined())
            e.remove(key);
        else
            e.insert(key, v);
        a[index] = e;
        o.insert(list, a);
    };

    QTest::newRow("unknown top-level key")
        << edit([](QJsonObject &o) { o.insert("comment", "x"); }) << "comment: unknown key";
    QTest::newRow("unknown robot key")
        << edit([&](QJsonObject &o) { inSection(o, "robot", "serial", 5); })
        << "robot.serial: unknown key";
    QTest::newRow("created not a date")
        << edit([](QJsonObject &o) { o.insert("created", "yesterday"); })
        << "created: must be a date and time";
    QTest::newRow("kp too short") << edit([&](QJsonObject &o) {
        inSection(o, "controller", "kp", QJsonArray{4500});
    }) << "controller.kp: must have 2 entries";
    QTest::newRow("kp string entry") << edit([&](QJsonObject &o) {
        inSection(o, "controller", "kp", QJsonArray{4500, "nan"});
    }) << "controller.kp[1]: must be a number, got \"nan\"";
    QTest::newRow("gain beyond REAL32")
        << edit([&](QJsonObject &o) {
               inSection(o, "controller", "ki", QJsonArray{3e104, 30});
           })
        << "controller.ki[0]: the drives store it as REAL32, so it must be a finite number of at "
           "most 3.40282e+38 in magnitude, got 3e+104";
    QTest::newRow("value beyond REAL32")
        << edit([&](QJsonObject &o) { inListEntry(o, "parameters", 1, "value", -1e39); })
        << "parameters[1].value: the drives store it as REAL32";
    QTest::newRow("unknown law") << edit([&](QJsonObject &o) {
        inSection(o, "identification", "law", "guess");
    }) << "identification.law: unknown learning law \"guess\"";
    QTest::newRow("too few parameters") << edit([](QJsonObject &o) {
        QJsonArray a = o.value("parameters").toArray();
        a.removeLast();
        o.insert("parameters", a);
    }) << "parameters: must have 3 entries (one per parameter of paper-2link), got 2";
    QTest::newRow("wrong parameter name")
        << edit([&](QJsonObject &o) { inListEntry(o, "parameters", 0, "name", "alpha"); })
        << "parameters[0].name: must be \"a\" (parameter 1 of paper-2link), got \"alpha\"";
    QTest::newRow("value null") << edit([&](QJsonObject &o) {
        inListEntry(o, "parameters", 2, "value", QJsonValue());
    }) << "parameters[2].value: must be a number, got null";
    QTest::newRow("std partly given") << edit([&](QJsonObject &o) {
        inListEntry(o, "parameters", 1, "standardDeviation", QJsonValue(QJsonValue::Undefined));
    }) << "parameters[1].standardDeviation: must be given for every parameter or for none";
    QTest::newRow("std negative") << edit([&](QJsonObject &o) {
        inListEntry(o, "parameters", 0, "standardDeviation", -1);
    })
                                  << "parameters[0].standardDeviation: must be zero, a positive "
                                     "number or unbounded (null), got -1";
    QTest::newRow("tracking figure for 3 joints") << edit([&](QJsonObject &o) {
        inSection(o, "quality", "rmsTrackingErrorDeg", QJsonArray{1, 2, 3});
    }) << "quality.rmsTrackingErrorDeg: must have 2 entries";
    QTest::newRow("rank above parameter count")
        << edit([&](QJsonObject &o) { inSection(o, "quality", "rank", 4); })
        << "quality.rank: must be an integer from 0 to 3, got 4";
    QTest::newRow("node 0") << edit([&](QJsonObject &o) {
        inListEntry(o, "canWrites", 0, "node", 0);
    }) << "canWrites[0].node: must be an integer from 1 to 127, got 0";
    QTest::newRow("index not hex")
        << edit([&](QJsonObject &o) { inListEntry(o, "canWrites", 1, "index", 8704); })
        << "canWrites[1].index: must be a string, got 8704";
    QTest::newRow("index format") << edit([&](QJsonObject &o) {
        inListEntry(o, "canWrites", 1, "index", "2200h");
    }) << "canWrites[1].index: must be an object index written as \"0x\" and four hex digits";
    QTest::newRow("raw odd hex") << edit([&](QJsonObject &o) {
        inListEntry(o, "canWrites", 2, "raw", "abc");
    }) << "canWrites[2].raw: must be the bytes written as pairs of hex digits, got \"abc\"";
    QTest::newRow("subindex 256") << edit([&](QJsonObject &o) {
        inListEntry(o, "canWrites", 0, "subindex", 256);
    }) << "canWrites[0].subindex: must be an integer from 0 to 255, got 256";
    QTest::newRow("duplicate joint node") << edit([&](QJsonObject &o) {
        inSection(o, "robot", "jointNodes", QJsonArray{4, 4});
    }) << "robot.jointNodes[1]: node 4 is given to two joints";
}

void TestParameterFile::badField_isRejectedWithKeyPath()
{
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    const QString message = readError(json);
    QVERIFY2(message.startsWith(QStringLiteral("robot.params.json: ") + expected),
             qPrintable(message));
}

void TestParameterFile::inconsistentContent_isRefusedOnWrite_data()
{
    QTest::addColumn<int>("change");
    QTest::addColumn<QString>("expected");
    QTest::newRow("nan value") << 0 << "parameters[1].value: must be a finite number, got nan";
    QTest::newRow("values short") << 1
                                  << "parameters: must have 3 entries (values, one per parameter";
    QTest::newRow("std length") << 2 << "parameters: must have 3 entries (standard deviations";
    QTest::newRow("no created") << 3 << "created: must be a valid date and time";
    QTest::newRow("unknown model") << 4 << "robot.model: unknown model \"scara\"";
    QTest::newRow("empty raw") << 5 << "canWrites[0].raw: must hold the bytes written";
    QTest::newRow("kp negative") << 6 << "controller.kp[0]: must be a positive number, got -1";
}

void TestParameterFile::inconsistentContent_isRefusedOnWrite()
{
    QFETCH(int, change);
    QFETCH(QString, expected);
    ParameterFileContent c = sampleParameterFile();
    switch (change) {
    case 0:
        c.values[1] = std::numeric_limits<double>::quiet_NaN();
        break;
    case 1:
        c.values.resize(2);
        break;
    case 2:
        c.standardDeviations.resize(4);
        c.standardDeviations.setZero();
        break;
    case 3:
        c.created = QDateTime();
        break;
    case 4:
        c.robotModel = QStringLiteral("scara");
        break;
    case 5:
        c.canWrites[0].raw.clear();
        break;
    case 6:
        c.controller.kp[0] = -1.0;
        break;
    }
    const QString message = test::errorOf([&] { parameterFileToJson(c); });
    QVERIFY2(message.startsWith(expected), qPrintable(message));
}

void TestParameterFile::parameterFile_writesAndReadsBackThroughAFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("robot.params.json"));
    writeFileAtomically(path, parameterFileToJson(sampleParameterFile()));
    compareContent(readParameterFile(path), sampleParameterFile());
    LEARNID_VERIFY_ERROR(readParameterFile(dir.filePath(QStringLiteral("none.json"))),
                         QStringLiteral("No such file or directory"));
}

QTEST_GUILESS_MAIN(TestParameterFile)
#include "tst_parameterfile.moc"
