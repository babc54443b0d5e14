// End to end over virtualcan with a 7-axis arm (the KUKA LWR4+ URDF of ../shared/data, skipped
// without it): learnid-robot-sim with seven drives on node ids spread over 1..127 and
// learnid-cli as two processes on a loopback port of their own, at a SYNC period whose bus load
// fits (4 ms: 48.9 %). Three learning trials, apply with read-back and store on every node;
// every fault of today with seven nodes ends the run with a clear error within 1 s and the
// stored parameters unchanged; the robot process killed mid-trial as well.
#include "can/CandumpLog.h"

#include "../support/CanE2eBus.h"
#include "../support/CanFaultLog.h"
#include "../support/RobotSimProcess.h"
#include "../support/SharedData.h"
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

using namespace learnid;

namespace {

using Result = learnid::test::ToolRun;

// Node ids of joint 1..7: any list, not 1..n (docs/can-protocol.md §1).
const QString kNodes = QStringLiteral("3,4,9,10,64,100,127");
constexpr quint32 kFirstNode = 3;
constexpr int kJoints = 7;

QJsonObject readJson(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

// A report's estimate ("phi" of "final" or of a trial) as numbers.
QList<double> phiOf(const QJsonValue &estimate)
{
    QList<double> phi;
    for (const QJsonValue v : estimate[QStringLiteral("phi")].toArray())
        phi << v.toDouble();
    return phi;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The 7-axis scenario of docs/scenario.md ("Any serial arm") at a 4 ms SYNC period, with the
// gains scaled for it (the 2 ms gains are unstable at 4 ms: the pre-trial check refuses them).
/// The gains of joint j scaled by gainScale and by wristScale for joints 5, 6 and 7 (j 4..6).
QByteArray lwrScenario(const QString &urdf, double samplePeriod, double gainScale, double lambda,
                       const QList<double> &wristScale = {1, 1, 1})
{
    const double kp[] = {340, 600, 100, 140, 15, 14, 11};
    const double ki[] = {34, 60, 10, 14, 1.5, 1.4, 1.1};
    const double kd[] = {45, 80, 14, 19, 2, 1.9, 1.5};
    QJsonArray p, i, d;
    for (int j = 0; j < kJoints; ++j) {
        const double scale = gainScale * (j >= 4 ? wristScale.value(j - 4, 1) : 1);
        p.append(kp[j] * scale);
        i.append(ki[j] * scale);
        d.append(kd[j] * scale);
    }
    const QJsonObject scenario{
        {QStringLiteral("schema"), QStringLiteral("learnid-scenario/2")},
        {QStringLiteral("robot"),
         QJsonObject{
             {QStringLiteral("model"), QStringLiteral("urdf")},
             {QStringLiteral("urdf"), QJsonObject{{QStringLiteral("file"), urdf}}},
             {QStringLiteral("jointTerms"),
              QJsonObject{{QStringLiteral("viscous"), true}, {QStringLiteral("coulomb"), true}}}}},
        {QStringLiteral("path"),
         QJsonObject{{QStringLiteral("kind"), QStringLiteral("waypoints")},
                     {QStringLiteral("waypoints"),
                      QJsonArray{QJsonArray{0, 0.3, 0, -1.2, 0, 0.5, 0},
                                 QJsonArray{0.8, 0.8, 0.5, -0.6, 0.6, -0.4, 0.9},
                                 QJsonArray{-0.4, 0.5, -0.5, -1.4, -0.5, 0.6, -0.7}}},
                     {QStringLiteral("planningFraction"), 0.3}}},
        {QStringLiteral("controller"), QJsonObject{{QStringLiteral("samplePeriod"), samplePeriod},
                                                   {QStringLiteral("kp"), p},
                                                   {QStringLiteral("ki"), i},
                                                   {QStringLiteral("kd"), d},
                                                   {QStringLiteral("lambda"), lambda}}},
        {QStringLiteral("simulation"), QJsonObject{{QStringLiteral("inertiaPerturbation"), 0.3},
                                                   {QStringLiteral("encoderCounts"), 1048576},
                                                   {QStringLiteral("torqueNoise"), 0.01}}},
        {QStringLiteral("safety"), QJsonObject{{QStringLiteral("maxTrackingErrorDeg"), 5}}}};
    return QJsonDocument(scenario).toJson();
}

} // namespace

class TestCanE2e7Axis : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void sevenAxesAt2ms_refusedWithTheOffer_offeredPeriodReachesTheBus();
    void sevenAxisSession_learnsAppliesWithReadBackAndStores();
    void recordedTrials_replayToTheSameEstimate();
    void fault_endsWithClearErrorQuickly_data();
    void fault_endsWithClearErrorQuickly();
    void robotKilledMidTrial_clearErrorWithinOneSecond_nothingApplied();

private:
    Result cli(const QStringList &args) const
    {
        return learnid::test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, m_dir.path(), 120000);
    }
    static QString interface(quint16 port) { return test::canE2eInterface(port); }
    bool startRobot(test::RobotSimProcess &robot, quint16 port, const QStringList &options) const
    {
        if (!test::canE2eOnSocketCan())
            return robot.start(interface(port), options);
        return robot.startOn(test::canE2ePlugin(), interface(port), options);
    }
    QStringList simOptions(const QString &state) const
    {
        return {QStringLiteral("--scenario"), m_scenario, QStringLiteral("--nodes"), kNodes,
                QStringLiteral("--state"),    state};
    }
    QStringList canRun(quint16 port) const
    {
        return QStringList{QStringLiteral("run"), QStringLiteral("--robot"),
                           QStringLiteral("can")} +
               test::canE2eBusOptions(port) +
               QStringList{QStringLiteral("--nodes"), kNodes, QStringLiteral("--scenario"),
                           m_scenario,
                           // CI runs this beside other tests on 2 cores (tst_can_e2e).
                           QStringLiteral("--can-sync-timeout"), QStringLiteral("200")};
    }

