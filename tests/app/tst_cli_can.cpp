// learnid-cli's CAN options without a robot on the bus: bad values name the option and the
// value, a configuration above the bus limit is refused with its figures and the SYNC period
// that fits, a bus nobody answers on fails quickly with the node and object, a malformed log
// names file and line.
#include "../support/ToolRun.h"

#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

class TestCliCan : public QObject
{
    Q_OBJECT

private slots:
    void badOption_exitsNamingOptionAndValue_data();
    void badOption_exitsNamingOptionAndValue();
    void silentBus_failsWithinSecondsNamingNodeAndObject();
    void malformedCandump_namesFileAndLine();

private:
    using Result = learnid::test::ToolRun;
    Result cli(const QStringList &args) const
    {
        return learnid::test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, m_dir.path(), 60000);
    }
    QTemporaryDir m_dir;
};

void TestCliCan::badOption_exitsNamingOptionAndValue_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QStringList>("expected");
    const QString run = QStringLiteral("run");
    const QStringList can{run,
                          QStringLiteral("--robot"),
                          QStringLiteral("can"),
                          QStringLiteral("--can-plugin"),
                          QStringLiteral("virtualcan"),
                          QStringLiteral("--can-interface"),
                          QStringLiteral("can0")};
    QTest::newRow("unknown robot")
        << QStringList{run, QStringLiteral("--robot"), QStringLiteral("ship")} << 2
        << QStringList{QStringLiteral("--robot"), QStringLiteral("ship")};
    QTest::newRow("plugin without can")
        << QStringList{run, QStringLiteral("--can-plugin"), QStringLiteral("x")} << 1
        << QStringList{QStringLiteral("--can-plugin"), QStringLiteral("--robot can")};
    QTest::newRow("no plugin") << QStringList{run, QStringLiteral("--robot"), QStringLiteral("can")}
                               << 2 << QStringList{QStringLiteral("--can-plugin")};
    QTest::newRow("bad node") << can + QStringList{QStringLiteral("--nodes"), QStringLiteral("1,x")}
                              << 2 << QStringList{QStringLiteral("--nodes"), QStringLiteral("'x'")};
    QTest::newRow("sync timeout 0")
        << can + QStringList{QStringLiteral("--can-sync-timeout"), QStringLiteral("0")} << 2
        << QStringList{QStringLiteral("--can-sync-timeout"), QStringLiteral("'0'")};
    QTest::newRow("sync timeout without can")
        << QStringList{run, QStringLiteral("--can-sync-timeout"), QStringLiteral("200")} << 1
        << QStringList{QStringLiteral("--can-sync-timeout needs --robot can")};
    QTest::newRow("node twice") << can +
                                       QStringList{QStringLiteral("--nodes"), QStringLiteral("3,3")}
                                << 2
                                << QStringList{QStringLiteral("--nodes"), QStringLiteral("node 3")};
    // A 6-axis robot (the built-in PUMA 560) at the default 2 ms: the load of its 6 nodes.
    const QString puma = m_dir.filePath(QStringLiteral("puma560.json"));
    QFile f(puma);
    if (f.open(QIODevice::WriteOnly)) {
        f.write(R"({"schema": "learnid-scenario/2", "robot": {"model": "puma560"},
            "path": {"kind": "waypoints",
                     "waypoints": [[0, 0.5, -0.5, 0, 0.3, 0], [0.6, 0.2, -0.2, 0.5, -0.3, 0.4]]},
            "controller": {"kp": [2000, 4000, 1500, 50, 50, 30], "ki": [20, 40, 15, 1, 1, 1],
                           "kd": [200, 400, 150, 5, 5, 3]}})");
    }
    QTest::newRow("bus overloaded")
        << can + QStringList{QStringLiteral("--scenario"), puma, QStringLiteral("--nodes"),
                             QStringLiteral("1,2,3,4,5,6")}
        << 2
        << QStringList{QStringLiteral("--nodes 1,2,3,4,5,6"), QStringLiteral("84.3 %"),
                       QStringLiteral("70 %"),
                       QStringLiteral("shortest SYNC period that fits is 3 ms")};
    QTest::newRow("nodes of another robot")
        << can + QStringList{QStringLiteral("--nodes"), QStringLiteral("1,2,3")} << 2
        << QStringList{QStringLiteral("--nodes 1,2,3"),
                       QStringLiteral("3 node ids for a robot of 2 joints")};
    QTest::newRow("unknown plugin") << QStringList{run,
                                                   QStringLiteral("--robot"),
                                                   QStringLiteral("can"),
                                                   QStringLiteral("--can-plugin"),
                                                   QStringLiteral("nosuchplugin"),
                                                   QStringLiteral("--can-interface"),
                                                   QStringLiteral("can0")}
                                    << 3 << QStringList{QStringLiteral("nosuchplugin")};
    QTest::newRow("replay without log")
        << QStringList{QStringLiteral("replay")} << 1 << QStringList{QStringLiteral("--candump")};
}

void TestCliCan::badOption_exitsNamingOptionAndValue()
{
    QFETCH(QStringList, args);
    QFETCH(int, exitCode);
    QFETCH(QStringList, expected);
    const Result r = cli(args);
    QVERIFY2(r.exitCode == exitCode, qPrintable(QString::number(r.exitCode) + r.err));
    for (const QString &e : expected)
        QVERIFY2(r.err.contains(e), qPrintable(r.err));
}

void TestCliCan::silentBus_failsWithinSecondsNamingNodeAndObject()
{
    // virtualcan on a free port: the tool hosts the bus itself, and no drive answers.
    QTcpServer probe;
    QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
    const quint16 port = probe.serverPort();
    probe.close();
    const Result r =
        cli({QStringLiteral("run"), QStringLiteral("--robot"), QStringLiteral("can"),
             QStringLiteral("--can-plugin"), QStringLiteral("virtualcan"),
             QStringLiteral("--can-interface"), QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port),
             QStringLiteral("--iterations"), QStringLiteral("1")});
    QVERIFY2(r.exitCode == 3, qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("node 1")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("0x1018:01")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("500 ms")), qPrintable(r.err));
    QVERIFY2(r.ms < 5000, qPrintable(QString::number(r.ms)));
    // The trial that never moved: no figures to show, said so; every sentence ends once.
    QVERIFY2(r.err.contains(QLatin1String("no samples recorded")), qPrintable(r.err));
    QVERIFY2(!r.err.contains(QLatin1String("max tracking error  deg")), qPrintable(r.err));
    QVERIFY2(!r.err.contains(QLatin1String(".;")) && !r.err.contains(QLatin1String("..")),
             qPrintable(r.err));
}

void TestCliCan::malformedCandump_namesFileAndLine()
{
    QFile f(m_dir.filePath(QStringLiteral("bad.log")));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("(1.000000) can0 080#01\n(1.002000) can0 zz#\n");
    f.close();
    const Result r = cli({QStringLiteral("replay"), QStringLiteral("--candump"), f.fileName()});
    QVERIFY2(r.exitCode == 2, qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("bad.log:2")), qPrintable(r.err));
}

QTEST_GUILESS_MAIN(TestCliCan)
#include "tst_cli_can.moc"
