#include "IoTestSupport.h"
#include "io/AtomicFile.h"
#include "io/TrialCsv.h"

#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <limits>
#include <random>

using namespace learnid;
using learnid::test::bitEqual;

namespace {

const QString source = QStringLiteral("trial-001.csv");

TrialPlan samplePlan(int samples)
{
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    TrialPlan plan;
    plan.desired.samplePeriod = 0.002;
    plan.desired.q.resize(2, samples);
    plan.desired.qd = Eigen::MatrixXd::Zero(2, samples);
    plan.desired.qdd = Eigen::MatrixXd::Zero(2, samples);
    plan.feedforward.resize(2, samples);
    for (int k = 0; k < samples; ++k) {
        for (int j = 0; j < 2; ++j) {
            plan.desired.q(j, k) = u(rng);
            plan.feedforward(j, k) = 4.0 * u(rng);
        }
    }
    return plan;
}

TrialRecord sampleRecord(const TrialPlan &plan, int samples)
{
    std::mt19937_64 rng(5);
    std::normal_distribution<double> noise(0.0, 1e-4);
    TrialRecord r;
    r.samplePeriod = plan.desired.samplePeriod;
    r.q = plan.desired.q.leftCols(samples);
    r.tau = plan.feedforward.leftCols(samples);
    for (int k = 0; k < samples; ++k) {
        for (int j = 0; j < 2; ++j) {
            r.q(j, k) += noise(rng);
            r.tau(j, k) += 1e3 * noise(rng);
        }
    }
    return r;
}

} // namespace

class TestTrialCsv : public QObject
{
    Q_OBJECT

private slots:
    void header_namesEveryColumnWithItsUnit();
    void roundTrip_isBitExact();
    void partialRecord_hasOneRowPerRecordedSample();
    void emptyRecord_isHeaderOnly();
    void nonFiniteMeasurement_roundTrips();
    void record_givesTheMeasuredPart();
    void windowsLineEnds_areAccepted();
    void recordLongerThanPlan_isRejected();
    void wrongHeader_isReportedOnLine1();
    void wrongFieldCount_isReportedWithLineNumber();
    void badNumber_isReportedWithLineAndColumn();
    void timeNotIncreasing_isReportedWithLineNumber();
    void file_readsBack();
};

void TestTrialCsv::header_namesEveryColumnWithItsUnit()
{
    const TrialPlan plan = samplePlan(3);
    const QByteArray csv = trialCsv(plan, sampleRecord(plan, 3));
    QCOMPARE(csv.left(csv.indexOf('\n')), QByteArray("t_s,qd1_rad,q1_rad,e1_deg,tauf1_Nm,tau1_Nm,"
                                                     "qd2_rad,q2_rad,e2_deg,tauf2_Nm,tau2_Nm"));
    QCOMPARE(csv.count('\n'), 4);
    QVERIFY(csv.endsWith('\n'));
}

void TestTrialCsv::roundTrip_isBitExact()
{
    const TrialPlan plan = samplePlan(400);
    const TrialRecord record = sampleRecord(plan, 400);
    const TrialRecordCsv back = readTrialCsv(trialCsv(plan, record), source);
    QCOMPARE(back.dof(), 2);
    QCOMPARE(back.samples(), 400);
    for (int k = 0; k < 400; ++k)
        QVERIFY(bitEqual(back.t[k], k * 0.002));
    QVERIFY(bitEqual(back.qDesired, plan.desired.q));
    QVERIFY(bitEqual(back.q, record.q));
    QVERIFY(bitEqual(back.feedforward, plan.feedforward));
    QVERIFY(bitEqual(back.tau, record.tau));
    const Eigen::MatrixXd errorDeg = (plan.desired.q - record.q) * (180.0 / M_PI);
    QVERIFY(bitEqual(back.trackingErrorDeg, errorDeg));
    QVERIFY(bitEqual(back.samplePeriod(), 0.002));
}

void TestTrialCsv::partialRecord_hasOneRowPerRecordedSample()
{
    const TrialPlan plan = samplePlan(100);
    TrialRecord record = sampleRecord(plan, 37);
    record.status = TrialStatus::Aborted;
    const QByteArray csv = trialCsv(plan, record);
    QCOMPARE(csv.count('\n'), 38);
    const TrialRecordCsv back = readTrialCsv(csv, source);
    QCOMPARE(back.samples(), 37);
    QVERIFY(bitEqual(back.q, record.q));
    QVERIFY(bitEqual(back.qDesired, plan.desired.q.leftCols(37)));
}

void TestTrialCsv::emptyRecord_isHeaderOnly()
{
    const TrialPlan plan = samplePlan(10);
    const QByteArray csv = trialCsv(plan, sampleRecord(plan, 0));
    QCOMPARE(csv.count('\n'), 1);
    const TrialRecordCsv back = readTrialCsv(csv, source);
    QCOMPARE(back.samples(), 0);
    QCOMPARE(back.dof(), 2);
    QCOMPARE(back.samplePeriod(), 0.0);
}

