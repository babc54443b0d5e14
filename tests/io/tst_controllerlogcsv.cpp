#include "IoTestSupport.h"
#include "io/ControllerLogCsv.h"

#include <QTest>

using namespace learnid;
using learnid::test::bitEqual;

class TestControllerLogCsv : public QObject
{
    Q_OBJECT

private slots:
    void onThePlansGrid_readsQAndTau();
    void jitterWithinAQuarterSample_isAccepted();
    void shorterLog_isATrialThatEndedEarly();
    void badLog_isRefusedNamingTheRow_data();
    void badLog_isRefusedNamingTheRow();
};

namespace {

const QString source = QStringLiteral("run.csv");

// A plan of 2 joints and 6 samples of 10 ms, as readPlanCsv() gives it.
PlanCsv samplePlan()
{
    PlanCsv plan;
    plan.planId = QString(64, QLatin1Char('c'));
    plan.robotModel = QStringLiteral("paper-2link");
    plan.samplePeriod = 0.01;
    plan.estimate = Eigen::Vector3d(40, 20, 30);
    plan.t = Eigen::VectorXd::LinSpaced(6, 0.0, 0.05);
    plan.qDesired = Eigen::MatrixXd::Zero(2, 6);
    plan.feedforward = Eigen::MatrixXd::Zero(2, 6);
    return plan;
}

QByteArray header()
{
    return "# plan-id: " + QByteArray(64, 'c') + "\ntau2,t,q1,q2,tau1,note\n";
}

QByteArray row(const QByteArray &t, int k)
{
    const QByteArray v = QByteArray::number(k);
    return "-" + v + "," + t + ",0.1" + v + ",0.2" + v + "," + v + ",x\n";
}

QByteArray log(int samples)
{
    QByteArray out = header();
    for (int k = 0; k < samples; ++k)
        out += row(QByteArray::number(k * 0.01), k);
    return out;
}

} // namespace

void TestControllerLogCsv::onThePlansGrid_readsQAndTau()
{
    const ControllerLog read = readControllerLog(log(6), source, samplePlan(), {true, true});
    QCOMPARE(read.planId, samplePlan().planId);
    QVERIFY(read.record.completed());
    QVERIFY(bitEqual(read.record.samplePeriod, 0.01));
    QCOMPARE(read.record.samples(), 6);
    QVERIFY(bitEqual(read.record.q(0, 3), 0.13));
    QVERIFY(bitEqual(read.record.q(1, 5), 0.25));
    QVERIFY(bitEqual(read.record.tau(0, 4), 4.0));
    QVERIFY(bitEqual(read.record.tau(1, 4), -4.0));
    QCOMPARE(read.rows.front(), 3);
}

void TestControllerLogCsv::jitterWithinAQuarterSample_isAccepted()
{
    QByteArray csv = header();
    const char *times[] = {"0.0004", "0.0124", "0.0176", "0.03", "0.04", "0.05"};
    for (int k = 0; k < 6; ++k)
        csv += row(times[k], k);
    const ControllerLog read = readControllerLog(csv, source, samplePlan());
    QVERIFY(read.record.completed());
    QCOMPARE(read.record.samples(), 6);
}

void TestControllerLogCsv::shorterLog_isATrialThatEndedEarly()
{
    const ControllerLog read = readControllerLog(log(4), source, samplePlan());
    QCOMPARE(read.record.status, TrialStatus::Aborted);
    QCOMPARE(read.record.samples(), 4);
    QCOMPARE(read.record.message,
             QStringLiteral("the log ends after 4 of the plan's 6 samples (t = 0.03 s of 0.05 s): "
                            "the trial ended early"));
}

void TestControllerLogCsv::badLog_isRefusedNamingTheRow_data()
{
    QTest::addColumn<QByteArray>("csv");
    QTest::addColumn<QString>("message");
    QByteArray noId = log(6);
    noId.replace("# plan-id:", "# plan:");
    QTest::newRow("no plan-id") << noId
                                << "run.csv: no \"# plan-id:\" comment line; the controller copies";
    QByteArray other = log(6);
    other.replace(QByteArray(64, 'c'), QByteArray(64, 'd'));
    QTest::newRow("other plan") << other
                                << "run.csv: the log is of plan " + QString(64, QLatin1Char('d')) +
                                       ", not of plan " + QString(64, QLatin1Char('c'));
    QByteArray late = log(6);
    late.replace("\n-3,0.03,", "\n-3,0.0326,");
    QTest::newRow("off the grid")
        << late
        << "run.csv: line 6: t = 0.0326 s is off the plan's grid: sample 3 is planned at "
           "t = 0.03 s (+-0.0025 s)";
    QByteArray fast = header();
    for (int k = 0; k < 12; ++k)
        fast += row(QByteArray::number(k * 0.005), k);
    QTest::newRow("another rate") << fast << "run.csv: line 4: t = 0.005 s is off the plan's grid";
    QTest::newRow("longer than planned")
        << log(6) + row("0.06", 6)
        << "run.csv: line 9: sample 6 (t = 0.06 s) is beyond the plan's 6 samples, the last at "
           "t = 0.05 s";
    QByteArray degrees = log(6);
    degrees.replace(",0.21,", ",12,");
    QTest::newRow("degrees") << degrees << "run.csv: line 4, column 4 (q2): 12 rad is more than";
    QTest::newRow("no torque") << "# plan-id: " + QByteArray(64, 'c') + "\nt,q1,q2,tau1\n"
                               << "run.csv: line 2: no column \"tau2\"";
}

void TestControllerLogCsv::badLog_isRefusedNamingTheRow()
{
    QFETCH(QByteArray, csv);
    QFETCH(QString, message);
    LEARNID_VERIFY_ERROR(readControllerLog(csv, source, samplePlan(), {true, true}), message);
}

QTEST_GUILESS_MAIN(TestControllerLogCsv)
#include "tst_controllerlogcsv.moc"
