// The parameter file's versions: what version 1 files hold is still read, and version 2's
// additions (a file without controller gains, the whole model as standard parameters with what
// the data determined) round-trip and are checked.
#include "IoTestSupport.h"
#include "ParameterFileSample.h"
#include "io/ParameterFile.h"
#include "model/Error.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <cmath>
#include <limits>

using namespace learnid;
using learnid::test::bitEqual;
using learnid::test::sampleParameterFile;

namespace {

const QString source = QStringLiteral("robot.params.json");

QJsonObject sampleObject()
{
    return QJsonDocument::fromJson(parameterFileToJson(sampleParameterFile())).object();
}

// The object with a new, correct checksum: what another tool (or an older learnid) writes.
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

class TestParameterFileVersions : public QObject
{
    Q_OBJECT

private slots:
    void schemaMismatch_isRejected();
    void version1File_isStillRead();
    void modelAlone_withoutGainsAndWithStandardParameters_roundTrips();
};

void TestParameterFileVersions::schemaMismatch_isRejected()
{
    QJsonObject o = sampleObject();
    o.insert(QStringLiteral("schema"), QStringLiteral("learnid-parameters/3"));
    QCOMPARE(readError(withChecksum(o)),
             QStringLiteral("robot.params.json: schema: this version of learnid reads "
                            "\"learnid-parameters/2\" and \"learnid-parameters/1\", got "
                            "\"learnid-parameters/3\""));
}

void TestParameterFileVersions::version1File_isStillRead()
{
    // What learnid wrote before version 2: no standard parameters, always a controller.
    QJsonObject o = sampleObject();
    o.insert(QStringLiteral("schema"), QStringLiteral("learnid-parameters/1"));
    o.remove(QStringLiteral("standardParameters"));
    const ParameterFileContent c = parameterFileFromJson(withChecksum(o), source);
    const ParameterFileContent sample = sampleParameterFile();
    QVERIFY(bitEqual(c.values, sample.values));
    QVERIFY(bitEqual(c.controller.kp, sample.controller.kp));
    QCOMPARE(c.canWrites.size(), sample.canWrites.size());
    QVERIFY(c.hasController);
    QVERIFY(c.standardParameters.isEmpty());
    // Version 1 knows neither key of version 2.
    o.insert(QStringLiteral("standardParameters"), QJsonArray());
    QVERIFY(readError(withChecksum(o))
                .startsWith(QStringLiteral("robot.params.json: standardParameters: unknown key")));
    o.remove(QStringLiteral("standardParameters"));
    o.insert(QStringLiteral("controller"), QJsonValue::Null);
    QVERIFY(
        readError(withChecksum(o)).startsWith(QStringLiteral("robot.params.json: controller: ")));
}

void TestParameterFileVersions::modelAlone_withoutGainsAndWithStandardParameters_roundTrips()
{
    ParameterFileContent c = sampleParameterFile();
    c.hasController = false;
    c.controller = ControllerSettings();
    c.canWrites.removeFirst(); // the 0x2100 gain write
    c.jointNodes = {3, 4};
    c.standardParameters = {{QStringLiteral("m1"), QStringLiteral("kg"), QStringLiteral("mass"),
                             QStringLiteral("link 1")},
                            {QStringLiteral("τo1"), QStringLiteral("N m"), QStringLiteral("offset"),
                             QStringLiteral("joint 1")},
                            {QStringLiteral("fv1"), QStringLiteral("N m s/rad"),
                             QStringLiteral("viscous"), QStringLiteral("joint 1")}};
    c.standardValues = Eigen::Vector3d(2.5, -0.35, 0.1);
    c.standardDetermined = {0.25, 0.97, std::numeric_limits<double>::quiet_NaN()};
    const QByteArray json = parameterFileToJson(c);
    QVERIFY(json.contains("\"controller\": null"));
    QVERIFY(json.contains("\"determined\": 0.97,\n            \"source\": \"data\""));
    QVERIFY(json.contains("\"determined\": 0.25,\n            \"source\": \"prior\""));
    QVERIFY(json.contains("\"determined\": null,\n            \"source\": \"unknown\""));
    const ParameterFileContent back = parameterFileFromJson(json, source);
    QVERIFY(!back.hasController);
    QCOMPARE(back.dof(), 2);
    QCOMPARE(back.nodes(), (QList<int>{3, 4}));
    QCOMPARE(back.standardParameters.size(), 3);
    QCOMPARE(back.standardParameters.at(1).name, QStringLiteral("τo1"));
    QVERIFY(bitEqual(back.standardValues, c.standardValues));
    QCOMPARE(back.standardDetermined[0], 0.25);
    QCOMPARE(back.standardDetermined[1], 0.97);
    QVERIFY(std::isnan(back.standardDetermined[2]));
    // Its DCF fragment holds the parameters alone.
    const QByteArray dcf = parameterDcfFragment(back, 0);
    QVERIFY(dcf.contains("SupportedObjects=1\n1=0x2200"));
    QVERIFY(!dcf.contains("[2100"));

    // Unknown for all (a session without a path): written as nulls, read back as none known.
    ParameterFileContent unknown = c;
    unknown.standardDetermined.clear();
    QVERIFY(parameterFileFromJson(parameterFileToJson(unknown), source).standardDetermined.empty());

    // A source that does not match the share, a share beyond 1, no nodes without gains.
    QJsonObject o = QJsonDocument::fromJson(json).object();
    QJsonArray standard = o.value(QStringLiteral("standardParameters")).toArray();
    QJsonObject first = standard.at(0).toObject();
    first.insert(QStringLiteral("source"), QStringLiteral("data"));
    standard.replace(0, first);
    o.insert(QStringLiteral("standardParameters"), standard);
    QCOMPARE(readError(withChecksum(o)),
             QStringLiteral("robot.params.json: standardParameters[0].source: must be \"prior\" "
                            "for determined 0.25, got \"data\""));
    first.insert(QStringLiteral("determined"), 1.5);
    standard.replace(0, first);
    o.insert(QStringLiteral("standardParameters"), standard);
    QCOMPARE(readError(withChecksum(o)),
             QStringLiteral("robot.params.json: standardParameters[0].determined: must be a share "
                            "from 0 to 1 or null, got 1.5"));
    c.jointNodes.clear();
    QVERIFY_THROWS_EXCEPTION(Error, parameterFileToJson(c));
}

QTEST_GUILESS_MAIN(TestParameterFileVersions)
#include "tst_parameterfileversions.moc"
