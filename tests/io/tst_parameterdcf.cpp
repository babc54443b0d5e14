#include "IoTestSupport.h"
#include "ParameterFileSample.h"
#include "can/PayloadObjects.h"
#include "io/ParameterFile.h"

#include <QMap>
#include <QTest>

using namespace learnid;
using learnid::test::sampleParameterFile;

namespace {

using IniSections = QMap<QString, QMap<QString, QString>>;

// A strict INI reader: comments start with ';', a section may appear once, every other line is
// key=value inside a section.
IniSections parseIni(const QByteArray &text)
{
    IniSections sections;
    QString current;
    for (const QByteArray &raw : text.split('\n')) {
        const QString line = QString::fromUtf8(raw).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char(';')))
            continue;
        if (line.startsWith(QLatin1Char('['))) {
            if (!line.endsWith(QLatin1Char(']')))
                throw Error(QStringLiteral("bad section line: ") + line);
            current = line.mid(1, line.size() - 2);
            if (sections.contains(current))
                throw Error(QStringLiteral("duplicate section: ") + current);
            sections[current];
            continue;
        }
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        if (current.isEmpty() || eq <= 0)
            throw Error(QStringLiteral("bad line: ") + line);
        const QString key = line.left(eq);
        if (sections[current].contains(key))
            throw Error(QStringLiteral("duplicate key: ") + key);
        sections[current][key] = line.mid(eq + 1);
    }
    return sections;
}

float real32(const IniSections &ini, const QString &section)
{
    bool ok = false;
    const float v = ini.value(section).value(QStringLiteral("ParameterValue")).toFloat(&ok);
    return ok ? v : -12345.0f;
}

} // namespace

class TestParameterDcf : public QObject
{
    Q_OBJECT

private slots:
    void jointFragment_holdsGainsAndParametersAsRealObjects();
    void jointFragment_namesItsNode();
    void wholeFragment_hasOneSectionSetPerNode();
    void real32Values_readBackToTheSameFloat();
    void jointOutOfRange_isRejected();
    void valueBeyondReal32_isRejected();
    void payloadWrites_becomeThePayloadObjectOfEachNode();
    void payloadWrittenInPart_isRejectedNamingTheEntry();
};

void TestParameterDcf::jointFragment_holdsGainsAndParametersAsRealObjects()
{
    const ParameterFileContent c = sampleParameterFile();
    const IniSections ini = parseIni(parameterDcfFragment(c, 1));

    QCOMPARE(ini.value("ManufacturerObjects").value("SupportedObjects"), QStringLiteral("2"));
    QCOMPARE(ini.value("ManufacturerObjects").value("1"), QStringLiteral("0x2100"));
    QCOMPARE(ini.value("ManufacturerObjects").value("2"), QStringLiteral("0x2200"));

    QCOMPARE(ini.value("2100").value("ObjectType"), QStringLiteral("0x9"));
    QCOMPARE(ini.value("2100").value("SubNumber"), QStringLiteral("5"));
    QCOMPARE(ini.value("2100sub0").value("DataType"), QStringLiteral("0x0005"));
    QCOMPARE(ini.value("2100sub0").value("AccessType"), QStringLiteral("ro"));
    QCOMPARE(ini.value("2100sub0").value("ParameterValue"), QStringLiteral("4"));
    const double gains[] = {c.controller.kp[1], c.controller.ki[1], c.controller.kd[1],
                            c.controller.lambda};
    for (int s = 1; s <= 4; ++s) {
        const QString section = QStringLiteral("2100sub%1").arg(s);
        QCOMPARE(ini.value(section).value("ObjectType"), QStringLiteral("0x7"));
        QCOMPARE(ini.value(section).value("DataType"), QStringLiteral("0x0008"));
        QCOMPARE(ini.value(section).value("AccessType"), QStringLiteral("rw"));
        QCOMPARE(real32(ini, section), float(gains[s - 1]));
        // The drive is set up from the same controller: its default is the configured gain.
        QCOMPARE(ini.value(section).value("DefaultValue"),
                 ini.value(section).value("ParameterValue"));
    }
    QCOMPARE(ini.value("2100sub1").value("ParameterName"), QStringLiteral("Gain kp [N m/rad]"));
    QCOMPARE(ini.value("2100sub1").value("ParameterValue"), QStringLiteral("5000"));

    QCOMPARE(ini.value("2200").value("ObjectType"), QStringLiteral("0x8"));
    QCOMPARE(ini.value("2200").value("SubNumber"), QStringLiteral("4"));
    // Sub 0 is the count apply writes (read-write, 0 until then), as docs/can-protocol.md says.
    QCOMPARE(ini.value("2200sub0").value("DataType"), QStringLiteral("0x0005"));
    QCOMPARE(ini.value("2200sub0").value("AccessType"), QStringLiteral("rw"));
    QCOMPARE(ini.value("2200sub0").value("DefaultValue"), QStringLiteral("0"));
    QCOMPARE(ini.value("2200sub0").value("ParameterValue"), QStringLiteral("3"));
    for (int i = 0; i < 3; ++i) {
        const QString section = QStringLiteral("2200sub%1").arg(i + 1);
        QCOMPARE(ini.value(section).value("DataType"), QStringLiteral("0x0008"));
        QCOMPARE(ini.value(section).value("ParameterName"),
                 c.parameters.at(i).name + QStringLiteral(" [kg m^2]"));
        QCOMPARE(real32(ini, section), float(c.values[i]));
        QCOMPARE(ini.value(section).value("DefaultValue"), QStringLiteral("0"));
    }
    QVERIFY(!ini.contains("2200sub4"));
}

