// `learnid-cli identify --payload` on simulated logs of the KUKA LWR4+ (its URDF held fixed as
// the arm's model) carrying a 3 kg payload 5 cm off the flange axis: the torque is the fixed
// model's inverse dynamics with the payload merged into the flange link, 1 % of each joint's
// limit as white noise, the angles on 2^20-count encoders, 500 Hz for 5 s. A path that tilts
// and turns the wrist gives mass within 1 % and the centre of mass within 3 mm; a path turning
// only about the vertical wrist axis reports m cz and the inertia as not identified and keeps
// the prior there; bad input is refused naming the option, and nothing is written.

#include "../support/SharedData.h"
#include "../support/ToolRun.h"
#include "PayloadLogs.h"
#include "PayloadTrialRows.h"
#include "model/ChainPerturbation.h"
#include "model/Payload.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <random>

using namespace learnid;
using learnid::test::payloadLog;
using learnid::test::tableRow;
using learnid::test::tableStdError;
using learnid::test::tableValue;
using learnid::test::truePayload;

namespace {

const QString cli = QStringLiteral(LEARNID_CLI_PATH);

} // namespace

class TestCliPayload : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void wristTurningPath_massWithinOnePercentAndComWithinThreeMillimetres();
    void verticalWristPath_reportsTheUnseenAndKeepsThePrior();
    void wrongArm_aBaselineLogTakesItsErrorOut();
    void badInput_namesTheOptionAndWritesNothing_data();
    void badInput_namesTheOptionAndWritesNothing();

private:
    QTemporaryDir m_dir;
    QString m_urdf, m_rich, m_check, m_vertical;
};

void TestCliPayload::initTestCase()
{
    m_urdf = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    const auto arm = test::kukaArm();
    if (!arm)
        QSKIP(qPrintable(test::sharedDataMissing()));
    // The arm model learnid-cli builds by default: viscous, Coulomb friction and offsets.
    const PayloadModel model(arm, arm->cadStandard());
    m_rich = m_dir.filePath(QStringLiteral("rich.csv"));
    m_check = m_dir.filePath(QStringLiteral("check.csv"));
    m_vertical = m_dir.filePath(QStringLiteral("vertical.csv"));
    QVERIFY(test::writeFile(m_rich, payloadLog(model, test::richPath(*arm, 5.0), 1)));
    QVERIFY(test::writeFile(m_check, payloadLog(model, test::richPath(*arm, 4.0), 2)));
    QVERIFY(test::writeFile(m_vertical, payloadLog(model, test::wristTurnPath(*arm, 5.0), 3)));
}

void TestCliPayload::wristTurningPath_massWithinOnePercentAndComWithinThreeMillimetres()
{
    const QString plots = m_dir.filePath(QStringLiteral("plots"));
    const test::ToolRun run =
        test::runTool(cli, {QStringLiteral("identify"), QStringLiteral("--robot"), m_urdf,
                            QStringLiteral("--log"), m_rich, QStringLiteral("--validate"), m_check,
                            QStringLiteral("--payload"), QStringLiteral("--payload-mass"),
                            QStringLiteral("2.5"), QStringLiteral("--payload-com"),
                            QStringLiteral("0,0,0.05"), QStringLiteral("--plots"), plots});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    qInfo("%s", qPrintable(run.out));
    const double mass = tableValue(run.out, QStringLiteral("m"));
    QVERIFY2(std::abs(mass - 3.0) < 0.03, qPrintable(QString::number(mass)));
    const Eigen::Vector3d c(tableValue(run.out, QStringLiteral("cx")),
                            tableValue(run.out, QStringLiteral("cy")),
                            tableValue(run.out, QStringLiteral("cz")));
    QVERIFY2((c - truePayload().com).norm() < 0.003,
             qPrintable(QStringLiteral("%1 %2 %3").arg(c.x()).arg(c.y()).arg(c.z())));
    for (const char *name : {"m", "cx", "cy", "cz"})
        QVERIFY(tableRow(run.out, QLatin1String(name)).endsWith(QStringLiteral("the logs")));
    QVERIFY(run.out.contains(QStringLiteral("A real body whose mass lies in the bound")));
    QVERIFY(QFileInfo::exists(QDir(plots).filePath(QStringLiteral("check-payload-torque.png"))));
}

