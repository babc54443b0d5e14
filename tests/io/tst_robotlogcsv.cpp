#include "../support/SharedData.h"
#include "IoTestSupport.h"
#include "io/AtomicFile.h"
#include "io/RobotLogCsv.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;
using learnid::test::bitEqual;

class TestRobotLogCsv : public QObject
{
    Q_OBJECT

private slots:
    void defaultColumns_readByNameOthersIgnored();
    void withoutVelocityColumns_theLogHasNone();
    void commentsBlankLinesCrlfSpacesAndBom_areAccepted_lineNumbersKept();
    void repeatedRows_areDroppedAndCounted();
    void staleRows_areDroppedAndListed_apartFromRepeats();
    void staleRows_stillOrderTheTimes();
    void unitCheck_onlyForAngularPositionsAndVelocities();
    void columnsOption_readsKeysAndKeepsDefaults();
    void columnsOption_badSpec_namesTheKey_data();
    void columnsOption_badSpec_namesTheKey();
    void badInput_namesFileLineAndColumn_data();
    void badInput_namesFileLineAndColumn();
    void missingFile_namesThePath();
    void kukaLogs_everyLineIsASample();
    void pendulumLogs_readThroughTheColumnsOption();
};

namespace {

const QString source = QStringLiteral("log.csv");

// The lines of a file that are not empty, the header included.
int nonEmptyLines(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    int lines = 0;
    while (!file.atEnd())
        lines += file.readLine().trimmed().isEmpty() ? 0 : 1;
    return lines;
}

} // namespace

void TestRobotLogCsv::defaultColumns_readByNameOthersIgnored()
{
    const QByteArray csv = "tau2,status,q1,t,dq2,q2,dq1,tau1\n"
                           "-2,ok,0.1,0,0.02,0.2,0.01,1\n"
                           "-2.5,late,0.11,0.005,0.021,0.21,0.011,1.5\n"
                           "-3,ok,0.12,0.01,0.022,0.22,0.012,2\n"
                           "-3.5,,0.13,0.015,0.023,0.23,0.013,2.5\n";
    const RobotLog log = readRobotLog(csv, source, 2, {}, {true, true});
    QCOMPARE(log.source, source);
    QCOMPARE(log.dof(), 2);
    QCOMPARE(log.samples(), Eigen::Index(4));
    QVERIFY(bitEqual(log.t, Eigen::Vector4d(0, 0.005, 0.01, 0.015)));
    Eigen::MatrixXd q(2, 4), dq(2, 4), tau(2, 4);
    q << 0.1, 0.11, 0.12, 0.13, 0.2, 0.21, 0.22, 0.23;
    dq << 0.01, 0.011, 0.012, 0.013, 0.02, 0.021, 0.022, 0.023;
    tau << 1, 1.5, 2, 2.5, -2, -2.5, -3, -3.5;
    QVERIFY(bitEqual(log.q, q));
    QVERIFY(bitEqual(log.dq, dq));
    QVERIFY(bitEqual(log.tau, tau));
    QCOMPARE(log.rows, std::vector<int>({2, 3, 4, 5}));
    QCOMPARE(log.repeatedSamples, 0);
}

void TestRobotLogCsv::withoutVelocityColumns_theLogHasNone()
{
    const QByteArray csv = "t,q1,tau1\n0,1,2\n1,1.1,2\n2,1.2,2\n3,1.3,2\n";
    const RobotLog log = readRobotLog(csv, source, 1);
    QCOMPARE(log.dq.rows(), Eigen::Index(0));
    QCOMPARE(log.dq.cols(), Eigen::Index(0));
    QCOMPARE(log.q.cols(), Eigen::Index(4));

    // An empty velocity pattern reads none even when the log has them.
    LogColumns noVelocities;
    noVelocities.velocity.clear();
    const QByteArray withDq = "t,q1,dq1,tau1\n0,1,0,2\n1,1.1,0,2\n2,1.2,0,2\n3,1.3,0,2\n";
    QCOMPARE(readRobotLog(withDq, source, 1, noVelocities).dq.size(), Eigen::Index(0));
    QCOMPARE(readRobotLog(withDq, source, 1).dq.size(), Eigen::Index(4));
}