void TestParameterDcf::jointFragment_namesItsNode()
{
    ParameterFileContent c = sampleParameterFile();
    QCOMPARE(parseIni(parameterDcfFragment(c, 0)).value("DeviceComissioning").value("NodeID"),
             QStringLiteral("1"));
    c.jointNodes = {12, 5};
    QCOMPARE(parseIni(parameterDcfFragment(c, 1)).value("DeviceComissioning").value("NodeID"),
             QStringLiteral("5"));
}

void TestParameterDcf::wholeFragment_hasOneSectionSetPerNode()
{
    ParameterFileContent c = sampleParameterFile();
    c.jointNodes = {12, 5};
    const QByteArray all = parameterDcfFragment(c);
    QCOMPARE(all, parameterDcfFragment(c, 0) + parameterDcfFragment(c, 1));
    // Split as docs/file-formats.md says: before each [DeviceComissioning] and its comments.
    const QList<QByteArray> parts = all.split('\n');
    QList<QByteArray> blocks;
    for (const QByteArray &line : parts) {
        if (line.startsWith("; learnid identified parameters"))
            blocks.append(QByteArray());
        QVERIFY(!blocks.isEmpty());
        blocks.last() += line + '\n';
    }
    QCOMPARE(blocks.size(), 2);
    QCOMPARE(parseIni(blocks.at(0)).value("DeviceComissioning").value("NodeID"),
             QStringLiteral("12"));
    QCOMPARE(parseIni(blocks.at(1)).value("DeviceComissioning").value("NodeID"),
             QStringLiteral("5"));
    QCOMPARE(real32(parseIni(blocks.at(0)), "2100sub1"), float(c.controller.kp[0]));
    QCOMPARE(real32(parseIni(blocks.at(1)), "2100sub1"), float(c.controller.kp[1]));
}

void TestParameterDcf::real32Values_readBackToTheSameFloat()
{
    ParameterFileContent c = sampleParameterFile();
    const double values[] = {1.0 / 3.0, -2.5e-20, 3.4e38, 0.1, 16777217.0, -0.0};
    for (double v : values) {
        c.values[0] = v;
        const IniSections ini = parseIni(parameterDcfFragment(c, 0));
        QCOMPARE(real32(ini, "2200sub1"), float(v));
    }
}

