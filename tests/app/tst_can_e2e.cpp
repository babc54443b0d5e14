// End to end over virtualcan: learnid-robot-sim and learnid-cli as two processes on a loopback
// port of their own (or over socketcan on a vcan interface, see ../support/CanE2eBus.h). The CAN
// session identifies what the simulated robot's session identifies; a swapped node list is
// refused before any motion (on socketcan: no NMT start, RPDO or SDO write on the bus); every
// fault the simulator injects ends the run with a clear error, quickly, a non-zero exit code and
// the robot's stored parameters unchanged; a recorded trial replays to the same estimate.
#include "can/CandumpLog.h"

#include "../support/CanE2eBus.h"
#include "../support/CanFaultLog.h"
#include "../support/RobotSimProcess.h"
#include "../support/ToolRun.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>

using namespace learnid;

namespace {

using Result = learnid::test::ToolRun;

QJsonObject readJson(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The final estimate of a session report.
QList<double> finalEstimate(const QString &reportPath)
{
    const QJsonObject final = readJson(reportPath).value(QStringLiteral("final")).toObject();
    QList<double> phi;
    for (const QJsonValue &v : final.value(QStringLiteral("phi")).toArray())
        phi << v.toDouble();
    return phi;
}

} // namespace

class TestCanE2e : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void canSession_identifiesAsTheSimulatedRobot();
    void recordedTrials_replayToTheSameEstimate();
    void swappedNodeList_refusedBeforeAnyMotion();
    void fault_endsWithClearErrorQuickly_data();
    void fault_endsWithClearErrorQuickly();

private:
    Result cli(const QStringList &args) const
    {
        return learnid::test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, m_dir.path(), 240000);
    }
    QStringList canRun(quint16 port) const
    {
        return QStringList{QStringLiteral("run"), QStringLiteral("--robot"),
                           QStringLiteral("can")} +
               test::canE2eBusOptions(port) +
               QStringList{// CI runs this beside other tests on 2 cores: a 20 ms stall of the
                           // simulator process is the machine, not the protocol (docs/cli.md).
                           QStringLiteral("--can-sync-timeout"), QStringLiteral("200")} +
               m_scenarioArgs;
    }
    bool startRobot(test::RobotSimProcess &robot, quint16 port, const QStringList &options) const
    {
        if (!test::canE2eOnSocketCan())
            return robot.start(test::canE2eInterface(port), options + m_scenarioArgs);
        return robot.startOn(test::canE2ePlugin(), test::canE2eInterface(port),
                             options + m_scenarioArgs);
    }

    QTemporaryDir m_dir; // the workspace of every run; the logs of the CAN session stay here
    int m_periodMs = 2;
    QStringList m_scenarioArgs; ///< --scenario FILE at a SYNC period other than 2 ms
    QList<double> m_canEstimate;
};

void TestCanE2e::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(QFileInfo::exists(QStringLiteral(LEARNID_CLI_PATH)));
    QVERIFY(QFileInfo::exists(QStringLiteral(LEARNID_ROBOT_SIM_PATH)));
    m_periodMs = test::canE2ePeriodMs(2);
    if (m_periodMs != 2) {
        // The paper scenario at a longer SYNC period, with gains that pass the pre-trial check
        // there (the 2 ms gains are unstable at 10 ms).
        const Result printed = cli({QStringLiteral("scenario"), QStringLiteral("--print")});
        QCOMPARE(printed.exitCode, 0);
        const QByteArray json = test::paperScenarioAt(printed.out.toUtf8(), m_periodMs);
        QVERIFY(!json.isEmpty());
        const QString path = m_dir.filePath(QStringLiteral("paper-%1ms.json").arg(m_periodMs));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly) && f.write(json) == json.size());
        m_scenarioArgs = {QStringLiteral("--scenario"), path};
    }
}

