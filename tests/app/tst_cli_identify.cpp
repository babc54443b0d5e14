// End-to-end tests of `learnid-cli identify`: a real robot identified from its recorded logs
// (../shared/data), what the tool prints against what the library computes for the same inputs,
// the files it writes, and the bad inputs it refuses without writing anything.
#include "../support/NumericAssert.h"
#include "../support/SharedData.h"
#include "../support/SyntheticRobotLog.h"
#include "../support/ToolRun.h"
#include "identify/LogFit.h"
#include "identify/UniformLog.h"
#include "io/ParameterFile.h"
#include "io/RobotLogCsv.h"
#include "model/ChainModel.h"
#include "model/UrdfChain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

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
    void plotsAndReport_drawEveryJointOfEveryValidationLog();
    void pandaLog1kHz_gapsAndStaleRows_summaryAndReportNameTheRobotFile();
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

void TestCliIdentify::pandaLog1kHz_gapsAndStaleRows_summaryAndReportNameTheRobotFile()
{
    // A Panda's 1 kHz controller log as issue 22 met it: 8.5 ms gaps every 5 s and 1131 stale
    // rows; the robot given as a URDF file of another name than the URDF's robot.
    QTemporaryDir dir;
    const ChainModel model = test::pandaLogModel();
    const Eigen::VectorXd truth = test::pandaLogTruth(model);
    test::SyntheticLogOptions options;
    const test::SyntheticLog training = test::syntheticPandaLog(model, truth, options);
    options.seconds = 11.0;
    options.seed = 2;
    const test::SyntheticLog validation = test::syntheticPandaLog(model, truth, options);
    const QList<QPair<QString, QByteArray>> files = {
        {QStringLiteral("run1.csv"),
         test::syntheticLogCsv(training, true, test::pickStaleRows(training, 1131, 7))},
        {QStringLiteral("run2.csv"), test::syntheticLogCsv(validation, true)}};
    for (const auto &[name, csv] : files) {
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(csv) == csv.size());
    }
    QVERIFY(QFile::copy(QStringLiteral(":/robots/panda.urdf"),
                        dir.filePath(QStringLiteral("fr3_lab.urdf"))));
    const test::ToolRun r =
        cli({QStringLiteral("identify"), QStringLiteral("--robot"), QStringLiteral("fr3_lab.urdf"),
             QStringLiteral("--log"), QStringLiteral("run1.csv"), QStringLiteral("--validate"),
             QStringLiteral("run2.csv"), QStringLiteral("--report"), QStringLiteral("report.pdf")},
            dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QString out = r.out;
    out.replace(QStringLiteral("\n  "), QStringLiteral(" ")); // sentences are wrapped at 100
    const QStringList expected = {
        QStringLiteral("fr3_lab.urdf (URDF robot \"panda\") in %1, 7 moving joints.")
            .arg(QDir::toNativeSeparators(QFileInfo(dir.path()).canonicalFilePath())),
        QStringLiteral("Fitted to 1 log, "), // a proper plural
        QStringLiteral("run1.csv: 1131 stale rows (values repeated under a new time stamp) "
                       "treated as missing."),
        QStringLiteral("Of the 91 standard parameters, any data could determine at most "),
        QStringLiteral("combinations (the base parameters); these logs determine "),
        QStringLiteral(" base parameters")};
    for (const QString &part : expected)
        QVERIFY2(out.contains(part), qPrintable(part + QStringLiteral("\n") + r.out));
    for (const QString &line : r.out.split(QLatin1Char('\n')))
        QVERIFY2(line.size() <= 100 || line.startsWith(QLatin1String("joint")), qPrintable(line));
    QVERIFY2(r.err.contains(QStringLiteral("fitting 91 standard parameters to 1 log\n")),
             qPrintable(r.err));
    QCOMPARE(readValidationTable(r.out).jointRows, 7);

    // The report's title names the robot as the user gave it (PDF strings are UTF-16BE).
    QFile pdf(dir.filePath(QStringLiteral("report.pdf")));
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    const QByteArray bytes = pdf.readAll();
    const auto utf16 = [](const QString &text) {
        QByteArray b;
        for (const QChar c : text)
            b += char(c.unicode() >> 8), b += char(c.unicode() & 0xff);
        return b;
    };
    QVERIFY(bytes.contains(utf16(QStringLiteral("learnid: fr3_lab.urdf "))));
    QVERIFY(!bytes.contains(utf16(QStringLiteral("learnid: panda "))));
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
    QTest::newRow("no --log") << good << QStringList{QStringLiteral("--no-log")} << 1
                              << QStringList{QStringLiteral("needs at least one --log FILE"),
                                             QStringLiteral("Usage:")};
    QTest::newRow("unknown robot")
        << good << QStringList{QStringLiteral("--robot"), QStringLiteral("no-such-robot")} << 2
        << QStringList{QStringLiteral("--robot: 'no-such-robot' is neither a URDF file")};
    // A 1 kHz log with a 30 ms gap: three times what the fit's filter tolerates by default.
    const auto oneKilohertz = [](int from, int to, int staleFrom, int staleTo) {
        QByteArray csv = "t,q1,q2,dq1,dq2,tau1,tau2\n";
        for (int k = 0; k < 60; ++k) {
            if (k >= from && k < to)
                continue;
            const int v = k >= staleFrom && k < staleTo ? staleFrom - 1 : k;
            csv += QByteArray::number(k * 0.001) + ',' + QByteArray::number(0.001 * v) + ",0.2," +
                   QByteArray::number(v) + ",1," + QByteArray::number(0.5 * v) + ",2\n";
        }
        return csv;
    };
    QTest::newRow("gap beyond the filter's bound")
        << oneKilohertz(20, 49, -1, -1) << QStringList() << 2
        << QStringList{QStringLiteral("log.csv: line 22: a gap of 30 ms after the sample at t = "
                                      "0.019 s, more than the 10 ms allowed (--max-gap; by "
                                      "default half the time constant 1/rho of the fit's filter, "
                                      "rho = 50 rad/s")};
    QTest::newRow("stale rows leaving a gap")
        << oneKilohertz(-1, -1, 20, 35) << QStringList() << 2
        << QStringList{QStringLiteral("log.csv: line 37: a gap of 16 ms after the sample at t = "
                                      "0.019 s (lines 22 to 36 are stale: 15 rows that repeated "
                                      "the values of line 21 under new time stamps and count as "
                                      "missing), more than the 10 ms allowed")};
    QTest::newRow("--max-gap of the user")
        << oneKilohertz(20, 49, -1, -1)
        << QStringList{QStringLiteral("--max-gap"), QStringLiteral("25")} << 2
        << QStringList{QStringLiteral("more than the 25 ms allowed (--max-gap)")};
    // The parameter file records controller gains; the defaults are the paper arm's two.
    QTest::newRow("gains for another robot")
        << good << QStringList{QStringLiteral("--robot"), QStringLiteral("puma560")} << 2
        << QStringList{QStringLiteral("--scenario FILE")};
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
    for (const char *option : {"--robot", "--log", "--validate", "--columns", "--joint-terms",
                               "--rho", "--prior-share", "--velocity", "--max-gap", "--export",
                               "--urdf-out", "--scenario", "--workspace", "--quiet"})
        QVERIFY2(help.out.contains(QLatin1String(option)), option);
}

QTEST_GUILESS_MAIN(TestCliIdentify)
#include "tst_cli_identify.moc"
