// `learnid-cli identify --payload --export/--urdf-out` on simulated KUKA LWR4+ logs with a 3 kg
// payload (PayloadLogs.h): the parameter file reads back to the arm as given plus the payload
// section, the URDF read back (urdfdom, the model's reader) gives the torques of the arm's model
// plus that payload; an arm identified earlier (identify --export without a payload) serves as
// --robot; a CAD arm draws a warning; bad input writes nothing.

#include "../support/NumericAssert.h"
#include "../support/RandomStates.h"
#include "../support/SharedData.h"
#include "../support/ToolRun.h"
#include "PayloadLogs.h"
#include "io/ParameterFile.h"
#include "model/UrdfChain.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>
#include <random>
#include <urdf_parser/urdf_parser.h>

using namespace learnid;

namespace {

const QString cli = QStringLiteral(LEARNID_CLI_PATH);

QStringList payloadArgs(const QString &robot, const QString &log)
{
    return {QStringLiteral("identify"),
            QStringLiteral("--robot"),
            robot,
            QStringLiteral("--log"),
            log,
            QStringLiteral("--payload"),
            QStringLiteral("--payload-mass"),
            QStringLiteral("2.5"),
            QStringLiteral("--payload-com"),
            QStringLiteral("0,0,0.05"),
            QStringLiteral("--quiet")};
}

} // namespace

class TestCliPayloadExport : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void exportAndUrdf_holdTheArmPlusThePayload();
    void armFromAnEarlierExport_isHeldFixed();
    void badInput_namesTheFileAndWritesNothing();

private:
    QTemporaryDir m_dir;
    QString m_urdf, m_rich, m_armOnly;
    std::shared_ptr<const ChainModel> m_arm;
};

void TestCliPayloadExport::initTestCase()
{
    m_urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    m_arm = test::kukaArm();
    if (!m_arm)
        QSKIP(qPrintable(test::sharedDataMissing()));
    const PayloadModel model(m_arm, m_arm->cadStandard());
    m_rich = m_dir.filePath(QStringLiteral("rich.csv"));
    m_armOnly = m_dir.filePath(QStringLiteral("arm.csv"));
    QVERIFY(test::writeFile(m_rich, test::payloadLog(model, test::richPath(*m_arm, 5.0), 1)));
    QVERIFY(test::writeFile(m_armOnly, test::payloadLog(model, test::richPath(*m_arm, 5.0), 4,
                                                        InertialParameters::Zero())));
}

void TestCliPayloadExport::exportAndUrdf_holdTheArmPlusThePayload()
{
    const QString json = m_dir.filePath(QStringLiteral("with-payload.json"));
    const QString urdf = m_dir.filePath(QStringLiteral("with-payload.urdf"));
    const test::ToolRun run =
        test::runTool(cli, payloadArgs(m_urdf, m_rich) << QStringLiteral("--export") << json
                                                       << QStringLiteral("--urdf-out") << urdf);
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    // The CAD URDF as the arm: said so.
    QVERIFY2(run.out.contains(QStringLiteral("Warning: the arm's model is")), qPrintable(run.out));

    const ParameterFileContent file = readParameterFile(json);
    QVERIFY(file.payload.has_value());
    const ParameterFilePayload &p = *file.payload;
    QCOMPARE(p.link, QStringLiteral("lwr_7_link"));
    QCOMPARE(file.robotModel, QStringLiteral("urdf"));
    // The arm as it was given, bit for bit; the payload as the table printed it (mass within 1 %,
    // centre of mass within 3 mm of the truth, each with its uncertainty).
    QVERIFY(file.standardValues == m_arm->cadStandard());
    QVERIFY2(std::abs(p.mass - 3.0) < 0.03, qPrintable(QString::number(p.mass)));
    QVERIFY((p.com - test::truePayload().com).norm() < 0.003);
    for (size_t i = 0; i < 4; ++i) {
        QVERIFY(p.identified[i]);
        QVERIFY(std::isfinite(p.standardUncertainty[i]) && p.standardUncertainty[i] > 0.0);
    }
    QVERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("with-payload.dcf"))));

    // urdfdom reads the payload link with the file's numbers.
    QFile text(urdf);
    QVERIFY(text.open(QIODevice::ReadOnly));
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text.readAll().toStdString());
    QVERIFY(model && model->getLink("payload") && model->getLink("payload")->inertial);
    QCOMPARE(model->getLink("payload")->inertial->mass, p.mass);
    QCOMPARE(QString::fromStdString(model->getLink("payload")->getParent()->name), p.link);

    // The URDF alone gives the torques of the arm's model plus the file's payload.
    const ChainModel loaded(readUrdfChain(urdf), m_arm->jointTerms(), QStringLiteral("urdf"));
    const PayloadModel arm(m_arm, file.standardValues);
    const InertialParameters pi = p.parameters();
    Eigen::MatrixXd y(7, loaded.standardCount());
    test::forRandomStates(7, 7, 10, [&](const auto &q, const auto &qd, const auto &qdd) {
        loaded.standardRegressor(q, qd, qdd, y);
        LEARNID_COMPARE_MATRIX(y * loaded.cadStandard(), arm.torqueAt(q, qd, qdd, pi), 1e-9);
    });
}