void TestCanE2e::canSession_identifiesAsTheSimulatedRobot()
{
    const Result sim =
        cli(QStringList{QStringLiteral("run"), QStringLiteral("--iterations"), QStringLiteral("3"),
                        QStringLiteral("--report"), QStringLiteral("sim.json")} +
            m_scenarioArgs);
    QCOMPARE(sim.exitCode, 0);
    const QList<double> simEstimate = finalEstimate(m_dir.filePath(QStringLiteral("sim.json")));
    QCOMPARE(simEstimate.size(), 3);
    // The two sessions run the same motion only when every set-point reached its drive in time:
    // a drive holds a late one over (docs/cli.md), and the session's report counts them. A few
    // move the estimate by far less than the tolerance, so the comparison is made on a session
    // with at most 0.25 % of its set-points late; up to three sessions run for one. A machine
    // that is late more often (virtualcan at 2 ms here: 54 to 172 of 13 850, 0.005 % to 0.013 %;
    // the VM of scripts/test-socketcan at 10 ms: up to 20 of 2 800, 0.6 %) is held to 2 % on
    // its session with the fewest: enough to catch a wrong scale, sign or joint on the bus.
    QList<int> late;
    bool compared = false;
    double fewestLateWorst = 0;
    for (int attempt = 0; attempt < 3 && !compared; ++attempt) {
        QVERIFY(QDir(m_dir.filePath(QStringLiteral("logs"))).removeRecursively());
        const quint16 port = test::canE2ePort();
        QVERIFY(port != 0 || test::canE2eOnSocketCan());
        test::RobotSimProcess robot(QStringLiteral(LEARNID_ROBOT_SIM_PATH));
        QVERIFY(
            startRobot(robot, port,
                       {QStringLiteral("--state"), m_dir.filePath(QStringLiteral("state.json"))}));
        const Result can =
            cli(canRun(port) + QStringList{QStringLiteral("--iterations"), QStringLiteral("3"),
                                           QStringLiteral("--report"), QStringLiteral("can.json"),
                                           QStringLiteral("--can-log"), QStringLiteral("logs")});
        const QString robotErr = robot.stderrText();
        QVERIFY2(can.exitCode == 0, qPrintable(can.err + robotErr));
        QVERIFY2(!can.out.contains(QLatin1String("vs truth")), qPrintable(can.out)); // no truth
        // Clean use of the device (socketcan: no bitrate set, the socket closed without a
        // notifier left on it).
        for (const QString &text : {can.err, robotErr}) {
            QVERIFY2(!text.contains(QLatin1String("Cannot apply parameter")), qPrintable(text));
            QVERIFY2(!text.contains(QLatin1String("QSocketNotifier")), qPrintable(text));
        }
        const QJsonObject report = readJson(m_dir.filePath(QStringLiteral("can.json")));
        int lateHere = 0;
        int setpoints = 0;
        for (const QJsonValue &v : report.value(QStringLiteral("trials")).toArray()) {
            const QJsonObject t = v.toObject();
            lateHere += t.value(QStringLiteral("lateSetpoints")).toInt();
            setpoints += t.value(QStringLiteral("samples")).toInt() *
                         int(t.value(QStringLiteral("maxTrackingErrorDeg")).toArray().size());
        }
        QVERIFY(setpoints > 0);
        late << lateHere;
        // Late set-points are said in the trial's line.
        QCOMPARE((can.out + can.err).contains(QLatin1String("reached the drives after")),
                 lateHere > 0);
        m_canEstimate = finalEstimate(m_dir.filePath(QStringLiteral("can.json")));
        QCOMPARE(m_canEstimate.size(), 3);
        double worst = 0;
        for (int i = 0; i < 3; ++i)
            worst = std::max(worst, std::abs(m_canEstimate[i] - simEstimate[i]) /
                                        std::abs(simEstimate[i]));
        qInfo("CAN %.6f %.6f %.6f, simulated %.6f %.6f %.6f: largest difference %.3g %%, %d of "
              "%d set-points late (%lld ms)",
              m_canEstimate[0], m_canEstimate[1], m_canEstimate[2], simEstimate[0], simEstimate[1],
              simEstimate[2], 100 * worst, lateHere, setpoints, can.ms);
        for (int k = 0; k < 3; ++k)
            QVERIFY(QFileInfo::exists(m_dir.filePath(
                QStringLiteral("logs/trial-%1.log").arg(k, 3, 10, QLatin1Char('0')))));
        // Integer positions (2^24 increments) and torques (limit / 25000) on the bus: see
        // docs/can-protocol.md, "Master side".
        compared = lateHere <= 0.0025 * setpoints;
        if (compared)
            QVERIFY(worst < 5e-3);
        if (late.size() == 1 || lateHere < *std::min_element(late.begin(), late.end() - 1))
            fewestLateWorst = worst;
    }
    if (!compared) {
        QStringList counts;
        for (const int n : late)
            counts << QString::number(n);
        qInfo("no session with at most 0.25 %% of its set-points late (late: %s): the one with "
              "the fewest is held to 2 %%",
              qPrintable(counts.join(QStringLiteral(", "))));
        QVERIFY2(fewestLateWorst < 2e-2, qPrintable(QString::number(100 * fewestLateWorst)));
    }
}

