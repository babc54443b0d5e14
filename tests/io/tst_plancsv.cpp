#include "IoTestSupport.h"
#include "io/AtomicFile.h"
#include "io/PlanCsv.h"

#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using namespace learnid;
using learnid::test::bitEqual;

class TestPlanCsv : public QObject
{
    Q_OBJECT

private slots:
    void writeThenRead_isBitExact();
    void planId_isTheHashOfTheLinesFromTheHeaderOn();
    void crlfAndExtraComments_areAccepted();
    void badInput_namesFileLineAndColumn_data();
    void badInput_namesFileLineAndColumn();
    void planIdLine_findsTheCopiedLine();
    void planIdLine_refusesAMalformedOrSecondId();
};

namespace {

const QString source = QStringLiteral("plan.csv");

// A plan with awkward numbers: thirds, tiny and large values, negative zero.
TrialPlan samplePlan()
{
    TrialPlan plan;
    const int n = 2, samples = 7;
    plan.desired.samplePeriod = 0.002;
    plan.desired.q.resize(n, samples);
    plan.feedforward.resize(n, samples);
    for (int k = 0; k < samples; ++k) {
        plan.desired.q(0, k) = -0.294515485108137 + k / 3.0;
        plan.desired.q(1, k) = std::sqrt(2.0) * k * 1e-7;
        plan.feedforward(0, k) = k == 0 ? -0.0 : 1.0 / (k * 7.0);
        plan.feedforward(1, k) = 1e3 * std::sin(k);
    }
    plan.feedforwardParameters = Eigen::Vector3d(40.0 / 3.0, 20.000000000000004, 1e-300);
    return plan;
}

// The plan file of samplePlan() with line `line` (1-based) replaced.
QByteArray withLine(int line, const QByteArray &text)
{
    QList<QByteArray> lines = planCsv(samplePlan(), QStringLiteral("paper-2link")).split('\n');
    lines[line - 1] = text;
    return lines.join('\n');
}

} // namespace

void TestPlanCsv::writeThenRead_isBitExact()
{
    const TrialPlan plan = samplePlan();
    const QByteArray csv = planCsv(plan, QStringLiteral("paper-2link"));
    QVERIFY(csv.startsWith("# learnid-plan/1\n# plan-id: "));
    QVERIFY(csv.contains("\n# robot: paper-2link, 2 joints\n# sample-period: 0.002\n"));
    QVERIFY(csv.contains("\nt,qd1,qd2,tauf1,tauf2\n0,"));

    const PlanCsv read = readPlanCsv(csv, source);
    QCOMPARE(read.planId, planIdOf(plan));
    QCOMPARE(read.robotModel, QStringLiteral("paper-2link"));
    QVERIFY(bitEqual(read.samplePeriod, 0.002));
    QVERIFY(bitEqual(read.estimate, plan.feedforwardParameters));
    QVERIFY(bitEqual(read.qDesired, plan.desired.q));
    QVERIFY(bitEqual(read.feedforward, plan.feedforward)); // -0 stays -0
    QCOMPARE(read.samples(), 7);
    for (int k = 0; k < read.samples(); ++k)
        QVERIFY(bitEqual(read.t[k], k * 0.002));

    // Through a file, too.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("plan.csv"));
    writeFileAtomically(path, csv);
    QVERIFY(bitEqual(readPlanCsvFile(path).feedforward, plan.feedforward));
}

void TestPlanCsv::planId_isTheHashOfTheLinesFromTheHeaderOn()
{
    const QByteArray csv = planCsv(samplePlan(), QStringLiteral("paper-2link"));
    const qsizetype header = csv.indexOf("t,qd1");
    QCOMPARE(planIdOf(samplePlan()), planIdOfData(csv.mid(header)));
    QCOMPARE(planIdOf(samplePlan()).size(), 64);
    // Another estimate's feedforward is another plan.
    TrialPlan other = samplePlan();
    other.feedforward(1, 3) = std::nextafter(other.feedforward(1, 3), 0.0);
    QVERIFY(planIdOf(other) != planIdOf(samplePlan()));
}

void TestPlanCsv::crlfAndExtraComments_areAccepted()
{
    QByteArray csv = planCsv(samplePlan(), QStringLiteral("paper-2link"));
    csv.replace("# sample-period:", "# written for the robot in hall 3\n\n# sample-period:");
    csv.replace('\n', "\r\n");
    const PlanCsv read = readPlanCsv(csv, source);
    QCOMPARE(read.planId, planIdOf(samplePlan()));
    QVERIFY(bitEqual(read.qDesired, samplePlan().desired.q));
}