void TestCliPayload::verticalWristPath_reportsTheUnseenAndKeepsThePrior()
{
    const test::ToolRun run =
        test::runTool(cli, {QStringLiteral("identify"), QStringLiteral("--robot"), m_urdf,
                            QStringLiteral("--log"), m_vertical, QStringLiteral("--payload"),
                            QStringLiteral("--payload-mass"), QStringLiteral("2.5"),
                            QStringLiteral("--payload-com"), QStringLiteral("0,0,0.05")});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    qInfo("%s", qPrintable(run.out));
    QVERIFY(tableRow(run.out, QStringLiteral("m")).endsWith(QStringLiteral("the logs")));
    QVERIFY(tableRow(run.out, QStringLiteral("cx")).endsWith(QStringLiteral("the logs")));
    QVERIFY(tableRow(run.out, QStringLiteral("cz")).endsWith(QStringLiteral("(not identified)")));
    QVERIFY(
        tableRow(run.out, QStringLiteral("Ic xx")).endsWith(QStringLiteral("(not identified)")));
    QVERIFY(std::abs(tableValue(run.out, QStringLiteral("m")) - 3.0) < 0.03);
    QVERIFY(std::abs(tableValue(run.out, QStringLiteral("cx")) - 0.05) < 0.003);
    // Kept: the prior's 5 cm along the wrist axis, not the true 8 cm.
    QVERIFY2(std::abs(tableValue(run.out, QStringLiteral("cz")) - 0.05) < 0.0005,
             qPrintable(tableRow(run.out, QStringLiteral("cz"))));
    QVERIFY(run.out.contains(QStringLiteral("the centre of mass along the z axis of lwr_7_link "
                                            "is not seen")));
    QVERIFY(run.out.contains(QStringLiteral("the inertia Ixx, Ixy, Iyy is not seen")));
}

void TestCliPayload::wrongArm_aBaselineLogTakesItsErrorOut()
{
    // The real arm +-10 % off the URDF held fixed; the payload log starts 0.3 s into the motion
    // the baseline log (the same program without the payload) recorded.
    const auto arm = test::kukaArm();
    const PayloadModel real(arm, perturbedStandard(*arm, 0.1, 4));
    const test::JointPath path = test::richPath(*arm, 5.6);
    test::JointPath part = path;
    part.q = path.q.middleCols(150, 2501);
    part.qd = path.qd.middleCols(150, 2501);
    part.qdd = path.qdd.middleCols(150, 2501);
    const QString with = m_dir.filePath(QStringLiteral("with.csv")),
                  without = m_dir.filePath(QStringLiteral("without.csv"));
    QVERIFY(test::writeFile(with, payloadLog(real, part, 5)));
    QVERIFY(test::writeFile(without, payloadLog(real, path, 6, InertialParameters::Zero())));
    const QStringList args{QStringLiteral("identify"),
                           QStringLiteral("--robot"),
                           m_urdf,
                           QStringLiteral("--log"),
                           with,
                           QStringLiteral("--payload"),
                           QStringLiteral("--payload-mass"),
                           QStringLiteral("2.5"),
                           QStringLiteral("--payload-com"),
                           QStringLiteral("0,0,0.05")};
    const test::ToolRun plain = test::runTool(cli, args);
    QVERIFY2(plain.exitCode == 0, qPrintable(plain.err));
    const test::ToolRun run =
        test::runTool(cli, args + QStringList{QStringLiteral("--baseline-log"), without});
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    qInfo("%s", qPrintable(run.out));
    QVERIFY2(
        run.out.contains(
            QStringLiteral("Baseline %1 taken out of %2: shifted by 0.300 s").arg(without, with)),
        qPrintable(run.out));
    // Each value within 4 of its standard errors of the truth (the baseline's own noise is in
    // them: they come from the residual after the subtraction); without the baseline the mass is
    // off by many.
    const double truth[] = {3.0, truePayload().com.x(), truePayload().com.y(),
                            truePayload().com.z()};
    const char *const names[] = {"m", "cx", "cy", "cz"};
    for (int i = 0; i < 4; ++i) {
        const QString name = QLatin1String(names[i]);
        const double value = tableValue(run.out, name), error = tableStdError(run.out, name);
        QVERIFY2(std::abs(value - truth[i]) < 4.0 * error,
                 qPrintable(QStringLiteral("%1: %2 +- %3").arg(name).arg(value).arg(error)));
    }
    const double biased = tableValue(plain.out, QStringLiteral("m"));
    const double biasedError = tableStdError(plain.out, QStringLiteral("m"));
    qInfo("without the baseline: %g +- %g kg", biased, biasedError);
    QVERIFY2(std::abs(biased - 3.0) > 10.0 * biasedError, qPrintable(QString::number(biased)));
}