void TestCanE2e::recordedTrials_replayToTheSameEstimate()
{
    if (m_canEstimate.isEmpty())
        QFAIL("no logs: canSession_identifiesAsTheSimulatedRobot, which records them, failed");
    QStringList args = QStringList{QStringLiteral("replay"), QStringLiteral("--report"),
                                   QStringLiteral("replay.json")} +
                       m_scenarioArgs;
    for (int k = 0; k < 3; ++k)
        args << QStringLiteral("--candump")
             << QStringLiteral("logs/trial-%1.log").arg(k, 3, 10, QLatin1Char('0'));
    const Result replay = cli(args);
    QVERIFY2(replay.exitCode == 0, qPrintable(replay.err));
    QCOMPARE(finalEstimate(m_dir.filePath(QStringLiteral("replay.json"))), m_canEstimate);
}

void TestCanE2e::swappedNodeList_refusedBeforeAnyMotion()
{
    // The drives wired joint 1 = node 1, joint 2 = node 2 (the simulator's default); the master
    // told --nodes 2,1, as the independent robot side of issue 24 found a session complete with
    // a and c exchanged.
    const quint16 port = test::canE2ePort();
    const QString state = m_dir.filePath(QStringLiteral("swapped-state.json"));
    test::RobotSimProcess robot(QStringLiteral(LEARNID_ROBOT_SIM_PATH));
    QVERIFY(startRobot(robot, port, {QStringLiteral("--state"), state}));
    const QByteArray stateBefore = readAll(state);
    QVERIFY(!stateBefore.isEmpty());
    QProcess candump; // on socketcan the whole bus is watched as well
    if (test::canE2eOnSocketCan()) {
        candump.setStandardOutputFile(m_dir.filePath(QStringLiteral("swapped-bus.log")));
        candump.start(QStringLiteral("candump"),
                      {QStringLiteral("-L"), test::canE2eInterface(port)});
        QVERIFY(candump.waitForStarted());
        QTest::qWait(300);
    }
    const Result r =
        cli(canRun(port) + QStringList{QStringLiteral("--nodes"), QStringLiteral("2,1"),
                                       QStringLiteral("--iterations"), QStringLiteral("2"),
                                       QStringLiteral("--apply"), QStringLiteral("--can-log"),
                                       QStringLiteral("swapped-logs")});
    QVERIFY2(r.exitCode == 3, qPrintable(QString::number(r.exitCode) + r.err));
    QVERIFY2(r.err.contains(QLatin1String("refused before any motion: node 2 is listed for joint 1 "
                                          "but is the drive of joint 2")),
             qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("--nodes 1,2")), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("no files written")), qPrintable(r.err));
    // No trial started: a trial's log begins with its NMT start; nothing stored on the drives.
    QVERIFY(QDir(m_dir.filePath(QStringLiteral("swapped-logs"))).entryList(QDir::Files).isEmpty());
    QCOMPARE(readAll(state), stateBefore);
    if (!test::canE2eOnSocketCan())
        return;
    QTest::qWait(300);
    candump.terminate();
    QVERIFY(candump.waitForFinished(5000));
    const QList<CandumpEntry> bus =
        candump::readFile(m_dir.filePath(QStringLiteral("swapped-bus.log")));
    QVERIFY(!bus.isEmpty()); // the identity reads (SDO 0x600 + node) at least
    for (const CandumpEntry &e : bus) {
        const quint32 id = e.frame.frameId();
        // No NMT start (0x000, command 0x01), no RPDO (0x200 + node), and of the SDO requests
        // (0x600 + node) only reads: client command 2 (initiate upload) or 3 (upload segment).
        const QByteArray data = e.frame.payload();
        QVERIFY2(!(id == 0 && data.startsWith('\x01')), "NMT start on the bus");
        QVERIFY2(id < 0x200 || id > 0x27F, qPrintable(QString::number(id, 16)));
        if (id > 0x600 && id <= 0x67F) {
            const int command = quint8(data.at(0)) >> 5;
            QVERIFY2(command == 2 || command == 3, qPrintable(data.toHex(' ')));
        }
    }
}