void TestRobotLogCsv::commentsBlankLinesCrlfSpacesAndBom_areAccepted_lineNumbersKept()
{
    const QByteArray csv = "\xEF\xBB\xBF# run 4\r\n"
                           "\r\n"
                           " t , q1 ,tau1\r\n"
                           "0.0, 0.5, -1\r\n"
                           "  # a pause\r\n"
                           "0.01,0.51,-0.99\r\n"
                           "0.02,0.52,-0.98\r\n"
                           "\r\n"
                           "0.03,0.53,-0.97";
    const RobotLog log = readRobotLog(csv, source, 1);
    QVERIFY(bitEqual(log.t, Eigen::Vector4d(0.0, 0.01, 0.02, 0.03)));
    QVERIFY(bitEqual(log.tau, Eigen::RowVector4d(-1, -0.99, -0.98, -0.97)));
    QCOMPARE(log.rows, std::vector<int>({4, 6, 7, 9}));
}

void TestRobotLogCsv::repeatedRows_areDroppedAndCounted()
{
    const QByteArray csv = "t,q1,tau1\n"
                           "0,1,2\n"
                           "0.01,1.1,2.1\n"
                           "0.01,1.1,2.1\n"
                           "0.01,1.1,2.1\n"
                           "0.02,1.2,2.2\n"
                           "0.03,1.3,2.3\n"
                           "0.03,1.3,2.3\n";
    const RobotLog log = readRobotLog(csv, source, 1);
    QCOMPARE(log.repeatedSamples, 3);
    QVERIFY(bitEqual(log.t, Eigen::Vector4d(0, 0.01, 0.02, 0.03)));
    QVERIFY(bitEqual(log.q, Eigen::RowVector4d(1, 1.1, 1.2, 1.3)));
    QCOMPARE(log.rows, std::vector<int>({2, 3, 6, 7}));
}

void TestRobotLogCsv::staleRows_areDroppedAndListed_apartFromRepeats()
{
    const QByteArray csv = "t,q1,dq1,tau1\n"
                           "0,1,0.5,2\n"
                           "0.01,1.1,0.5,2.1\n"
                           "0.02,1.1,0.5,2.1\n" // stale: line 3's values, a new time
                           "0.03,1.1,0.5,2.1\n" // stale
                           "0.03,1.1,0.5,2.1\n" // line 5 written twice: a repeat
                           "0.04,1.2,0.5,2.2\n"
                           "0.05,1.2,0.6,2.2\n" // only the velocity is new: not stale
                           "0.06,1.3,0.6,2.3\n";
    const RobotLog log = readRobotLog(csv, source, 1);
    QCOMPARE(log.rows, std::vector<int>({2, 3, 7, 8, 9}));
    QCOMPARE(log.staleRows, std::vector<int>({4, 5}));
    QCOMPARE(log.staleSamples(), 2);
    QCOMPARE(log.repeatedSamples, 1);
    QVERIFY(bitEqual(
        log.t, Eigen::VectorXd((Eigen::VectorXd(5) << 0, 0.01, 0.04, 0.05, 0.06).finished())));
    QVERIFY(bitEqual(
        log.dq, Eigen::RowVectorXd((Eigen::RowVectorXd(5) << 0.5, 0.5, 0.5, 0.6, 0.6).finished())));

    // Without the velocities read, line 8 repeats every value read: stale too.
    LogColumns noVelocities;
    noVelocities.velocity.clear();
    const RobotLog positions = readRobotLog(csv, source, 1, noVelocities);
    QCOMPARE(positions.staleRows, std::vector<int>({4, 5, 8}));
    QCOMPARE(positions.rows, std::vector<int>({2, 3, 7, 9}));
    QCOMPARE(positions.repeatedSamples, 1);

    // Kept on request (a controller's own log of a plan): every row a sample, the repeat too.
    const RobotLog kept = readRobotLog(csv, source, 1, {}, {}, StaleRows::Keep);
    QCOMPARE(kept.rows, std::vector<int>({2, 3, 4, 5, 7, 8, 9}));
    QVERIFY(kept.staleRows.empty());
    QCOMPARE(kept.repeatedSamples, 1);

    // A joint whose values stay is not enough: every joint's must repeat.
    const QByteArray twoJoints = "t,q1,q2,tau1,tau2\n0,1,2,3,4\n0.01,1,2,3,4.5\n"
                                 "0.02,1,2.5,3,4.5\n0.03,1,2.5,3,4.5\n0.04,1,2.6,3,4.5\n";
    const RobotLog two = readRobotLog(twoJoints, source, 2);
    QCOMPARE(two.staleRows, std::vector<int>({5}));
    QCOMPARE(two.samples(), Eigen::Index(4));
}