void TestCliPayload::badInput_namesTheOptionAndWritesNothing_data()
{
    QTest::addColumn<QStringList>("options");
    QTest::addColumn<QString>("message");
    const auto l = [](std::initializer_list<const char *> a) {
        QStringList out;
        for (const char *s : a)
            out << QLatin1String(s);
        return out;
    };
    QTest::newRow("zero mass") << l({"--payload", "--payload-mass", "0"})
                               << QStringLiteral("--payload-mass: the payload's mass must be a "
                                                 "positive number");
    QTest::newRow("negative mass")
        << l({"--payload", "--payload-mass", "-2"}) << QStringLiteral("--payload-mass:");
    QTest::newRow("nan mass") << l({"--payload", "--payload-mass", "nan"})
                              << QStringLiteral("--payload-mass:");
    QTest::newRow("nan com") << l({"--payload", "--payload-mass", "3", "--payload-com",
                                   "0,nan,0.05"})
                             << QStringLiteral("--payload-com: the centre of mass must be finite");
    QTest::newRow("bound without prior")
        << l({"--payload", "--payload-mass", "3", "--payload-com", "0,0,0.05", "--payload-radius",
              "0.04"})
        << QStringLiteral("--payload-radius: the prior centre of mass (0, 0, 0.05) m is not "
                          "inside the bound");
    QTest::newRow("box without prior")
        << l({"--payload", "--payload-mass", "3", "--payload-com", "0,0,0.2", "--payload-box",
              "-0.1,-0.1,0,0.1,0.1,0.15"})
        << QStringLiteral("--payload-box: the prior centre of mass");
    QTest::newRow("unknown link") << l({"--payload", "--payload-mass", "3", "--payload-link",
                                        "gripper"})
                                  << QStringLiteral("--payload-link: payload link 'gripper' is "
                                                    "not a moving link");
    QTest::newRow("no mass") << l({"--payload"})
                             << QStringLiteral("--payload: needs --payload-mass");
    QTest::newRow("no --payload") << l({"--payload-mass", "3"})
                                  << QStringLiteral("--payload-mass: needs --payload");
    QTest::newRow("arm urdf without payload")
        << l({"--arm-urdf", "arm.urdf"}) << QStringLiteral("--arm-urdf: needs --payload");
    QTest::newRow("arm urdf for a urdf")
        << l({"--payload", "--payload-mass", "3", "--arm-urdf", "arm.urdf", "--export", "p.json"})
        << QStringLiteral("--arm-urdf: only for a parameter file");
    QTest::newRow("baseline without payload")
        << l({"--baseline-log", "b.csv"}) << QStringLiteral("--baseline-log: needs --payload");
    QTest::newRow("baseline missing")
        << l({"--payload", "--payload-mass", "3", "--baseline-log", "nosuch.csv"})
        << QStringLiteral("nosuch.csv");
    QTest::newRow("baseline of another path")
        << QStringList{QStringLiteral("--payload"), QStringLiteral("--payload-mass"),
                       QStringLiteral("3"), QStringLiteral("--baseline-log"), m_vertical}
        << QStringLiteral("%1 does not follow the path of %2: their joint angles differ by")
               .arg(m_vertical, m_rich);
}

void TestCliPayload::badInput_namesTheOptionAndWritesNothing()
{
    QFETCH(QStringList, options);
    QFETCH(QString, message);
    QTemporaryDir work;
    const QString plots = work.filePath(QStringLiteral("plots"));
    const test::ToolRun run = test::runTool(
        cli,
        QStringList{QStringLiteral("identify"), QStringLiteral("--robot"), m_urdf,
                    QStringLiteral("--log"), m_rich, QStringLiteral("--plots"), plots,
                    QStringLiteral("--report"), work.filePath(QStringLiteral("r.pdf"))} +
            options,
        work.path());
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.contains(message), qPrintable(run.err));
    QVERIFY(QDir(work.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries).isEmpty());
}

QTEST_MAIN(TestCliPayload)
#include "tst_cli_payload.moc"