    QTemporaryDir m_dir;
    QString m_urdf;
    QString m_scenario; ///< the 7-axis scenario at 4 ms (or LEARNID_CAN_E2E_PERIOD_MS)
    int m_periodMs = 4;
    QList<double> m_canEstimate;
};

void TestCanE2e7Axis::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(QFileInfo::exists(QStringLiteral(LEARNID_CLI_PATH)));
    QVERIFY(QFileInfo::exists(QStringLiteral(LEARNID_ROBOT_SIM_PATH)));
    m_urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (m_urdf.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    // Gains that pass the pre-trial check, keep every joint within the 5 deg tracking limit for
    // 20 trials and halve the largest tracking error in 3 (learnid-cli run --iterations 20 on
    // this scenario): at 4 ms x 0.4 with lambda 400; at 5 and 10 ms (the VM of
    // scripts/test-socketcan) x 0.2 and x 0.15 with lambda 150 and the wrist (joints 5, 6, 7)
    // x 4, 4, 3 of that (at 10 ms x 0.15 alone: joint 6 passes 5 deg at 0.61 s; x 0.25 alone
    // is unstable).
    m_periodMs = test::canE2ePeriodMs(4);
    m_scenario = m_dir.filePath(QStringLiteral("lwr-%1ms.json").arg(m_periodMs));
    QFile f(m_scenario);
    QVERIFY(f.open(QIODevice::WriteOnly));
    const double ts = m_periodMs / 1000.0;
    f.write(m_periodMs <= 4   ? lwrScenario(m_urdf, ts, 0.4, 400)
            : m_periodMs <= 5 ? lwrScenario(m_urdf, ts, 0.2, 150, {4, 4, 3})
                              : lwrScenario(m_urdf, ts, 0.15, 150, {4, 4, 3}));
}