void TestCanE2e::fault_endsWithClearErrorQuickly_data()
{
    // At sample 600 of 2 ms (1.2 s into the plan), after 4000 frames of 2 ms: the same times.
    const int periodMs = test::canE2ePeriodMs(2);
    test::addCanFaultRows(600 * 2 / periodMs, 4000 * 2 / periodMs);
}

void TestCanE2e::fault_endsWithClearErrorQuickly()
{
    QFETCH(QStringList, faults);
    QFETCH(QStringList, cliArgs);
    QFETCH(QString, expected);
    const quint16 port = test::canE2ePort();
    const QString tag = QString::fromLatin1(QTest::currentDataTag());
    const QString state = m_dir.filePath(tag + QStringLiteral("-state.json"));
    test::RobotSimProcess robot(QStringLiteral(LEARNID_ROBOT_SIM_PATH));
    QVERIFY(startRobot(robot, port, QStringList{QStringLiteral("--state"), state} + faults));
    const QByteArray stateBefore = [&] {
        QFile f(state);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }();
    QVERIFY(!stateBefore.isEmpty());
    const QString logs = tag + QStringLiteral("-logs");
    const Result r = cli(canRun(port) + cliArgs + QStringList{QStringLiteral("--can-log"), logs});
    QVERIFY2(r.exitCode == 3, qPrintable(QString::number(r.exitCode) + r.err));
    QVERIFY2(r.err.contains(expected), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("node")) || r.err.contains(QLatin1String("SYNC")),
             qPrintable(r.err));
    QFile after(state);
    QVERIFY(after.open(QIODevice::ReadOnly));
    QCOMPARE(after.readAll(), stateBefore); // nothing stored

    if (tag == QLatin1String("refuse-sdo"))
        return; // the trial completed; apply is refused at its first write
    // From the fault to the end of the trial (the master's last frame, NMT pre-operational):
    // the fault is the EMCY, the robot's last frame, or the SYNC the missing TPDO belonged to.
    const QList<CandumpEntry> log =
        candump::readFile(m_dir.filePath(logs + QStringLiteral("/trial-000.log")));
    QVERIFY(!log.isEmpty());
    const qint64 fault = test::faultMicroseconds(log, tag, 1);
    QVERIFY(fault > 0);
    const qint64 reactionMs = (test::candumpMicroseconds(log.constLast()) - fault) / 1000;
    qInfo("%s: %s; fault to end of trial %lld ms; CLI %lld ms", qPrintable(tag),
          qPrintable(r.err.section(QLatin1Char('\n'), -3, -3)), reactionMs, r.ms);
    QVERIFY(reactionMs < 1000);
}

QTEST_GUILESS_MAIN(TestCanE2e)
#include "tst_can_e2e.moc"
