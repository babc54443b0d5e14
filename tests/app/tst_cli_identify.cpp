// End-to-end tests of `learnid-cli identify`: a real robot identified from its recorded logs
// (../shared/data), what the tool prints against what the library computes for the same inputs,
// the files it writes, and the bad inputs it refuses without writing anything.
#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "../support/ToolRun.h"
#include "identify/LogFit.h"
#include "identify/UniformLog.h"
#include "io/ParameterFile.h"
#include "io/RobotLogCsv.h"
#include "model/ChainModel.h"
#include "model/UrdfChain.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using namespace learnid;

namespace {

/// What the tool printed for one --validate log.
struct ValidationTable
{
    int jointRows = 0;
    QString givenOverall;      ///< the URDF as given: sqrt(sum e^2 / sum tau^2) [%], as printed
    QString identifiedOverall; ///< the identified parameters' figure, as printed
};

// The first validation table in out: its joint rows and the two overall figures.
ValidationTable readValidationTable(const QString &out)
{
    static const QRegularExpression jointRow(QStringLiteral("^\\s+\\d+ \\S"));
    static const QRegularExpression figure(QStringLiteral("(\\d+\\.\\d+)"));
    ValidationTable table;
    bool inTable = false;
    for (const QString &line : out.split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1String("validation on")))
            inTable = true;
        else if (inTable && jointRow.match(line).hasMatch())
            ++table.jointRows;
        else if (inTable && line.startsWith(QLatin1String("overall"))) {
            QStringList figures;
            for (const QRegularExpressionMatch &m : figure.globalMatch(line))
                figures << m.captured(1);
            if (figures.size() == 2) {
                table.givenOverall = figures.at(0);
                table.identifiedOverall = figures.at(1);
            }
            break;
        }
    }
    return table;
}

QString percent(double ratio)
{
    return QString::number(100.0 * ratio, 'f', 3);
}

// The pipeline of bench/realdata.cpp, as the tool runs it with its default settings.
FilteredLog loadLog(const QString &path, const ChainModel &model, const LogColumns &columns)
{
    QList<bool> angular;
    for (const ChainJoint &j : model.chain().joints)
        angular << (j.type == JointType::Revolute);
    return filterLog(resampleUniform(readRobotLogFile(path, model.dof(), columns, angular)),
                     LogFilterSettings{});
}

} // namespace

class TestCliIdentify : public QObject
{
    Q_OBJECT

private slots:
    void doublePendulum_printsTheLibrarysFiguresAndWritesItsFit();
    void kuka_identifiedModelPredictsTheHeldOutRunBetterThanItsUrdf();
    void kuka_exportedUrdfAndParameterFileAloneReproduceThePrintedFigures();
    void plotsAndReport_drawEveryJointOfEveryValidationLog();
    void badInput_exitsWithMessageAndWritesNothing_data();
    void badInput_exitsWithMessageAndWritesNothing();
    void help_listsTheCommandAndItsOptions();

private:
    static test::ToolRun cli(const QStringList &args, const QString &dir)
    {
        return test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, dir);
    }
};

