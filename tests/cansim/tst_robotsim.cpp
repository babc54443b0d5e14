// The learnid-robot-sim executable: its command line errors, and one start and stop over
// virtualcan on a loopback port of this test's own.
#include "can/CanLink.h"
#include "can/CanOpen.h"
#include "can/Nmt.h"
#include "can/SdoClient.h"

#include "../support/RobotSimProcess.h"

#include <QCanBus>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>
#include <arpa/inet.h>
#include <cmath>
#include <fcntl.h>
#include <memory>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

class TestRobotSim : public QObject
{
    Q_OBJECT

private slots:
    void badCommandLine_exitsWithUsageCodeNamingOptionAndValue_data();
    void badCommandLine_exitsWithUsageCodeNamingOptionAndValue();
    void help_listsEveryOption();
    void virtualcan_printsReady_writesState_andStopsWhenStdinCloses();
    void sigterm_stopsCleanly();
    void virtualcanClient_getsSdoAnswersSyncsAndTpdos();
    void hostThatNeverAccepts_failsAfterTheConnectTimeout();

private:
    static QStringList bus(int port)
    {
        return {QStringLiteral("--can-plugin"), QStringLiteral("virtualcan"),
                QStringLiteral("--can-interface"),
                QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port)};
    }
};

void TestRobotSim::badCommandLine_exitsWithUsageCodeNamingOptionAndValue_data()
{
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    const QStringList vc = {"--can-plugin", "virtualcan", "--can-interface",
                            "tcp://127.0.0.1:1/can0"};
    QTest::newRow("no plugin") << QStringList{"--can-interface", "can0"}
                               << "--can-plugin is required";
    QTest::newRow("unknown plugin")
        << QStringList{"--can-plugin", "nosuch", "--can-interface", "can0"}
        << "--can-plugin: unknown plugin 'nosuch'";
    QTest::newRow("no interface") << QStringList{"--can-plugin", "virtualcan"}
                                  << "--can-interface is required";
    QTest::newRow("node not a number") << (vc + QStringList{"--nodes", "1,x"}) << "--nodes: 'x'";
    QTest::newRow("node 128") << (vc + QStringList{"--nodes", "1,128"}) << "--nodes: '128'";
    QTest::newRow("node twice") << (vc + QStringList{"--nodes", "3,3"})
                                << "--nodes: node 3 is listed twice";
    QTest::newRow("three nodes for two joints")
        << (vc + QStringList{"--nodes", "1,2,3"}) << "--nodes: the paper-2link arm has 2 joints";
    QTest::newRow("drop fraction 2")
        << (vc + QStringList{"--drop-fraction", "2"}) << "--drop-fraction: '2'";
    QTest::newRow("silent after -1")
        << (vc + QStringList{"--silent-after", "-1"}) << "--silent-after: '-1'";
    QTest::newRow("emcy at sample 0")
        << (vc + QStringList{"--emcy-at-sample", "0"}) << "--emcy-at-sample: '0'";
    QTest::newRow("refuse-sdo without sub")
        << (vc + QStringList{"--refuse-sdo", "0x2200"}) << "--refuse-sdo: '0x2200'";
    QTest::newRow("refuse-sdo sub 256")
        << (vc + QStringList{"--refuse-sdo", "2200:256"}) << "--refuse-sdo: '2200:256'";
    QTest::newRow("missing scenario")
        << (vc + QStringList{"--scenario", "no-such-scenario.json"}) << "no-such-scenario.json";
    QTest::newRow("unknown option") << (vc + QStringList{"--frobnicate"}) << "frobnicate";
    QTest::newRow("stray argument") << (vc + QStringList{"extra"}) << "unexpected argument 'extra'";
}

void TestRobotSim::badCommandLine_exitsWithUsageCodeNamingOptionAndValue()
{
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QProcess p;
    p.setWorkingDirectory(dir.path());
    p.start(QStringLiteral(LEARNID_ROBOT_SIM_PATH), args);
    QVERIFY(p.waitForFinished(20000));
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 2);
    QVERIFY2(err.contains(QStringLiteral("learnid-robot-sim: error: ")), qPrintable(err));
    QVERIFY2(err.contains(message), qPrintable(err));
    QVERIFY(p.readAllStandardOutput().isEmpty());
}

void TestRobotSim::help_listsEveryOption()
{
    QProcess p;
    p.start(QStringLiteral(LEARNID_ROBOT_SIM_PATH), {QStringLiteral("--help")});
    QVERIFY(p.waitForFinished(20000));
    QCOMPARE(p.exitCode(), 0);
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    for (const char *option :
         {"--can-plugin", "--can-interface", "--nodes", "--scenario", "--state", "--drop-fraction",
          "--silent-after", "--emcy-at-sample", "--refuse-sdo"})
        QVERIFY2(out.contains(QLatin1String(option)), option);
}