void TestParameterDcf::jointOutOfRange_isRejected()
{
    LEARNID_VERIFY_ERROR(parameterDcfFragment(sampleParameterFile(), 2),
                         QStringLiteral("joint 3 does not exist; the robot has 2 joints"));
}

void TestParameterDcf::valueBeyondReal32_isRejected()
{
    ParameterFileContent c = sampleParameterFile();
    c.values[2] = 1e39;
    LEARNID_VERIFY_ERROR(parameterDcfFragment(c, 0),
                         QStringLiteral("parameters[2].value: the drives store it as REAL32, so it "
                                        "must be a finite number of at "
                                        "most 3.40282e+38 in magnitude, got 1e+39"));
}

// The payload's body as a payload session's file sends it (payloadWrites, joint 2), and the
// fragment of every node holds it as the drive's 0x2500 RECORD.
void TestParameterDcf::payloadWrites_becomeThePayloadObjectOfEachNode()
{
    ParameterFileContent c = sampleParameterFile();
    c.jointNodes = {12, 5};
    Eigen::VectorXd body(10);
    body << 1.5, 0.075, -0.002, 0.12, 0.0121, 5e-4, 0.0113, -1e-4, 2e-5, 0.003;
    c.canWrites += objects::payloadWrites(c.nodes(), 2, body);
    for (int joint = 0; joint < 2; ++joint) {
        const IniSections ini = parseIni(parameterDcfFragment(c, joint));
        QCOMPARE(ini.value("ManufacturerObjects").value("SupportedObjects"), QStringLiteral("3"));
        QCOMPARE(ini.value("ManufacturerObjects").value("3"), QStringLiteral("0x2500"));
        QCOMPARE(ini.value("2500").value("ObjectType"), QStringLiteral("0x9"));
        QCOMPARE(ini.value("2500").value("SubNumber"), QStringLiteral("12"));
        QCOMPARE(ini.value("2500sub0").value("AccessType"), QStringLiteral("ro"));
        QCOMPARE(ini.value("2500sub0").value("ParameterValue"), QStringLiteral("11"));
        QCOMPARE(ini.value("2500sub1").value("DataType"), QStringLiteral("0x0005"));
        QCOMPARE(ini.value("2500sub1").value("ParameterValue"), QStringLiteral("2"));
        QCOMPARE(ini.value("2500sub1").value("DefaultValue"), QStringLiteral("0"));
        for (int i = 0; i < 10; ++i) {
            const QString section =
                QStringLiteral("2500sub") + QString::number(i + 2, 16).toUpper();
            QCOMPARE(ini.value(section).value("DataType"), QStringLiteral("0x0008"));
            QCOMPARE(ini.value(section).value("AccessType"), QStringLiteral("rw"));
            QCOMPARE(real32(ini, section), float(body[i]));
        }
        QCOMPARE(ini.value("2500sub2").value("ParameterName"), QStringLiteral("Payload m [kg]"));
        QCOMPARE(ini.value("2500sub5").value("ParameterName"),
                 QStringLiteral("Payload m cz [kg m]"));
        QCOMPARE(ini.value("2500subB").value("ParameterName"),
                 QStringLiteral("Payload Izz [kg m^2]"));
        QVERIFY(!ini.contains("2500subC"));
    }
}

void TestParameterDcf::payloadWrittenInPart_isRejectedNamingTheEntry()
{
    ParameterFileContent c = sampleParameterFile();
    QList<SdoWrite> writes = objects::payloadWrites(c.nodes(), 1, Eigen::VectorXd::Ones(10));
    writes.removeIf([](const SdoWrite &w) { return w.node == 2 && w.subIndex == 5; });
    c.canWrites += writes;
    QVERIFY(parseIni(parameterDcfFragment(c, 0)).contains("2500subB"));
    LEARNID_VERIFY_ERROR(parameterDcfFragment(c, 1),
                         QStringLiteral("canWrites (node 2, 0x2500:05): the payload object is "
                                        "written in part"));
}

QTEST_GUILESS_MAIN(TestParameterDcf)
#include "tst_parameterdcf.moc"
