// `learnid-cli run --robot can` with a payload section, end to end over virtualcan:
// learnid-robot-sim's seven drives move the Panda carrying the scenario's payload (1.5 kg 5 cm off
// the flange axis, simulation.payload), learnid-cli learns it through the bus in the learning
// loop, the arm's model held fixed, applies it to the drives (0x2500, read back and stored) and
// exports it. Baseline trials, which need the payload taken off, are refused on the CAN robot
// before anything is sent.
#include "../session/PayloadScenarios.h"
#include "../support/CanE2eBus.h"
#include "../support/RobotSimProcess.h"
#include "../support/ToolRun.h"
#include "PayloadTrialRows.h"
#include "io/ParameterFile.h"
#include "io/ScenarioFile.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

namespace {

const QString kNodes = QStringLiteral("1,2,3,4,5,6,7");

} // namespace

class TestCliCanPayload : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // SYNC every 4 ms: seven nodes at 2 ms would need 98 % of a 1 Mbit/s bus.
        Scenario s = test::pandaWithPayload();
        s.controller.samplePeriod = 0.004;
        m_scenario = m_dir.filePath(QStringLiteral("panda-payload-4ms.json"));
        writeScenarioFile(m_scenario, s);
    }

    void payloadOverCan_learnedAndExported()
    {
        const quint16 port = test::canE2ePort();
        QVERIFY(port != 0);
        test::RobotSimProcess robot(QStringLiteral(LEARNID_ROBOT_SIM_PATH));
        const QString state = m_dir.filePath(QStringLiteral("state.json"));
        QVERIFY(robot.start(test::canE2eInterface(port),
                            {QStringLiteral("--scenario"), m_scenario, QStringLiteral("--nodes"),
                             kNodes, QStringLiteral("--state"), state}));
        const QString exported = m_dir.filePath(QStringLiteral("payload.json"));
        const test::ToolRun run = runCli(
            QStringList{QStringLiteral("run"), QStringLiteral("--robot"), QStringLiteral("can")} +
            test::canE2eBusOptions(port) +
            QStringList{QStringLiteral("--nodes"), kNodes, QStringLiteral("--scenario"), m_scenario,
                        QStringLiteral("--can-sync-timeout"), QStringLiteral("200"),
                        QStringLiteral("--apply"), QStringLiteral("--export"), exported});
        QVERIFY2(run.exitCode == 0, qPrintable(run.err + robot.stderrText()));
        qInfo("%s", qPrintable(run.out));
        QVERIFY2(run.err.contains(QStringLiteral("CAN virtualcan")), qPrintable(run.err));
        QVERIFY(run.err.contains(QStringLiteral("the payload on panda_link7")));

        // Trial 0 ran with the prior (1.2 kg on the flange's axis); each fit finds the payload
        // the drives carry, within 1 % and 3 mm, and the feedforward with it tracks far better.
        const QList<test::PayloadRow> rows = test::payloadTrialRows(run.out);
        QCOMPARE(rows.size(), 3);
        for (const test::PayloadRow &r : rows) {
            QCOMPARE(r.identified, QStringLiteral("all"));
            QVERIFY2(std::abs(r.mass - 1.5) < 0.015, qPrintable(QString::number(r.mass)));
            QVERIFY2((r.comMm - Eigen::Vector3d(50, 0, 80)).norm() < 3.0,
                     qPrintable(QString::number(r.comMm.z())));
        }
        QVERIFY(rows[0].maxError > 10.0 * rows[2].maxError);

        const ParameterFileContent content = readParameterFile(exported);
        QVERIFY(content.payload.has_value());
        QCOMPARE(content.payload->link, QStringLiteral("panda_link7"));
        QVERIFY(std::abs(content.payload->mass - rows.back().mass) < 0.0005 * rows.back().mass);

        // Applied: every drive stored the exported payload on joint 7 (panda_link7 is the body
        // of joint 7 itself, so its frame is the body's), in REAL32.
        QVERIFY(run.err.contains(QStringLiteral("the payload applied to the robot")));
        QFile f(state);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject nodes =
            QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("nodes")).toObject();
        QCOMPARE(nodes.size(), 7);
        const InertialParameters body = content.payload->parameters();
        for (const QString &node : nodes.keys()) {
            const QJsonObject stored =
                nodes.value(node).toObject().value(QStringLiteral("storedPayload")).toObject();
            QCOMPARE(stored.value(QStringLiteral("joint")).toInt(), 7);
            const QJsonArray values = stored.value(QStringLiteral("parameters")).toArray();
            QCOMPARE(values.size(), 10);
            for (int i = 0; i < 10; ++i) {
                QVERIFY2(std::abs(values[i].toDouble() - body[i]) <=
                             1e-6 * std::abs(body[i]) + 1e-12,
                         qPrintable(QStringLiteral("node %1, 0x2500:%2: %3 against %4")
                                        .arg(node)
                                        .arg(i + 2)
                                        .arg(values[i].toDouble())
                                        .arg(body[i])));
            }
        }
    }

    void baselineTrials_refusedOnTheCanRobotBeforeTheBus()
    {
        Scenario s = test::pandaWithPayload();
        s.controller.samplePeriod = 0.004;
        s.payload.baselineTrials = 1;
        const QString file = m_dir.filePath(QStringLiteral("baseline.json"));
        writeScenarioFile(file, s);
        // Nobody listens on this port: the refusal comes before any connection.
        const test::ToolRun run = runCli(
            QStringList{QStringLiteral("run"), QStringLiteral("--robot"), QStringLiteral("can")} +
            test::canE2eBusOptions(test::freeLoopbackPort()) +
            QStringList{QStringLiteral("--nodes"), kNodes, QStringLiteral("--scenario"), file});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.contains(QStringLiteral("payload.baselineTrials: baseline trials are not "
                                                 "offered on the CAN robot")),
                 qPrintable(run.err));
        QVERIFY(!run.err.contains(QStringLiteral("connected")));
    }

private:
    test::ToolRun runCli(const QStringList &args) const
    {
        return test::runTool(QStringLiteral(LEARNID_CLI_PATH), args, m_dir.path(), 240000);
    }

    QTemporaryDir m_dir;
    QString m_scenario;
};

QTEST_GUILESS_MAIN(TestCliCanPayload)
#include "tst_cli_can_payload.moc"