void TestRobotSim::virtualcan_printsReady_writesState_andStopsWhenStdinCloses()
{
    QTemporaryDir dir;
    const QString state = dir.filePath(QStringLiteral("state.json"));
    QProcess p;
    p.start(QStringLiteral(LEARNID_ROBOT_SIM_PATH),
            bus(learnid::test::freeLoopbackPort()) + QStringList{QStringLiteral("--nodes"),
                                                                 QStringLiteral("7,9"),
                                                                 QStringLiteral("--state"), state});
    QTRY_VERIFY_WITH_TIMEOUT(p.canReadLine() || p.state() == QProcess::NotRunning, 10000);
    QCOMPARE(p.readLine().trimmed(), QByteArray("ready"));
    QFile f(state);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QJsonObject nodes =
        QJsonDocument::fromJson(f.readAll()).object().value("nodes").toObject();
    QCOMPARE(nodes.keys(), (QStringList{"7", "9"}));
    p.closeWriteChannel();
    QVERIFY(p.waitForFinished(5000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 0);
}

void TestRobotSim::sigterm_stopsCleanly()
{
    QProcess p;
    p.start(QStringLiteral(LEARNID_ROBOT_SIM_PATH), bus(learnid::test::freeLoopbackPort()));
    QTRY_VERIFY_WITH_TIMEOUT(p.canReadLine() || p.state() == QProcess::NotRunning, 10000);
    QCOMPARE(p.readLine().trimmed(), QByteArray("ready"));
    p.terminate(); // SIGTERM
    QVERIFY(p.waitForFinished(5000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 0);
    QVERIFY(p.readAllStandardError().contains("SIGTERM"));
}

void TestRobotSim::virtualcanClient_getsSdoAnswersSyncsAndTpdos()
{
    const QStringList args = bus(learnid::test::freeLoopbackPort());
    QProcess p;
    p.start(QStringLiteral(LEARNID_ROBOT_SIM_PATH), args);
    QTRY_VERIFY_WITH_TIMEOUT(p.canReadLine() || p.state() == QProcess::NotRunning, 10000);
    QCOMPARE(p.readLine().trimmed(), QByteArray("ready"));

    std::unique_ptr<QCanBusDevice> device(
        QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), args.last()));
    QVERIFY(device);
    learnid::CanLink link(device.get());
    learnid::SdoClient sdo(&link);
    QList<QCanBusFrame> frames;
    connect(&link, &learnid::CanLink::frameReceived,
            [&frames](const QCanBusFrame &f) { frames.append(f); });
    QVERIFY(device->connectDevice());
    QTRY_COMPARE_WITH_TIMEOUT(device->state(), QCanBusDevice::ConnectedState, 3000);

    QSignalSpy done(&sdo, &learnid::SdoClient::finished);
    sdo.upload(2, 0x1000, 0);
    QVERIFY(done.wait(2000));
    const learnid::SdoResult r = done.at(0).at(0).value<learnid::SdoResult>();
    QVERIFY2(r.ok(), qPrintable(r.errorMessage));
    QCOMPARE(learnid::canopen::readU32(r.data, 0), 0x00020192u);

    QVERIFY(link.send(learnid::nmtCommandFrame(learnid::NmtCommand::Start, 0)));
    QTest::qWait(100);
    frames.clear();
    QElapsedTimer clock;
    clock.start();
    QTest::qWait(500);
    const double seconds = clock.elapsed() / 1000.0;
    int syncs = 0;
    int tpdos = 0;
    for (const QCanBusFrame &f : frames) {
        syncs += f.frameId() == 0x80;
        tpdos += f.frameId() == 0x181 || f.frameId() == 0x182;
    }
    qInfo("%d SYNCs and %d TPDOs in %.3f s", syncs, tpdos, seconds);
    // 500 SYNCs per second, each followed by both TPDOs (a loaded machine may lose some ticks).
    QVERIFY2(syncs > 0.5 * 500 * seconds && syncs < 1.1 * 500 * seconds + 2,
             qPrintable(QString::number(syncs)));
    QVERIFY(std::abs(tpdos - 2 * syncs) <= 2);
    device->disconnectDevice();
    p.closeWriteChannel();
    QVERIFY(p.waitForFinished(5000));
    QCOMPARE(p.exitCode(), 0);
}

void TestRobotSim::hostThatNeverAccepts_failsAfterTheConnectTimeout()
{
    // A loopback port whose listen queue is full: the port is taken (virtualcan cannot host
    // there, so it connects as a client) and connection attempts hang, as with an unreachable
    // host.
    QList<int> fds;
    const int server = ::socket(AF_INET, SOCK_STREAM, 0);
    fds << server;
    sockaddr_in address = {};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    QVERIFY(::bind(server, reinterpret_cast<sockaddr *>(&address), length) == 0);
    QVERIFY(::listen(server, 0) == 0);
    QVERIFY(::getsockname(server, reinterpret_cast<sockaddr *>(&address), &length) == 0);
    for (int i = 0; i < 3; ++i) {
        const int client = ::socket(AF_INET, SOCK_STREAM, 0);
        ::fcntl(client, F_SETFL, O_NONBLOCK);
        ::connect(client, reinterpret_cast<sockaddr *>(&address), length);
        fds << client;
    }
    QProcess p;
    QElapsedTimer clock;
    clock.start();
    p.start(QStringLiteral(LEARNID_ROBOT_SIM_PATH), bus(ntohs(address.sin_port)));
    const bool finished = p.waitForFinished(15000);
    const qint64 elapsed = clock.elapsed();
    for (const int fd : fds)
        ::close(fd);
    QVERIFY(finished);
    QCOMPARE(p.exitCode(), 1);
    const QString err = QString::fromUtf8(p.readAllStandardError());
    QVERIFY2(err.contains(QStringLiteral("did not connect within 3 s")), qPrintable(err));
    QVERIFY2(elapsed >= 2900 && elapsed < 8000, qPrintable(QString::number(elapsed)));
    QVERIFY(p.readAllStandardOutput().isEmpty());
}

QTEST_GUILESS_MAIN(TestRobotSim)
#include "tst_robotsim.moc"