void TestRobotLogCsv::staleRows_stillOrderTheTimes()
{
    // A stale row's time stamp still counts: the next must be later.
    const QByteArray back = "t,q1,tau1\n0,1,2\n0.01,1.1,2.1\n0.05,1.1,2.1\n0.03,1.2,2.2\n";
    LEARNID_VERIFY_ERROR(readRobotLog(back, source, 1),
                         QStringLiteral("log.csv: line 5, column 1 (t): the times must increase "
                                        "from sample to sample, got 0.03 after 0.05 on line 4"));
    // The same time as a stale row with other values is no repeat.
    const QByteArray same = "t,q1,tau1\n0,1,2\n0.01,1.1,2.1\n0.02,1.1,2.1\n0.02,1.2,2.2\n";
    LEARNID_VERIFY_ERROR(readRobotLog(same, source, 1),
                         QStringLiteral("log.csv: line 5, column 1 (t): the time 0.02 repeats that "
                                        "of line 4 with other values (q1: 1.1 there, 1.2 here)"));
    // Samples are counted without the stale rows, and the message says how many there were.
    const QByteArray few = "t,q1,tau1\n0,1,2\n0.01,1.1,2.1\n0.02,1.1,2.1\n0.03,1.1,2.1\n"
                           "0.04,1.2,2.2\n";
    LEARNID_VERIFY_ERROR(readRobotLog(few, source, 1),
                         QStringLiteral("log.csv: line 7: 3 samples after the header on line 1 "
                                        "(and 2 stale row(s): values repeated under a new time "
                                        "stamp, treated as missing); a log needs at least 4"));
}

void TestRobotLogCsv::unitCheck_onlyForAngularPositionsAndVelocities()
{
    // Joint 2 prismatic: 95 m is not degrees; torques are never checked; 6.5 rad is 1.03 turns.
    const QByteArray csv = "t,q1,q2,dq1,dq2,tau1,tau2\n"
                           "0,6.5,95,-99,500,1000,0\n"
                           "1,-6.5,95,99,500,-1000,0\n"
                           "2,0,95,0,500,0,0\n"
                           "3,0.1,95,0,500,0,0\n";
    const RobotLog log = readRobotLog(csv, source, 2, {}, {true, false});
    QCOMPARE(log.q(1, 0), 95.0);
    QCOMPARE(log.tau(0, 0), 1000.0);
    QCOMPARE(readRobotLog(csv, source, 2).dq(1, 0), 500.0); // no kinds: no unit check
}

void TestRobotLogCsv::columnsOption_readsKeysAndKeepsDefaults()
{
    const LogColumns pendulum =
        parseLogColumns(QStringLiteral("t=time,q=pos_meas%1, dq = vel_meas%1 ,tau=tau_meas%1"));
    QCOMPARE(pendulum.time, QStringLiteral("time"));
    QCOMPARE(pendulum.position, QStringLiteral("pos_meas%1"));
    QCOMPARE(pendulum.velocity, QStringLiteral("vel_meas%1"));
    QCOMPARE(pendulum.torque, QStringLiteral("tau_meas%1"));

    const LogColumns some = parseLogColumns(QStringLiteral("tau=effort_%1,dq="));
    QCOMPARE(some.time, QStringLiteral("t"));
    QCOMPARE(some.position, QStringLiteral("q%1"));
    QVERIFY(some.velocity.isEmpty());
    QCOMPARE(some.torque, QStringLiteral("effort_%1"));
}