void TestCanE2e7Axis::sevenAxesAt2ms_refusedWithTheOffer_offeredPeriodReachesTheBus()
{
    // At 2 ms seven drives need 97.8 % of the bus: refused before anything is sent, with the
    // figures and the shortest SYNC period that fits.
    const QString at2ms = m_dir.filePath(QStringLiteral("lwr-2ms.json"));
    QFile f(at2ms);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(lwrScenario(m_urdf, 0.002, 1.0, 1000));
    f.close();
    const quint16 port = test::canE2ePort();
    QStringList args = canRun(port);
    args[args.indexOf(m_scenario)] = at2ms;
    const Result refused = cli(args + QStringList{QStringLiteral("--iterations"), "1"});
    QVERIFY2(refused.exitCode == 2, qPrintable(QString::number(refused.exitCode) + refused.err));
    for (const char *part :
         {"--nodes 3,4,9,10,64,100,127", "97.8 % of 1000 kbit/s", "the 70 % the tool allows",
          "fits is 3 ms", "65.2 %", "controller.samplePeriod to 0.003 s"})
        QVERIFY2(refused.err.contains(QLatin1String(part)), qPrintable(part + refused.err));

    // The offer taken (3 ms, gains that are stable there): past the load check to the bus,
    // where nobody answers (the tool hosts the bus itself): the first node's first SDO.
    const QString at3ms = m_dir.filePath(QStringLiteral("lwr-3ms.json"));
    QFile g(at3ms);
    QVERIFY(g.open(QIODevice::WriteOnly));
    g.write(lwrScenario(m_urdf, 0.003, 0.5, 400));
    g.close();
    args[args.indexOf(at2ms)] = at3ms;
    const Result offered = cli(args + QStringList{QStringLiteral("--iterations"), "1"});
    QVERIFY2(offered.exitCode == 3, qPrintable(QString::number(offered.exitCode) + offered.err));
    QVERIFY2(!offered.err.contains(QLatin1String("kbit/s")), qPrintable(offered.err));
    QVERIFY2(offered.err.contains(QLatin1String("node 3")) &&
                 offered.err.contains(QLatin1String("0x1018:01")),
             qPrintable(offered.err));
}

void TestCanE2e7Axis::sevenAxisSession_learnsAppliesWithReadBackAndStores()
{
    const quint16 port = test::canE2ePort();
    QVERIFY(port != 0 || test::canE2eOnSocketCan());
    const QString state = m_dir.filePath(QStringLiteral("state.json"));
    test::RobotSimProcess robot(QStringLiteral(LEARNID_ROBOT_SIM_PATH));
    QVERIFY(startRobot(robot, port, simOptions(state)));
    const Result can =
        cli(canRun(port) + QStringList{QStringLiteral("--iterations"), QStringLiteral("3"),
                                       QStringLiteral("--apply"), QStringLiteral("--report"),
                                       QStringLiteral("can.json"), QStringLiteral("--can-log"),
                                       QStringLiteral("logs")});
    QVERIFY2(can.exitCode == 0, qPrintable(can.err + robot.stderrText()));

    const QJsonObject report = readJson(m_dir.filePath(QStringLiteral("can.json")));
    const QJsonArray trials = report.value(QStringLiteral("trials")).toArray();
    QCOMPARE(trials.size(), 3);
    double first = 0, last = 0; // largest tracking error over the joints
    for (const QJsonValue v : trials.first()[QStringLiteral("maxTrackingErrorDeg")].toArray())
        first = std::max(first, v.toDouble());
    for (const QJsonValue v : trials.last()[QStringLiteral("maxTrackingErrorDeg")].toArray())
        last = std::max(last, v.toDouble());
    m_canEstimate = phiOf(report[QStringLiteral("final")]);
    QVERIFY(m_canEstimate.size() > 3 * kJoints); // 57 base parameters and friction
    qInfo("7 axes over %s: %lld parameters, max tracking error %.3f -> %.3f deg (%lld ms)",
          qPrintable(test::canE2ePlugin()), qint64(m_canEstimate.size()), first, last, can.ms);
    // Halved on the host; in the VM (socketcan at 10 ms, emulated CPU) the third trial's error
    // varies from run to run with the set-points' timing (1.11 to 1.54 deg from 2.71 measured),
    // so there it must fall by a quarter: learning over the bus, with a margin against the VM.
    const double fall = test::canE2ePlugin() == QLatin1String("socketcan") ? 0.75 : 0.5;
    QVERIFY2(last < fall * first, qPrintable(QString::number(last) + " " + QString::number(first)));

    // Apply: every node holds the estimate the session proposes (REAL32, read back before the
    // store), stored. That is the newest unless a later trial tracked worse than an earlier
    // one (TrialSeries.h); in the VM the third trial's error varies enough for that to happen.
    const int proposed = report.value(QStringLiteral("proposedEstimate")).toInt(-1);
    QVERIFY2(proposed >= 1 && proposed <= trials.size(), qPrintable(QString::number(proposed)));
    const QList<double> applied =
        phiOf(proposed == trials.size() ? report[QStringLiteral("final")] : trials.at(proposed));
    QVERIFY2(proposed == trials.size() ||
                 can.err.contains(QStringLiteral("estimate %1 tracked best").arg(proposed)),
             qPrintable(can.err));
    const QJsonObject nodes = readJson(state).value(QStringLiteral("nodes")).toObject();
    QCOMPARE(nodes.size(), kJoints);
    for (const QString &node : kNodes.split(QLatin1Char(','))) {
        const QJsonArray stored =
            nodes.value(node).toObject().value(QStringLiteral("storedParameters")).toArray();
        QVERIFY2(stored.size() == applied.size(), qPrintable(node));
        for (int i = 0; i < stored.size(); ++i)
            QCOMPARE(float(stored[i].toDouble()), float(applied[i]));
    }
    for (int k = 0; k < 3; ++k)
        QVERIFY(QFileInfo::exists(
            m_dir.filePath(QStringLiteral("logs/trial-%1.log").arg(k, 3, 10, QLatin1Char('0')))));
}

