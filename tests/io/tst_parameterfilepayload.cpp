// The parameter file's optional payload section: it writes and reads back bit-exactly, files
// without it read as before, and every bad value is refused naming its key path.

#include "IoTestSupport.h"
#include "ParameterFileSample.h"
#include "io/ParameterFile.h"
#include "model/ChainModel.h"
#include "model/ModelFactory.h"
#include "model/UrdfChain.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <cmath>

using namespace learnid;
using learnid::test::bitEqual;

namespace {

const QString source = QStringLiteral("arm+payload.json");

// The built-in double pendulum's CAD model as an identification from logs exports it.
ParameterFileContent armFile(const QString &model = QStringLiteral("double-pendulum"))
{
    const auto arm = std::dynamic_pointer_cast<const ChainModel>(
        makeRobotModel(QStringLiteral("double-pendulum")));
    ParameterFileContent c;
    c.robotModel = model;
    c.robotDescription = QStringLiteral("double pendulum, identified from logs");
    c.hasController = false;
    c.jointNodes = {1, 2};
    c.created = QDateTime(QDate(2026, 11, 27), QTime(1, 2, 3, 456), Qt::UTC);
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.law = QStringLiteral("improved");
    c.parameters = arm->parameters();
    c.values = arm->baseFromStandard(arm->cadStandard());
    c.standardParameters = arm->standardParameters();
    c.standardValues = arm->cadStandard();
    c.condition = std::numeric_limits<double>::infinity();
    return c;
}

ParameterFilePayload payload()
{
    ParameterFilePayload p;
    p.link = QStringLiteral("link2");
    p.mass = 0.30000000000000004;
    p.com = Eigen::Vector3d(0.01, -0.002, 1.0 / 3.0);
    p.inertiaAtCom = {2e-3, 1e-4, 2.5e-3, 0.0, -2e-4, 1e-3};
    p.identified = {true, true, false, true, false, false, true, false, false, false};
    for (size_t i = 0; i < 10; ++i)
        if (p.identified[i])
            p.standardUncertainty[i] = 1e-3 * double(i + 1) / 7.0;
    p.standardUncertainty[6] = std::nan(""); // identified, no uncertainty
    return p;
}

QJsonObject fileObject(const ParameterFileContent &c)
{
    return QJsonDocument::fromJson(parameterFileToJson(c)).object();
}

QByteArray withChecksum(QJsonObject o)
{
    o.remove(QStringLiteral("checksum"));
    o.insert(QStringLiteral("checksum"), QString::fromLatin1(parameterFileChecksum(o)));
    return QJsonDocument(o).toJson();
}

QString readError(const QJsonObject &o)
{
    return test::errorOf([&] { parameterFileFromJson(withChecksum(o), source); });
}

} // namespace

class TestParameterFilePayload : public QObject
{
    Q_OBJECT

private slots:
    void payload_roundTripsBitExactly();
    void noPayload_writesNoSectionAndReadsNone();
    void section_standsBetweenStandardParametersAndQuality();
    void badSection_isRefusedNamingTheKey_data();
    void badSection_isRefusedNamingTheKey();
    void nanOrNoLink_isRefusedOnWrite();
    void urdfModel_linkIsCheckedAgainstItsChain();
};

void TestParameterFilePayload::payload_roundTripsBitExactly()
{
    ParameterFileContent c = armFile();
    c.payload = payload();
    const ParameterFileContent back = parameterFileFromJson(parameterFileToJson(c), source);
    QVERIFY(back.payload.has_value());
    const ParameterFilePayload &a = *c.payload, &b = *back.payload;
    QCOMPARE(b.link, a.link);
    QVERIFY(bitEqual(b.mass, a.mass));
    QVERIFY(bitEqual(b.com, a.com));
    for (size_t i = 0; i < 6; ++i)
        QVERIFY(bitEqual(b.inertiaAtCom[i], a.inertiaAtCom[i]));
    QCOMPARE(b.identified, a.identified);
    for (size_t i = 0; i < 10; ++i) // NaN (not available) reads back as NaN
        QVERIFY2(bitEqual(b.standardUncertainty[i], a.standardUncertainty[i]) ||
                     (std::isnan(a.standardUncertainty[i]) && std::isnan(b.standardUncertainty[i])),
                 qPrintable(QString::number(i)));
    QVERIFY(bitEqual(back.standardValues, c.standardValues));
    // The 10 parameters by the parallel axis theorem: Ixx = Ic_xx + m (cy^2 + cz^2).
    const InertialParameters pi = b.parameters();
    QCOMPARE(pi[3], a.mass * a.com.z());
    QVERIFY(std::abs(pi[4] - (2e-3 + a.mass * (0.002 * 0.002 + 1.0 / 9.0))) < 1e-15);
}

void TestParameterFilePayload::noPayload_writesNoSectionAndReadsNone()
{
    const ParameterFileContent c = armFile();
    const QByteArray json = parameterFileToJson(c);
    QVERIFY(!json.contains("\"payload\""));
    QVERIFY(!parameterFileFromJson(json, source).payload.has_value());
}

void TestParameterFilePayload::section_standsBetweenStandardParametersAndQuality()
{
    ParameterFileContent c = armFile();
    c.payload = payload();
    const QByteArray json = parameterFileToJson(c);
    const qsizetype standard = json.indexOf("\"standardParameters\"");
    const qsizetype section = json.indexOf("\"payload\"");
    const qsizetype quality = json.indexOf("\"quality\"");
    QVERIFY(standard >= 0 && standard < section && section < quality);
    QVERIFY(json.contains(R"("source": ["data", "data", "prior", "data", "prior")"));
}