void TestRobotLogCsv::columnsOption_badSpec_namesTheKey_data()
{
    QTest::addColumn<QString>("spec");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown key") << "t=time,qd=v%1"
                                 << "--columns: unknown key \"qd\"; the keys are t, q, dq and tau";
    QTest::newRow("no =") << "t=time,q"
                          << "--columns: \"q\" has no '='; expected key=pattern with the keys t, "
                             "q, dq and tau, e.g. q=pos_meas%1";
    QTest::newRow("empty") << ""
                           << "--columns: \"\" has no '='";
    QTest::newRow("q without %1") << "q=pos_meas"
                                  << "--columns: q=pos_meas has no %1 where the joint number "
                                     "goes, e.g. q=pos_meas%1";
    QTest::newRow("tau without %1") << "tau=effort"
                                    << "--columns: tau=effort has no %1";
    QTest::newRow("dq without %1") << "dq=vel"
                                   << "--columns: dq=vel has no %1";
    QTest::newRow("empty q") << "q="
                             << "--columns: q= has no %1";
    QTest::newRow("empty t") << "t=,q=p%1"
                             << "--columns: t= names no column; the time column is needed";
    QTest::newRow("repeated key") << "q=a%1,q=b%1"
                                  << "--columns: the key q is given twice";
}

void TestRobotLogCsv::columnsOption_badSpec_namesTheKey()
{
    QFETCH(QString, spec);
    QFETCH(QString, message);
    const QString error = test::errorOf([&] { parseLogColumns(spec); });
    QVERIFY2(error.startsWith(message), qPrintable(error));
}