void TestCanE2e7Axis::recordedTrials_replayToTheSameEstimate()
{
    if (m_canEstimate.isEmpty())
        QFAIL("no logs: sevenAxisSession_learnsAppliesWithReadBackAndStores failed");
    QStringList args{QStringLiteral("replay"),
                     QStringLiteral("--scenario"),
                     m_scenario,
                     QStringLiteral("--nodes"),
                     kNodes,
                     QStringLiteral("--report"),
                     QStringLiteral("replay.json")};
    for (int k = 0; k < 3; ++k)
        args << QStringLiteral("--candump")
             << QStringLiteral("logs/trial-%1.log").arg(k, 3, 10, QLatin1Char('0'));
    const Result replay = cli(args);
    QVERIFY2(replay.exitCode == 0, qPrintable(replay.err));
    QCOMPARE(
        phiOf(readJson(m_dir.filePath(QStringLiteral("replay.json")))[QStringLiteral("final")]),
        m_canEstimate);
}

void TestCanE2e7Axis::fault_endsWithClearErrorQuickly_data()
{
    // At sample 300 of 4 ms, after 4000 frames of 4 ms: the same times at another period.
    const int periodMs = test::canE2ePeriodMs(4);
    test::addCanFaultRows(300 * 4 / periodMs, 4000 * 4 / periodMs);
}

void TestCanE2e7Axis::fault_endsWithClearErrorQuickly()
{
    QFETCH(QStringList, faults);
    QFETCH(QStringList, cliArgs);
    QFETCH(QString, expected);
    const quint16 port = test::canE2ePort();
    const QString tag = QString::fromLatin1(QTest::currentDataTag());
    const QString state = m_dir.filePath(tag + QStringLiteral("-state.json"));
    test::RobotSimProcess robot(QStringLiteral(LEARNID_ROBOT_SIM_PATH));
    QVERIFY(startRobot(robot, port, simOptions(state) + faults));
    const QByteArray stateBefore = readAll(state);
    QVERIFY(!stateBefore.isEmpty());
    const QString logs = tag + QStringLiteral("-logs");
    const Result r = cli(canRun(port) + cliArgs + QStringList{QStringLiteral("--can-log"), logs});
    QVERIFY2(r.exitCode == 3, qPrintable(QString::number(r.exitCode) + r.err));
    QVERIFY2(r.err.contains(expected), qPrintable(r.err));
    QVERIFY2(r.err.contains(QLatin1String("node")) || r.err.contains(QLatin1String("SYNC")),
             qPrintable(r.err));
    QCOMPARE(readAll(state), stateBefore); // nothing stored on any node

    if (tag == QLatin1String("refuse-sdo")) {
        // Refused at the first node's first parameter: no 0x1010 written anywhere.
        QVERIFY2(r.err.contains(QLatin1String("node 3")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QLatin1String("nothing was stored")), qPrintable(r.err));
        return;
    }
    // From the fault to the end of the trial (the master's last frame, NMT pre-operational):
    // the fault is the EMCY, the robot's last frame, or the SYNC the missing TPDO belonged to.
    const QList<CandumpEntry> log =
        candump::readFile(m_dir.filePath(logs + QStringLiteral("/trial-000.log")));
    QVERIFY(!log.isEmpty());
    const qint64 fault = test::faultMicroseconds(log, tag, kFirstNode);
    QVERIFY(fault > 0);
    const qint64 reactionMs = (test::candumpMicroseconds(log.constLast()) - fault) / 1000;
    qInfo("%s: %s; fault to end of trial %lld ms; CLI %lld ms", qPrintable(tag),
          qPrintable(r.err.section(QLatin1Char('\n'), -3, -3)), reactionMs, r.ms);
    QVERIFY(reactionMs < 1000);
}