void TestPlanCsv::badInput_namesFileLineAndColumn_data()
{
    QTest::addColumn<QByteArray>("csv");
    QTest::addColumn<QString>("message");
    QTest::newRow("empty") << QByteArray() << "plan.csv: line 1: not a plan file of this version";
    QTest::newRow("other schema") << withLine(1, "# learnid-plan/2")
                                  << "plan.csv: line 1: not a plan file of this version";
    QTest::newRow("no plan-id") << withLine(2, "# note")
                                << "plan.csv: line 6: no \"# plan-id:\" line before the header";
    QTest::newRow("short plan-id")
        << withLine(2, "# plan-id: 12ab") << "plan.csv: line 2: the plan-id must be 64 hex digits";
    QTest::newRow("robot") << withLine(3, "# robot: paper-2link")
                           << "plan.csv: line 3: expected \"# robot: <model>, <n> joints\"";
    QTest::newRow("sample period") << withLine(4, "# sample-period: -1")
                                   << "plan.csv: line 4: the sample period must be a positive";
    QTest::newRow("estimate") << withLine(5, "# estimate: 1, x, 3")
                              << "plan.csv: line 5: estimate value 2 is not a finite number";
    QTest::newRow("repeated key") << withLine(5, "# robot: paper-2link, 2 joints")
                                  << "plan.csv: line 5: a second \"# robot:\" line";
    QTest::newRow("header")
        << withLine(6, "t,qd1,qd2,tau1,tauf2")
        << "plan.csv: line 6, column 4 (tau1): the header of a plan of 2 joints";
    QTest::newRow("header of 3 joints")
        << withLine(6, "t,qd1,qd2,qd3,tauf1,tauf2,tauf3") << "plan.csv: line 6, column 4 (qd3)";
    QTest::newRow("fields") << withLine(8, "0.002,1,2,3")
                            << "plan.csv: line 8, column 5 (tauf2): expected 5 fields, got 4";
    QTest::newRow("number") << withLine(9, "0.004,1,2,abc,4")
                            << "plan.csv: line 9, column 4 (tauf1): not a finite number: \"abc\"";
    QTest::newRow("nan") << withLine(9, "0.004,nan,2,3,4")
                         << "plan.csv: line 9, column 2 (qd1): not a finite number";
    QTest::newRow("time") << withLine(9, "0.005,1,2,3,4")
                          << "plan.csv: line 9, column 1 (t): sample 2 is at k Ts = 0.004 s";
    QTest::newRow("blank among samples")
        << withLine(9, "") << "plan.csv: line 9: a blank or comment line among the samples";
    QTest::newRow("edited") << withLine(9, "0.004,1,2,3,4")
                            << "plan.csv: line 2: the plan-id " + planIdOf(samplePlan()) +
                                   " is not that of the plan's numbers";
    QByteArray noSamples = planCsv(samplePlan(), QStringLiteral("paper-2link"));
    noSamples.truncate(noSamples.indexOf("\n0,") + 1);
    QTest::newRow("no samples") << noSamples << "plan.csv: line 7: no samples after the header";
}

void TestPlanCsv::badInput_namesFileLineAndColumn()
{
    QFETCH(QByteArray, csv);
    QFETCH(QString, message);
    LEARNID_VERIFY_ERROR(readPlanCsv(csv, source), message);
}

void TestPlanCsv::planIdLine_findsTheCopiedLine()
{
    const QString id = planIdOf(samplePlan());
    QCOMPARE(planIdLine("t,q1\n0,1\n", source), QString());
    QCOMPARE(planIdLine("# controller X\r\n#plan-id:" + id.toUpper().toLatin1() +
                            "\r\nt,q1\n# plan-id: " + id.toLatin1() + "\n",
                        source),
             id);
    QCOMPARE(planIdLine(planCsv(samplePlan(), QStringLiteral("paper-2link")), source), id);
}

void TestPlanCsv::planIdLine_refusesAMalformedOrSecondId()
{
    const QByteArray id(64, 'a');
    LEARNID_VERIFY_ERROR(planIdLine("t\n# plan-id: xyz\n", source),
                         "plan.csv: line 2: the plan-id must be 64 hex digits");
    LEARNID_VERIFY_ERROR(
        planIdLine("# plan-id: " + id + "\n# plan-id: " + QByteArray(64, 'b'), source),
        "plan.csv: line 2: a second plan-id, " + QString(64, QLatin1Char('b')) + ", other than " +
            QString(64, QLatin1Char('a')) + " on line 1");
}

QTEST_GUILESS_MAIN(TestPlanCsv)
#include "tst_plancsv.moc"