void TestRobotLogCsv::badInput_namesFileLineAndColumn_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<int>("joints");
    QTest::addColumn<QList<bool>>("angular");
    QTest::addColumn<QString>("message"); // the start of the message after "log.csv: "
    const QByteArray header = "t,q1,q2,dq1,dq2,tau1,tau2\n";
    const QByteArray head = header + "0,0.1,0.2,0,0,1,2\n";
    const QByteArray tail = "0.03,0.1,0.2,0,0,1,2\n0.04,0.1,0.2,0,0,1,2\n0.05,0.1,0.2,0,0,1,2\n";
    const QList<bool> revolute = {true, true};
    QTest::newRow("empty") << QByteArray() << 2 << QList<bool>()
                           << "line 1: the file holds no header line; expected one naming the "
                              "columns t, q1..q2, tau1..tau2";
    QTest::newRow("only comments")
        << QByteArray("# a\n\n") << 2 << QList<bool>() << "line 3: the file holds no header line";
    QTest::newRow("no torque of joint 2")
        << QByteArray("t,q1,q2,tau1\n") + tail << 2 << QList<bool>()
        << "line 1: no column \"tau2\" (the torque of joint 2); the header has: t, q1, q2, tau1";
    QTest::newRow("no time, long header shortened")
        << QByteArray("# x\ntime,q1,q2,tau1,tau2,a,b,c,d,e,f,g,h,i,j\n") << 2 << QList<bool>()
        << "line 2: no column \"t\" (the time [s]); the header has: time, q1, q2, tau1, tau2, a, "
           "b, c, d, e, ... (15 columns)";
    QTest::newRow("no time, empty names quoted")
        << QByteArray(",q1,q2,tau1,tau2\n") << 2 << QList<bool>()
        << "line 1: no column \"t\" (the time [s]); the header has: \"\", q1, q2, tau1, tau2";
    QTest::newRow("more joints than the robot")
        << QByteArray("t,q1,q2,q3,tau1,tau2,tau3\n") << 2 << QList<bool>()
        << "line 1: the log has 3 joints (q1..q3), the robot 2";
    QTest::newRow("fewer joints than the robot")
        << head + tail << 3 << QList<bool>()
        << "line 1: the log has 2 joints (q1..q2), the robot 3";
    QTest::newRow("one joint's position missing")
        << QByteArray("t,q1,q3,tau1,tau2,tau3\n") << 3 << QList<bool>()
        << "line 1: no column \"q2\" (the position of joint 2)";
    QTest::newRow("velocities of some joints")
        << QByteArray("t,q1,q2,dq2,tau1,tau2\n") << 2 << QList<bool>()
        << "line 1: no column \"dq1\" (the velocity of joint 1, as the log has velocities of "
           "other joints)";
    QTest::newRow("repeated name") << QByteArray("t,q1,q2,tau1,q1,tau2\n") << 2 << QList<bool>()
                                   << "line 1, column 5 (q1): the name repeats that of column 2";
    QTest::newRow("too few fields")
        << head + "0.01,0.1,0.2,0,0,1\n" + tail << 2 << QList<bool>()
        << "line 3, column 7 (tau2): expected 7 fields (t, q1, q2, dq1, dq2, tau1, tau2), got 6";
    QTest::newRow("too many fields") << head + "0.01,0.1,0.2,0,0,1,2,3\n" + tail << 2
                                     << QList<bool>() << "line 3, column 8: expected 7 fields";
    QTest::newRow("not a number") << head + "0.01,abc,0.2,0,0,1,2\n" + tail << 2 << QList<bool>()
                                  << "line 3, column 2 (q1): not a number: \"abc\"";
    QTest::newRow("empty field") << head + "0.01,0.1,0.2,0,0,,2\n" + tail << 2 << QList<bool>()
                                 << "line 3, column 6 (tau1): the field is empty; expected a "
                                    "number";
    QTest::newRow("nan") << head + "0.01,0.1,0.2,nan,0,1,2\n" + tail << 2 << QList<bool>()
                         << "line 3, column 4 (dq1): must be a finite number, got nan";
    QTest::newRow("inf time") << head + "inf,0.1,0.2,0,0,1,2\n" + tail << 2 << QList<bool>()
                              << "line 3, column 1 (t): must be a finite number, got inf";
    QTest::newRow("time going back")
        << head + "# c\n-0.5,0.1,0.2,0,0,1,2\n" + tail << 2 << QList<bool>()
        << "line 4, column 1 (t): the times must increase from sample to sample, got -0.5 after "
           "0 on line 2";
    QTest::newRow("repeated time, other values")
        << head + "0.01,0.1,0.2,0,0,1,2\n0.01,0.1,0.3,0,0,1,2\n" + tail << 2 << QList<bool>()
        << "line 4, column 1 (t): the time 0.01 repeats that of line 3 with other values (q2: "
           "0.2 there, 0.3 here)";
    QTest::newRow("three samples")
        << header + "0,0,0,0,0,0,0\n1,1,0,0,0,0,0\n2,2,0,0,0,0,0" << 2 << QList<bool>()
        << "line 5: 3 samples after the header on line 1; a log needs "
           "at least 4";
    QTest::newRow("four rows, one a repeat")
        << header + "0,0,0,0,0,0,0\n1,1,0,0,0,0,0\n1,1,0,0,0,0,0\n2,2,0,0,0,0,0\n"
        << 2 << QList<bool>() << "line 6: 3 samples after the header on line 1; a log";
    QTest::newRow("degrees") << head + "0.01,0.1,95.5,0,0,1,2\n" + tail << 2 << revolute
                             << "line 3, column 3 (q2): 95.5 rad is more than 1.05 turns (6.60 "
                                "rad); the log looks like it holds degrees, radians are expected";
    QTest::newRow("degrees per second")
        << head + tail + "0.06,0.1,0.2,-120,0,1,2\n"
        << 2 << revolute
        << "line 6, column 4 (dq1): -120 rad/s is faster than any robot joint turns (at most 100 "
           "rad/s); the log looks like it holds degrees per second, radians per second are "
           "expected";
}