void TestCliPayloadExport::armFromAnEarlierExport_isHeldFixed()
{
    // The arm identified first, without the payload; then the payload on that file.
    const QString armJson = m_dir.filePath(QStringLiteral("arm.json"));
    const QString armUrdf = m_dir.filePath(QStringLiteral("arm.urdf"));
    const test::ToolRun arm =
        test::runTool(cli, {QStringLiteral("identify"), QStringLiteral("--robot"), m_urdf,
                            QStringLiteral("--log"), m_armOnly, QStringLiteral("--export"), armJson,
                            QStringLiteral("--urdf-out"), armUrdf, QStringLiteral("--quiet")});
    QVERIFY2(arm.exitCode == 0, qPrintable(arm.err));
    const ParameterFileContent armFile = readParameterFile(armJson);
    // The identified URDF is an identified arm too: no warning.
    const test::ToolRun onUrdf = test::runTool(cli, payloadArgs(armUrdf, m_rich));
    QVERIFY2(onUrdf.exitCode == 0, qPrintable(onUrdf.err));
    QVERIFY2(!onUrdf.out.contains(QStringLiteral("Warning: the arm's model")),
             qPrintable(onUrdf.out));

    const QString json = m_dir.filePath(QStringLiteral("arm+payload.json"));
    const test::ToolRun run =
        test::runTool(cli, payloadArgs(armJson, m_rich) << QStringLiteral("--arm-urdf") << m_urdf
                                                        << QStringLiteral("--export") << json);
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QVERIFY2(!run.out.contains(QStringLiteral("Warning: the arm's model")), qPrintable(run.out));
    QVERIFY(run.out.contains(QDir::toNativeSeparators(armJson)));
    const ParameterFileContent file = readParameterFile(json);
    // The arm's model is the earlier file's, with what its data determined.
    QVERIFY(file.standardValues == armFile.standardValues);
    QVERIFY(file.standardDetermined == armFile.standardDetermined);
    QVERIFY(file.payload && std::abs(file.payload->mass - 3.0) < 0.03);

    // Without the URDF a "urdf" file cannot be placed: the message says what to give.
    const test::ToolRun bare = test::runTool(cli, payloadArgs(armJson, m_rich));
    QCOMPARE(bare.exitCode, 2);
    QVERIFY2(bare.err.contains(QStringLiteral("robot.model is \"urdf\"")) &&
                 bare.err.contains(QStringLiteral("--arm-urdf")),
             qPrintable(bare.err));
}

void TestCliPayloadExport::badInput_namesTheFileAndWritesNothing()
{
    QTemporaryDir work;
    // The KUKA's arm file (armFromAnEarlierExport) placed on another robot's URDF: its standard
    // parameters do not fit that model.
    const QString armJson = m_dir.filePath(QStringLiteral("arm.json"));
    QVERIFY(QFileInfo::exists(armJson));
    const QString pendulum = work.filePath(QStringLiteral("pendulum.urdf"));
    QFile builtIn(QStringLiteral(":/robots/double-pendulum.urdf"));
    QVERIFY(builtIn.open(QIODevice::ReadOnly));
    QVERIFY(test::writeFile(pendulum, builtIn.readAll()));
    const QString out = work.filePath(QStringLiteral("out"));
    QVERIFY(QDir().mkpath(out));
    const test::ToolRun run = test::runTool(
        cli, payloadArgs(armJson, m_rich)
                 << QStringLiteral("--arm-urdf") << pendulum << QStringLiteral("--export")
                 << QDir(out).filePath(QStringLiteral("p.json")) << QStringLiteral("--urdf-out")
                 << QDir(out).filePath(QStringLiteral("p.urdf")));
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(QDir::toNativeSeparators(armJson)) &&
                 run.err.contains(QStringLiteral("standardParameters")),
             qPrintable(run.err));
    QVERIFY(QDir(out).entryList(QDir::NoDotAndDotDot | QDir::AllEntries).isEmpty());
}

QTEST_MAIN(TestCliPayloadExport)
#include "tst_cli_payload_export.moc"
