// `learnid-cli identify` on 1 kHz controller logs as a Franka Panda's logger writes them
// (synthetic: tests/support/SyntheticRobotLog.h): the gaps and stale rows of issue 22 accepted,
// the summary's words and plurals, the report named after the robot file; and gaps beyond what
// the fit's filter tolerates refused naming file and line, with nothing written.
#include "../support/SyntheticRobotLog.h"
#include "../support/ToolRun.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

// A 2-joint log at 1 kHz, 60 rows, the rows [from, to) lost and the rows [staleFrom, staleTo)
// holding the values of the row before them.
QByteArray oneKilohertz(int from, int to, int staleFrom, int staleTo)
{
    QByteArray csv = "t,q1,q2,dq1,dq2,tau1,tau2\n";
    for (int k = 0; k < 60; ++k) {
        if (k >= from && k < to)
            continue;
        const int v = k >= staleFrom && k < staleTo ? staleFrom - 1 : k;
        csv += QByteArray::number(k * 0.001) + ',' + QByteArray::number(0.001 * v) + ",0.2," +
               QByteArray::number(v) + ",1," + QByteArray::number(0.5 * v) + ",2\n";
    }
    return csv;
}

} // namespace

class TestCliIdentify1kHz : public QObject
{
    Q_OBJECT

private slots:
    void pandaLog_gapsAndStaleRows_summaryAndReportNameTheRobotFile();
    void badGaps_exitWithFileAndLineAndWriteNothing_data();
    void badGaps_exitWithFileAndLineAndWriteNothing();

private:
    static test::ToolRun cli(const QStringList &args, const QString &dir)
    {
        return test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, dir);
    }
};

void TestCliIdentify1kHz::pandaLog_gapsAndStaleRows_summaryAndReportNameTheRobotFile()
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
    // The summary's sentences are wrapped (the PDF prints lines as they are).
    for (const QString &line : r.out.left(r.out.indexOf(QStringLiteral("Identified parameters")))
                                   .split(QLatin1Char('\n')))
        QVERIFY2(line.size() <= 100, qPrintable(line));
    QVERIFY2(r.err.contains(QStringLiteral("fitting 91 standard parameters to 1 log\n")),
             qPrintable(r.err));
    // The validation table: a row per joint.
    const QString table = r.out.mid(r.out.indexOf(QStringLiteral("validation on run2.csv")));
    static const QRegularExpression jointRow(QStringLiteral("(?m)^\\s+\\d panda_joint\\d "));
    QCOMPARE(table.count(jointRow), 7);

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

void TestCliIdentify1kHz::badGaps_exitWithFileAndLineAndWriteNothing_data()
{
    QTest::addColumn<QByteArray>("log");
    QTest::addColumn<QStringList>("extraArgs");
    QTest::addColumn<QString>("message");
    // 30 ms: three times what the fit's filter tolerates by default.
    QTest::newRow("gap beyond the filter's bound")
        << oneKilohertz(20, 49, -1, -1) << QStringList()
        << QStringLiteral("log.csv: line 22: a gap of 30 ms after the sample at t = 0.019 s, "
                          "more than the 10 ms allowed (--max-gap; by default half the time "
                          "constant 1/rho of the fit's filter, rho = 50 rad/s");
    QTest::newRow("stale rows leaving a gap")
        << oneKilohertz(-1, -1, 20, 35) << QStringList()
        << QStringLiteral("log.csv: line 37: a gap of 16 ms after the sample at t = 0.019 s "
                          "(lines 22 to 36 are stale: 15 rows that repeated the values of line "
                          "21 under new time stamps and count as missing), more than the 10 ms "
                          "allowed");
    QTest::newRow("--max-gap of the user")
        << oneKilohertz(20, 49, -1, -1)
        << QStringList{QStringLiteral("--max-gap"), QStringLiteral("25")}
        << QStringLiteral("more than the 25 ms allowed (--max-gap)");
}

void TestCliIdentify1kHz::badGaps_exitWithFileAndLineAndWriteNothing()
{
    QFETCH(QByteArray, log);
    QFETCH(QStringList, extraArgs);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QFile file(dir.filePath(QStringLiteral("log.csv")));
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(log) == log.size());
    file.close();
    const test::ToolRun r =
        cli(QStringList{QStringLiteral("identify"), QStringLiteral("--robot"),
                        QStringLiteral("double-pendulum"), QStringLiteral("--log"),
                        QStringLiteral("log.csv"), QStringLiteral("--export"),
                        QStringLiteral("params.json"), QStringLiteral("--urdf-out"),
                        QStringLiteral("robot.urdf"), QStringLiteral("--report"),
                        QStringLiteral("report.pdf")} +
                extraArgs,
            dir.path());
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(QStringLiteral("learnid-cli: error: log.csv: line ")),
             qPrintable(r.err));
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("log.csv")});
}

QTEST_GUILESS_MAIN(TestCliIdentify1kHz)
#include "tst_cli_identify1khz.moc"