void TestParameterFilePayload::badSection_isRefusedNamingTheKey_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<QJsonValue>("value");
    QTest::addColumn<QString>("message");
    QTest::newRow("zero mass") << "mass" << QJsonValue(0.0)
                               << "payload.mass: must be a positive number";
    QTest::newRow("negative mass") << "mass" << QJsonValue(-3.0) << "payload.mass:";
    QTest::newRow("mass text") << "mass" << QJsonValue(QStringLiteral("3")) << "payload.mass:";
    QTest::newRow("com of two") << "com" << QJsonValue(QJsonArray{0.0, 0.1}) << "payload.com:";
    QTest::newRow("com null") << "com" << QJsonValue(QJsonArray{0.0, QJsonValue(), 0.1})
                              << "payload.com[1]:";
    QTest::newRow("inertia not a body")
        << "inertiaAtCom" << QJsonValue(QJsonArray{1e-3, 0.0, 1e-3, 0.0, 0.0, 5e-3})
        << "payload.inertiaAtCom: is not a real body";
    QTest::newRow("unknown link") << "link" << QJsonValue(QStringLiteral("gripper"))
                                  << "payload.link: payload link 'gripper' is not a moving link";
    // Fixed to the world, not to a moving link.
    QTest::newRow("base link") << "link" << QJsonValue(QStringLiteral("base_link"))
                               << "payload.link: payload link 'base_link'";
    QJsonArray sources;
    for (int i = 0; i < 10; ++i)
        sources.append(i == 3 ? QStringLiteral("maybe") : QStringLiteral("data"));
    QTest::newRow("bad source") << "source" << QJsonValue(sources) << "payload.source[3]:";
    QJsonArray uncertainties;
    for (int i = 0; i < 10; ++i)
        uncertainties.append(0.001);
    QTest::newRow("uncertainty of a prior value")
        << "standardUncertainty" << QJsonValue(uncertainties)
        << "payload.standardUncertainty[2]: must be null for a value kept at the prior";
    uncertainties[0] = -1.0;
    QTest::newRow("negative uncertainty")
        << "standardUncertainty" << QJsonValue(uncertainties) << "payload.standardUncertainty[0]:";
    QTest::newRow("unknown key") << "colour" << QJsonValue(QStringLiteral("red"))
                                 << "payload.colour: unknown key";
    QTest::newRow("no link") << "-link" << QJsonValue() << "payload.link: is missing";
}

void TestParameterFilePayload::badSection_isRefusedNamingTheKey()
{
    QFETCH(QString, field);
    QFETCH(QJsonValue, value);
    QFETCH(QString, message);
    ParameterFileContent c = armFile();
    c.payload = payload();
    QJsonObject root = fileObject(c);
    QJsonObject section = root.value(QStringLiteral("payload")).toObject();
    if (field.startsWith(QLatin1Char('-')))
        section.remove(field.mid(1));
    else
        section.insert(field, value);
    root.insert(QStringLiteral("payload"), section);
    const QString error = readError(root);
    QVERIFY2(error.startsWith(source + QStringLiteral(": ")) && error.contains(message),
             qPrintable(error));
}

void TestParameterFilePayload::nanOrNoLink_isRefusedOnWrite()
{
    ParameterFileContent c = armFile();
    c.payload = payload();
    c.payload->com.y() = std::nan("");
    LEARNID_VERIFY_ERROR(parameterFileToJson(c), QStringLiteral("payload.com[1]:"));
    c.payload = payload();
    c.payload->mass = std::nan("");
    LEARNID_VERIFY_ERROR(parameterFileToJson(c), QStringLiteral("payload.mass:"));
    c.payload = payload();
    c.payload->link.clear();
    LEARNID_VERIFY_ERROR(parameterFileToJson(c), QStringLiteral("payload.link: must name"));
    // The paper's closed-form arm has no links.
    ParameterFileContent paper = test::sampleParameterFile();
    paper.payload = payload();
    LEARNID_VERIFY_ERROR(parameterFileToJson(paper), QStringLiteral("payload: the model"));
    // Version 1 knows no payload: the key is unknown there.
    ParameterFileContent v2 = armFile();
    v2.payload = payload();
    QJsonObject v1 = fileObject(test::sampleParameterFile());
    v1.insert(QStringLiteral("payload"), fileObject(v2).value(QStringLiteral("payload")));
    v1.insert(QStringLiteral("schema"), QStringLiteral("learnid-parameters/1"));
    v1.remove(QStringLiteral("standardParameters"));
    QVERIFY2(readError(v1).contains(QStringLiteral("payload: unknown key")),
             qPrintable(readError(v1)));
}

void TestParameterFilePayload::urdfModel_linkIsCheckedAgainstItsChain()
{
    // A "urdf" file does not carry its URDF: the link is checked when the file meets it.
    ParameterFileContent c = armFile(QStringLiteral("urdf"));
    c.payload = payload();
    c.payload->link = QStringLiteral("flange");
    const ParameterFileContent back = parameterFileFromJson(parameterFileToJson(c), source);
    const auto arm = std::dynamic_pointer_cast<const ChainModel>(
        makeRobotModel(QStringLiteral("double-pendulum")));
    LEARNID_VERIFY_ERROR(
        checkPayloadLink(*back.payload, arm->chain()),
        QStringLiteral("payload.link: payload link 'flange' is not a moving link"));
    c.payload->link = QStringLiteral("link1");
    QCOMPARE(checkPayloadLink(*c.payload, arm->chain()), 0);
    // "tool" is fixed to link2 and merged into its body: the payload is on link2's body.
    c.payload->link = QStringLiteral("tool");
    QCOMPARE(checkPayloadLink(*c.payload, arm->chain()), 1);
}

QTEST_GUILESS_MAIN(TestParameterFilePayload)
#include "tst_parameterfilepayload.moc"