void TestCanE2e7Axis::robotKilledMidTrial_clearErrorWithinOneSecond_nothingApplied()
{
    const quint16 port = test::canE2ePort();
    const QString state = m_dir.filePath(QStringLiteral("killed-state.json"));
    // The simulator as a process of this test's own, so that it can be killed (SIGKILL: no
    // goodbye on the bus; over virtualcan it hosts the server, so the tool's socket closes).
    QProcess robot;
    robot.start(QStringLiteral(LEARNID_ROBOT_SIM_PATH), test::canE2eBusOptions(port) +
                                                            test::RobotSimProcess::drivesWait() +
                                                            simOptions(state));
    QElapsedTimer ready;
    ready.start();
    while (!robot.canReadLine() && ready.elapsed() < 10000)
        robot.waitForReadyRead(200);
    QCOMPARE(robot.readLine().trimmed(), QByteArrayLiteral("ready"));
    const QByteArray stateBefore = readAll(state);

    QProcess tool;
    tool.setWorkingDirectory(m_dir.path());
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
    tool.setProcessEnvironment(env);
    test::DrivesFollowWatch watch(interface(port), 3);
    tool.start(QStringLiteral(LEARNID_CLI_PATH),
               canRun(port) + QStringList{QStringLiteral("--iterations"), QStringLiteral("3"),
                                          QStringLiteral("--apply"), QStringLiteral("--report"),
                                          QStringLiteral("killed.json")});
    QVERIFY(tool.waitForStarted());
    // Configuration (7 x 29 SDOs), enable walk, return move and hold take about 1.5 s, the
    // first plan 2.7 s: then the drives follow the set-points.
    QByteArray progress;
    QVERIFY2(watch.wait(tool, &progress), progress.constData());
    QCOMPARE(tool.state(), QProcess::Running);
    robot.kill();
    QElapsedTimer sinceKill;
    sinceKill.start();
    QVERIFY(robot.waitForFinished(5000));
    QVERIFY(tool.waitForFinished(10000));
    const qint64 ms = sinceKill.elapsed();
    const QString err = QString::fromUtf8(progress + tool.readAllStandardError());
    qInfo("killed: %s; tool exited %lld ms after the kill",
          qPrintable(err.section(QLatin1Char('\n'), -3, -3)), ms);
    QVERIFY2(tool.exitCode() == 3, qPrintable(QString::number(tool.exitCode()) + err));
    // virtualcan: the server went with the robot; socketcan: the bus falls silent.
    const QLatin1String why(test::canE2eOnSocketCan() ? "no SYNC" : "went unconnected");
    QVERIFY2(err.contains(why), qPrintable(err));
    QVERIFY2(ms < 1000, qPrintable(QString::number(ms)));
    // The report asked for is written, saying the session ended early and why (issue 23).
    QVERIFY2(err.contains(QLatin1String("(the session ended early)")), qPrintable(err));
    QFile killed(m_dir.filePath(QStringLiteral("killed.json")));
    QVERIFY(killed.open(QIODevice::ReadOnly));
    const QString endedEarly = QJsonDocument::fromJson(killed.readAll())
                                   .object()
                                   .value(QStringLiteral("endedEarly"))
                                   .toString();
    QVERIFY2(endedEarly.contains(why), qPrintable(endedEarly));
    QCOMPARE(readAll(state), stateBefore); // nothing applied: the stored sets never changed
}

QTEST_GUILESS_MAIN(TestCanE2e7Axis)
#include "tst_can_e2e_7axis.moc"