void TestTrialCsv::nonFiniteMeasurement_roundTrips()
{
    const TrialPlan plan = samplePlan(5);
    TrialRecord record = sampleRecord(plan, 5);
    record.q(1, 3) = std::numeric_limits<double>::quiet_NaN();
    record.tau(0, 4) = -std::numeric_limits<double>::infinity();
    const QByteArray csv = trialCsv(plan, record);
    QVERIFY(csv.contains(",nan,"));
    QVERIFY(csv.contains(",-inf"));
    const TrialRecordCsv back = readTrialCsv(csv, source);
    QVERIFY(std::isnan(back.q(1, 3)));
    QVERIFY(std::isnan(back.trackingErrorDeg(1, 3)));
    QCOMPARE(back.tau(0, 4), -std::numeric_limits<double>::infinity());
}

void TestTrialCsv::record_givesTheMeasuredPart()
{
    const TrialPlan plan = samplePlan(20);
    const TrialRecord record = sampleRecord(plan, 20);
    const TrialRecord back = readTrialCsv(trialCsv(plan, record), source).record();
    QVERIFY(bitEqual(back.samplePeriod, record.samplePeriod));
    QVERIFY(bitEqual(back.q, record.q));
    QVERIFY(bitEqual(back.tau, record.tau));
    QVERIFY(back.completed());
}

void TestTrialCsv::windowsLineEnds_areAccepted()
{
    const TrialPlan plan = samplePlan(6);
    const TrialRecord record = sampleRecord(plan, 6);
    QByteArray csv = trialCsv(plan, record);
    csv.replace("\n", "\r\n");
    QVERIFY(bitEqual(readTrialCsv(csv, source).tau, record.tau));
}

void TestTrialCsv::recordLongerThanPlan_isRejected()
{
    const TrialPlan plan = samplePlan(10);
    const TrialRecord record = sampleRecord(samplePlan(12), 12);
    LEARNID_VERIFY_ERROR(trialCsv(plan, record),
                         QStringLiteral("the record (2 joints, 12 samples) does not fit its plan "
                                        "(2 joints, 10 samples)"));
}

void TestTrialCsv::wrongHeader_isReportedOnLine1()
{
    LEARNID_VERIFY_ERROR(readTrialCsv("t,q1\n0,1\n", source),
                         QStringLiteral("trial-001.csv: line 1: the header must be t_s,qd1_rad,"));
    LEARNID_VERIFY_ERROR(readTrialCsv("", source),
                         QStringLiteral("trial-001.csv: line 1: the file is empty"));
}

void TestTrialCsv::wrongFieldCount_isReportedWithLineNumber()
{
    const TrialPlan plan = samplePlan(5);
    QList<QByteArray> lines = trialCsv(plan, sampleRecord(plan, 5)).split('\n');
    lines[3].chop(lines[3].size() - lines[3].lastIndexOf(','));
    QCOMPARE(test::errorOf([&] { readTrialCsv(lines.join('\n'), source); }),
             QStringLiteral("trial-001.csv: line 4: expected 11 fields, got 10"));
}

void TestTrialCsv::badNumber_isReportedWithLineAndColumn()
{
    const TrialPlan plan = samplePlan(5);
    QList<QByteArray> lines = trialCsv(plan, sampleRecord(plan, 5)).split('\n');
    QList<QByteArray> fields = lines[5].split(',');
    fields[7] = "0.1x";
    lines[5] = fields.join(',');
    QCOMPARE(test::errorOf([&] { readTrialCsv(lines.join('\n'), source); }),
             QStringLiteral("trial-001.csv: line 6: q2_rad is not a number: \"0.1x\""));
}

void TestTrialCsv::timeNotIncreasing_isReportedWithLineNumber()
{
    const TrialPlan plan = samplePlan(5);
    QList<QByteArray> lines = trialCsv(plan, sampleRecord(plan, 5)).split('\n');
    QList<QByteArray> fields = lines[3].split(',');
    fields[0] = "0.001";
    lines[3] = fields.join(',');
    LEARNID_VERIFY_ERROR(readTrialCsv(lines.join('\n'), source),
                         QStringLiteral("trial-001.csv: line 4: t_s must be finite and increase"));
}

void TestTrialCsv::file_readsBack()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("trial-001.csv"));
    const TrialPlan plan = samplePlan(8);
    const TrialRecord record = sampleRecord(plan, 8);
    writeFileAtomically(path, trialCsv(plan, record));
    QVERIFY(bitEqual(readTrialCsvFile(path).q, record.q));
}

QTEST_GUILESS_MAIN(TestTrialCsv)
#include "tst_trialcsv.moc"