void TestCliIdentify::doublePendulum_printsTheLibrarysFiguresAndWritesItsFit()
{
    QStringList files;
    for (const char *name :
         {"trajectory_00.csv", "trajectory_01.csv", "trajectory_02.csv", "trajectory_03.csv"}) {
        files << test::sharedDataFile(QStringLiteral("double-pendulum/") + QLatin1String(name));
        if (files.constLast().isEmpty())
            QSKIP(qPrintable(test::sharedDataMissing()));
    }
    const QString spec = QStringLiteral("t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1");
    QTemporaryDir dir;
    const test::ToolRun r =
        cli({QStringLiteral("identify"), QStringLiteral("--robot"),
             QStringLiteral("double-pendulum"), QStringLiteral("--columns"), spec,
             QStringLiteral("--log"), files[0], QStringLiteral("--log"), files[1],
             QStringLiteral("--log"), files[2], QStringLiteral("--validate"), files[3],
             QStringLiteral("--export"), QStringLiteral("params.json"),
             QStringLiteral("--urdf-out"), QStringLiteral("identified.urdf")},
            dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(r.err.contains(QStringLiteral("reading"))); // progress on stderr
    const ValidationTable table = readValidationTable(r.out);
    QCOMPARE(table.jointRows, 2);

    // The same inputs through the library in this process.
    const ChainModel model(readUrdfChain(QStringLiteral(":/robots/double-pendulum.urdf")),
                           JointTerms{false, true, true, true}, QStringLiteral("double-pendulum"));
    const LogColumns columns = parseLogColumns(spec);
    const LogFit fit =
        fitLogs(model,
                {loadLog(files[0], model, columns), loadLog(files[1], model, columns),
                 loadLog(files[2], model, columns)},
                LogFitSettings{});
    const FilteredLog validation = loadLog(files[3], model, columns);
    const TorqueFigures given = torqueFigures(model, model.cadStandard(), validation);
    const TorqueFigures identified = torqueFigures(model, fit.standard, validation);
    QCOMPARE(table.identifiedOverall, percent(identified.overall));
    QCOMPARE(table.givenOverall, percent(given.overall));
    QVERIFY(identified.overall < given.overall);

    const ParameterFileContent params =
        readParameterFile(dir.filePath(QStringLiteral("params.json")));
    QCOMPARE(params.robotModel, QStringLiteral("double-pendulum"));
    QCOMPARE(params.parameters.size(), model.parameters().size());
    for (int i = 0; i < int(params.parameters.size()); ++i)
        QCOMPARE(params.parameters.at(i).name, model.parameters().at(i).name);
    LEARNID_COMPARE_MATRIX(params.values, fit.base, 1e-12 * fit.base.cwiseAbs().maxCoeff());
    QVERIFY(QFile::exists(dir.filePath(QStringLiteral("params.dcf"))));

    const SerialChain written = readUrdfChain(dir.filePath(QStringLiteral("identified.urdf")));
    QCOMPARE(written.dof(), 2);
    const int terms = model.jointTerms().count();
    for (int j = 0; j < 2; ++j) {
        const Eigen::VectorXd body = fit.standard.segment<10>(10 * j);
        LEARNID_COMPARE_MATRIX(written.joints[size_t(j)].inertial, body,
                               1e-12 * body.cwiseAbs().maxCoeff());
        LEARNID_COMPARE_NEAR(written.joints[size_t(j)].damping, fit.standard[20 + j * terms],
                             1e-15);
        LEARNID_COMPARE_NEAR(written.joints[size_t(j)].friction, fit.standard[21 + j * terms],
                             1e-15);
    }
}

void TestCliIdentify::kuka_identifiedModelPredictsTheHeldOutRunBetterThanItsUrdf()
{
    const QString urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    const QString run1 = test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_1.csv"));
    const QString run3 = test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_3.csv"));
    if (urdf.isEmpty() || run1.isEmpty() || run3.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    QTemporaryDir dir;
    const test::ToolRun r =
        cli({QStringLiteral("identify"), QStringLiteral("--robot"), urdf, QStringLiteral("--log"),
             run3, QStringLiteral("--validate"), run1, QStringLiteral("--quiet")},
            dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(r.err.isEmpty()); // --quiet
    const ValidationTable table = readValidationTable(r.out);
    QCOMPARE(table.jointRows, 7);
    QVERIFY2(table.identifiedOverall.toDouble() < 3.5, qPrintable(r.out));
    QVERIFY2(table.identifiedOverall.toDouble() < table.givenOverall.toDouble(), qPrintable(r.out));
}

void TestCliIdentify::kuka_exportedUrdfAndParameterFileAloneReproduceThePrintedFigures()
{
    const QString urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    QStringList runs;
    for (const char *name : {"measurements_1.csv", "measurements_2.csv", "measurements_3.csv"})
        runs << test::sharedDataFile(QStringLiteral("kuka-lwr4/") + QLatin1String(name));
    if (urdf.isEmpty() || runs.contains(QString()))
        QSKIP(qPrintable(test::sharedDataMissing()));
    // A 7-joint arm exports without --scenario: the parameter file holds the model alone.
    QTemporaryDir dir;
    const test::ToolRun r =
        cli({QStringLiteral("identify"), QStringLiteral("--robot"), urdf, QStringLiteral("--log"),
             runs[0], QStringLiteral("--log"), runs[1], QStringLiteral("--validate"), runs[2],
             QStringLiteral("--export"), QStringLiteral("lwr.json"), QStringLiteral("--urdf-out"),
             QStringLiteral("lwr.urdf"), QStringLiteral("--quiet")},
            dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const ValidationTable table = readValidationTable(r.out);
    QCOMPARE(table.jointRows, 7);
    const double printed = table.identifiedOverall.toDouble();
    QVERIFY2(printed > 0.0, qPrintable(r.out));
    QVERIFY(r.out.contains(QLatin1String("standard parameters: the URDF's, the identified")));

    // The exported URDF alone, read as a robot: its own values are the identified model,
    // offsets included (learnid's extension element).
    const JointTerms terms{false, true, true, true};
    const QString written = dir.filePath(QStringLiteral("lwr.urdf"));
    const ChainModel exported(readUrdfChain(written), terms, QStringLiteral("urdf"));
    const FilteredLog run3 = loadLog(runs[2], exported, LogColumns{});
    const double fromUrdf = 100.0 * torqueFigures(exported, exported.cadStandard(), run3).overall;
    LEARNID_COMPARE_NEAR(fromUrdf, printed, 0.01);
    // The offsets enter the prediction as the constants they are: F(s)F(-s) passes a constant
    // unchanged, so the torque with and without them differs by each joint's offset.
    SerialChain noOffsets = readUrdfChain(written);
    for (ChainJoint &j : noOffsets.joints)
        j.offset = 0.0;
    const ChainModel withoutOffsets(noOffsets, terms, QStringLiteral("urdf"));
    const Eigen::MatrixXd difference =
        predictedTorque(exported, exported.cadStandard(), run3) -
        predictedTorque(withoutOffsets, withoutOffsets.cadStandard(), run3);
    for (int j = 0; j < 7; ++j) {
        const double offset = exported.chain().joints[size_t(j)].offset;
        LEARNID_COMPARE_NEAR(difference.row(j).minCoeff(), offset, 1e-9 + 1e-6 * std::abs(offset));
        LEARNID_COMPARE_NEAR(difference.row(j).maxCoeff(), offset, 1e-9 + 1e-6 * std::abs(offset));
    }

    // The parameter file alone, with the robot's URDF as given: its standard parameters, and
    // its base parameters, predict the same.
    const ParameterFileContent params = readParameterFile(dir.filePath(QStringLiteral("lwr.json")));
    QVERIFY(!params.hasController);
    const ChainModel cad(readUrdfChain(urdf), terms, QStringLiteral("urdf"));
    QCOMPARE(params.standardValues.size(), cad.standardCount());
    LEARNID_COMPARE_NEAR(100.0 * torqueFigures(cad, params.standardValues, run3).overall, printed,
                         0.01);
    LEARNID_COMPARE_NEAR(100.0 *
                             torqueFigures(cad, cad.standardFromBase(params.values), run3).overall,
                         printed, 0.01);
    // Both files carry the same offsets, the fit's.
    for (int j = 0; j < 7; ++j) {
        const int at = 70 + 3 * j + 2; // per joint: viscous, Coulomb, offset
        QCOMPARE(params.standardParameters.at(at).name.left(2), QStringLiteral("τo"));
        QCOMPARE(params.standardValues[at], exported.chain().joints[size_t(j)].offset);
    }
    int data = 0;
    for (int i = 0; i < cad.standardCount(); ++i)
        data += params.standardDetermined[size_t(i)] >= 0.5;
    QVERIFY2(data > 0 && data < cad.standardCount(), qPrintable(QString::number(data)));
}

void TestCliIdentify::plotsAndReport_drawEveryJointOfEveryValidationLog()
{
    QStringList files;
    for (const char *name : {"trajectory_00.csv", "trajectory_02.csv", "trajectory_03.csv"}) {
        files << test::sharedDataFile(QStringLiteral("double-pendulum/") + QLatin1String(name));
        if (files.constLast().isEmpty())
            QSKIP(qPrintable(test::sharedDataMissing()));
    }
    QTemporaryDir dir;
    const test::ToolRun r =
        cli({QStringLiteral("identify"), QStringLiteral("--robot"),
             QStringLiteral("double-pendulum"), QStringLiteral("--columns"),
             QStringLiteral("t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1"),
             QStringLiteral("--log"), files[0], QStringLiteral("--validate"), files[1],
             QStringLiteral("--validate"), files[2], QStringLiteral("--plots"),
             QStringLiteral("plots"), QStringLiteral("--report"), QStringLiteral("report.pdf")},
            dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    // One PNG per validation log: a panel per joint (2 x 170 px, 14 between, 96 of title,
    // legend and time axis), the identified torque drawn in its blue in every panel.
    for (const char *name : {"trajectory_02-torque.png", "trajectory_03-torque.png"}) {
        QImage image(dir.filePath(QStringLiteral("plots/") + QLatin1String(name)));
        QVERIFY2(!image.isNull(), name);
        QCOMPARE(image.size(), QSize(1200, 56 + 2 * 170 + 14 + 40));
        for (const int panelTop : {56, 56 + 170 + 14}) {
            int blue = 0;
            for (int y = panelTop; y < panelTop + 170; ++y) {
                for (int x = 90; x < 1180; ++x)
                    blue += image.pixelColor(x, y) == QColor(30, 90, 200) ? 1 : 0;
            }
            QVERIFY2(blue > 500, qPrintable(QStringLiteral("%1: %2 blue pixels in the panel at "
                                                           "y = %3")
                                                .arg(QLatin1String(name))
                                                .arg(blue)
                                                .arg(panelTop)));
        }
    }
    // The report: the tables' text, then one page per plot.
    QFile pdf(dir.filePath(QStringLiteral("report.pdf")));
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    const QByteArray bytes = pdf.readAll();
    QVERIFY(bytes.startsWith("%PDF-"));
    QCOMPARE(bytes.count("/Type /Page\n"), 3);
}

void TestCliIdentify::badInput_exitsWithMessageAndWritesNothing_data()
{
    QTest::addColumn<QByteArray>("log");
    QTest::addColumn<QStringList>("extraArgs");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QStringList>("messageParts");

    const QByteArray good = "t,q1,q2,dq1,dq2,tau1,tau2\n0,0,0,0,0,0,0\n0.002,0,0,0,0,0,0\n";
    QTest::newRow("joint count") << QByteArray("t,q1,q2,q3,dq1,dq2,dq3,tau1,tau2,tau3\n"
                                               "0,0,0,0,0,0,0,0,0,0\n")
                                 << QStringList() << 2
                                 << QStringList{QStringLiteral("log.csv: line 1"),
                                                QStringLiteral("3 joints"),
                                                QStringLiteral("the robot 2")};
    QTest::newRow("text in a number")
        << QByteArray("t,q1,q2,dq1,dq2,tau1,tau2\n0,0,0,0,0,0,0\n0.002,0,0,0,abc,0,0\n")
        << QStringList() << 2
        << QStringList{QStringLiteral("log.csv: line 3, column 5 (dq2)"),
                       QStringLiteral("\"abc\"")};
    QTest::newRow("unknown --columns key")
        << good << QStringList{QStringLiteral("--columns"), QStringLiteral("t=t,torque=tau%1")} << 2
        << QStringList{QStringLiteral("--columns: unknown key \"torque\"")};
    QTest::newRow("unknown joint term")
        << good << QStringList{QStringLiteral("--joint-terms"), QStringLiteral("viscous,stiction")}
        << 2 << QStringList{QStringLiteral("--joint-terms: unknown term 'stiction'")};
    QTest::newRow("negative --torque-sensor-lag")
        << good << QStringList{QStringLiteral("--torque-sensor-lag"), QStringLiteral("-1")} << 2
        << QStringList{QStringLiteral("--torque-sensor-lag: must be a number of ms from 0 to "
                                      "1000, got '-1'")};
    QTest::newRow("no --log") << good << QStringList{QStringLiteral("--no-log")} << 1
                              << QStringList{QStringLiteral("needs at least one --log FILE"),
                                             QStringLiteral("Usage:")};
    QTest::newRow("unknown robot")
        << good << QStringList{QStringLiteral("--robot"), QStringLiteral("no-such-robot")} << 2
        << QStringList{QStringLiteral("--robot: 'no-such-robot' is neither a URDF file")};
    // The parameter file records controller gains only from a scenario, which must be read.
    QTest::newRow("missing gains scenario")
        << good << QStringList{QStringLiteral("--scenario"), QStringLiteral("gains.json")} << 2
        << QStringList{QStringLiteral("gains.json")};
}

void TestCliIdentify::badInput_exitsWithMessageAndWritesNothing()
{
    QFETCH(QByteArray, log);
    QFETCH(QStringList, extraArgs);
    QFETCH(int, exitCode);
    QFETCH(QStringList, messageParts);
    QTemporaryDir dir;
    QFile file(dir.filePath(QStringLiteral("log.csv")));
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(log);
    file.close();

    QStringList args{QStringLiteral("identify"), QStringLiteral("--export"),
                     QStringLiteral("params.json"), QStringLiteral("--urdf-out"),
                     QStringLiteral("robot.urdf")};
    if (!extraArgs.contains(QStringLiteral("--robot")))
        args << QStringLiteral("--robot") << QStringLiteral("double-pendulum");
    if (extraArgs.contains(QStringLiteral("--no-log")))
        extraArgs.removeAll(QStringLiteral("--no-log"));
    else
        args << QStringLiteral("--log") << QStringLiteral("log.csv");
    const test::ToolRun r = cli(args + extraArgs, dir.path());
    QCOMPARE(r.exitCode, exitCode);
    QVERIFY2(r.err.contains(QStringLiteral("learnid-cli: error: ")), qPrintable(r.err));
    for (const QString &part : messageParts)
        QVERIFY2(r.err.contains(part), qPrintable(r.err));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("log.csv")});
}

void TestCliIdentify::help_listsTheCommandAndItsOptions()
{
    const test::ToolRun usage = cli({QStringLiteral("--help")}, {});
    QCOMPARE(usage.exitCode, 0);
    QVERIFY(usage.out.contains(QStringLiteral("learnid-cli identify --robot ROBOT --log FILE")));
    const test::ToolRun help = cli({QStringLiteral("identify"), QStringLiteral("--help")}, {});
    QCOMPARE(help.exitCode, 0);
    for (const char *option :
         {"--robot", "--log", "--validate", "--columns", "--joint-terms", "--rho", "--prior-share",
          "--velocity", "--max-gap", "--torque-sensor-lag", "--export", "--urdf-out", "--scenario",
          "--workspace", "--quiet"})
        QVERIFY2(help.out.contains(QLatin1String(option)), option);
}

QTEST_GUILESS_MAIN(TestCliIdentify)
#include "tst_cli_identify.moc"
