// The DCF fragment learnid exports against the drive learnid-robot-sim serves: a drive set up
// from the DCF must be the drive the master talks to (one object table behind both).
#include "CanSimTestBus.h"
#include "can/PayloadObjects.h"
#include "can/SdoAbortCode.h"
#include "cansim/CanArmSimulator.h"
#include "cansim/ScenarioCanArm.h"
#include "io/ParameterFile.h"
#include "model/ModelFactory.h"
#include "types/Scenario.h"

#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>

using namespace learnid;
using canopen::DataType;

namespace {

ParameterFileContent contentFor(const Scenario &scenario)
{
    ParameterFileContent c;
    c.robotModel = scenario.model;
    c.controller = scenario.controller;
    c.created = QDateTime::currentDateTimeUtc();
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.law = QStringLiteral("improved");
    c.parameters = makeRobotModel(c.robotModel)->parameters();
    c.values = Eigen::Vector3d(20.25, 5.5, 8.125);
    // A payload on joint 2, as a payload session's file writes it (0x2500 in the fragment).
    Eigen::VectorXd body(10);
    body << 0.5, 0.025, 0.0, 0.01, 1e-3, 0.0, 1e-3, 0.0, 0.0, 5e-4;
    c.canWrites = objects::payloadWrites(c.nodes(), 2, body);
    return c;
}

} // namespace

class TestDcfDrive : public QObject
{
    Q_OBJECT

private slots:
    void exportedDcf_describesEachObjectTheDriveAnswers();
};

// Every entry of the fragment: the drive has it, with the DCF's data type (the size of what an
// SDO upload returns), its default (a fresh drive's value), and its access (a read-only entry
// refuses the write of its own value, a read-write one takes it). And one sub-index past each
// object's last one does not exist on the drive either.
void TestDcfDrive::exportedDcf_describesEachObjectTheDriveAnswers()
{
    const Scenario scenario; // the paper scenario, as learnid-robot-sim serves it by default
    test::CanSimTestBus net;
    CanArmSimulator sim(
        &net.slaveLink,
        canArmSettings(scenario, makeRobotModel(scenario.model, scenario.urdf), {1, 2}));
    const ParameterFileContent content = contentFor(scenario);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QRegularExpression entryName(QStringLiteral("^([0-9A-F]{4})sub([0-9A-F]+)$"));
    for (int joint = 0; joint < 2; ++joint) {
        const QString file = dir.filePath(QStringLiteral("joint%1.dcf").arg(joint));
        QFile out(file);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(parameterDcfFragment(content, joint));
        out.close();
        QSettings dcf(file, QSettings::IniFormat);
        QCOMPARE(dcf.status(), QSettings::NoError);
        const quint8 node = quint8(dcf.value(QStringLiteral("DeviceComissioning/NodeID")).toInt());
        QCOMPARE(node, quint8(joint + 1));

        int entries = 0;
        for (const QString &group : dcf.childGroups()) {
            const QRegularExpressionMatch m = entryName.match(group);
            if (!m.hasMatch())
                continue;
            ++entries;
            const quint16 index = quint16(m.captured(1).toUInt(nullptr, 16));
            const quint8 sub = quint8(m.captured(2).toUInt(nullptr, 16));
            dcf.beginGroup(group);
            const auto type =
                DataType(dcf.value(QStringLiteral("DataType")).toString().toUInt(nullptr, 16));
            const QString access = dcf.value(QStringLiteral("AccessType")).toString();
            const double defaultValue = dcf.value(QStringLiteral("DefaultValue")).toDouble();
            dcf.endGroup();
            const QString where = QStringLiteral("node %1, 0x%2:%3")
                                      .arg(node)
                                      .arg(index, 4, 16, QLatin1Char('0'))
                                      .arg(sub);

            const SdoResult read = net.read(node, index, sub);
            QVERIFY2(read.ok(), qPrintable(where + QStringLiteral(": ") + read.errorMessage));
            QVERIFY2(read.data.size() == canopen::dataTypeSize(type), qPrintable(where));
            const double value = canopen::decodeValue(type, read.data);
            QVERIFY2(value ==
                         (type == DataType::Real32 ? double(float(defaultValue)) : defaultValue),
                     qPrintable(QStringLiteral("%1: the drive holds %2, the DCF's default is %3")
                                    .arg(where)
                                    .arg(value)
                                    .arg(defaultValue)));

            const SdoResult write = net.writeRaw(node, index, sub, read.data);
            if (access == QLatin1String("ro")) {
                QVERIFY2(write.abortCode == sdoabort::readOnly, qPrintable(where));
            } else {
                QCOMPARE(access, QStringLiteral("rw"));
                QVERIFY2(write.ok(), qPrintable(where + QStringLiteral(": ") + write.errorMessage));
            }
            const QString next = QStringLiteral("%1sub%2")
                                     .arg(m.captured(1))
                                     .arg(QString::number(sub + 1, 16).toUpper());
            if (!dcf.childGroups().contains(next)) {
                const SdoResult beyond = net.read(node, index, quint8(sub + 1));
                QVERIFY2(beyond.abortCode == sdoabort::subIndexDoesNotExist,
                         qPrintable(where + QStringLiteral(" is the last entry in the DCF")));
            }
        }
        QCOMPARE(entries, 5 + 1 + 3 + 12); // 0x2100:00..04, 0x2200:00..03, 0x2500:00..0B
    }
}

QTEST_GUILESS_MAIN(TestDcfDrive)
#include "tst_dcfdrive.moc"