void TestRobotLogCsv::badInput_namesFileLineAndColumn()
{
    QFETCH(QByteArray, content);
    QFETCH(int, joints);
    QFETCH(QList<bool>, angular);
    QFETCH(QString, message);
    const QString error =
        test::errorOf([&] { readRobotLog(content, source, joints, {}, angular); });
    QVERIFY2(error.startsWith(source + QStringLiteral(": ") + message), qPrintable(error));
}

void TestRobotLogCsv::missingFile_namesThePath()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("absent.csv"));
    LEARNID_VERIFY_ERROR(readRobotLogFile(path, 7),
                         QStringLiteral("cannot read ") + QDir::toNativeSeparators(path));
}

void TestRobotLogCsv::kukaLogs_everyLineIsASample()
{
    for (int run = 1; run <= 3; ++run) {
        const QString path =
            test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_%1.csv").arg(run));
        if (path.isEmpty())
            QSKIP(qPrintable(test::sharedDataMissing()));
        const RobotLog log = readRobotLogFile(path, 7, {}, QList<bool>(7, true));
        QCOMPARE(log.source, QDir::toNativeSeparators(path));
        QCOMPARE(log.dof(), 7);
        QCOMPARE(log.samples(), Eigen::Index(nonEmptyLines(path) - 1)); // 5027 each
        QCOMPARE(log.dq.rows(), Eigen::Index(7));
        QCOMPARE(log.tau.cols(), log.samples());
        QCOMPARE(log.repeatedSamples, 0);
        QCOMPARE(log.staleSamples(), 0);
        QCOMPARE(log.rows.front(), 2);
        QCOMPARE(log.rows.back(), int(log.samples()) + 1);
        QVERIFY(log.t[log.samples() - 1] > 25.0);
    }
    // The log holds 7 joints; read for a 6-joint robot it is refused.
    const QString path = test::sharedDataFile(QStringLiteral("kuka-lwr4/measurements_1.csv"));
    LEARNID_VERIFY_ERROR(readRobotLogFile(path, 6),
                         QStringLiteral(": line 1: the log has 7 joints (q1..q7), the robot 6"));
}

void TestRobotLogCsv::pendulumLogs_readThroughTheColumnsOption()
{
    const LogColumns columns =
        parseLogColumns(QStringLiteral("t=time,q=pos_meas%1,dq=vel_meas%1,tau=tau_meas%1"));
    for (int run = 0; run <= 3; ++run) {
        const QString path =
            test::sharedDataFile(QStringLiteral("double-pendulum/trajectory_0%1.csv").arg(run));
        if (path.isEmpty())
            QSKIP(qPrintable(test::sharedDataMissing()));
        const RobotLog log = readRobotLogFile(path, 2, columns, {true, true});
        QCOMPARE(log.dof(), 2);
        QCOMPARE(log.samples(), Eigen::Index(nonEmptyLines(path) - 1));
        QCOMPARE(log.dq.cols(), log.samples());
        QVERIFY(log.t[log.samples() - 1] > 9.9);
        // trajectory_00's rows 2 and 3 repeat positions and torques at rest, not the velocities.
        QCOMPARE(log.staleSamples(), 0);
    }
    // Without the option the header does not name the time t; the long header is shortened.
    const QString path = test::sharedDataFile(QStringLiteral("double-pendulum/trajectory_00.csv"));
    LEARNID_VERIFY_ERROR(readRobotLogFile(path, 2),
                         QStringLiteral(": line 1: no column \"t\" (the time [s]); the header "
                                        "has: time, pos_meas1, pos_meas2, vel_meas1, vel_meas2, "
                                        "pos_filt1, pos_filt2, vel_filt1, vel_filt2, tau_con1, "
                                        "... (15 columns)"));
}

QTEST_GUILESS_MAIN(TestRobotLogCsv)
#include "tst_robotlogcsv.moc"
