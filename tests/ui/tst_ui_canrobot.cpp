#include "../support/RobotSimProcess.h"
#include "UiTestSupport.h"

#include "service/SessionController.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/MessageBar.h"
#include "ui/RobotPanel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSpinBox>
#include <QtTest>
#include <cmath>

using namespace learnid;
using namespace learnid::test;

/// The window's CAN robot choice: against learnid-robot-sim over virtualcan on a loopback port,
/// and the settings a technician can get wrong.
class TestCanRobotChoice : public QObject
{
    Q_OBJECT

private slots:
    void badNodeList_isRefusedBeforeConnecting()
    {
        WindowFixture f;
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        f.chooseCan(QStringLiteral("virtualcan"), QStringLiteral("tcp://127.0.0.1:1/can0"),
                    QStringLiteral("1,200"));
        QVERIFY(f.click("connectButton"));
        QVERIFY(!f.window->controller()->isOpen());
        const QString text = f.window->messageBar()->text();
        QVERIFY2(text.contains(QStringLiteral("200")), qPrintable(text));
    }

    void syncTimeout_isTheLongestGapOrTheDefaultOfThePeriod()
    {
        WindowFixture f;
        f.chooseCan(QStringLiteral("virtualcan"), QStringLiteral("tcp://127.0.0.1:1/can0"),
                    QStringLiteral("1,2"));
        auto *timeout = f.window->findChild<QSpinBox *>(QStringLiteral("canSyncTimeout"));
        const auto *panel = f.window->findChild<RobotPanel *>();
        QVERIFY(timeout && panel);
        QCOMPARE(timeout->value(), 0); // automatic: 10 periods, at least 50 ms
        // {spin box, SYNC timeout in force at the 2 ms of the paper scenario}
        for (const auto &[ms, expected] : {std::pair{0, 50}, {3, 4}, {21, 21}, {200, 200}}) {
            timeout->setValue(ms);
            QString error;
            const std::optional<RobotRequest> choice = panel->choice(&error);
            QVERIFY2(choice.has_value(), qPrintable(error));
            QCOMPARE(choice->can.syncPeriod, 0.002);
            QCOMPARE(effectiveSyncTimeoutMs(choice->can), expected);
        }
    }

    // learnid-cli's --commission in the window: unticked, drives never commissioned are refused
    // before any motion, naming node and joint; ticked, the same drives run the trial.
    void firstCommissioning_isTheCheckBox_refusedWithoutItRunsWithIt()
    {
        const quint16 port = freeLoopbackPort();
        QVERIFY(port > 0);
        const QString interface = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
        RobotSimProcess sim(QStringLiteral(LEARNID_ROBOT_SIM_PATH));
        QVERIFY(sim.start(interface, {QStringLiteral("--uncommissioned")}));

        WindowFixture f;
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        SessionController *c = f.window->controller();
        f.chooseCan(QStringLiteral("virtualcan"), interface, QStringLiteral("1,2"));
        f.window->findChild<QSpinBox *>(QStringLiteral("canSyncTimeout"))->setValue(200);
        auto *commission = f.window->findChild<QCheckBox *>(QStringLiteral("canCommission"));
        const auto *panel = f.window->findChild<RobotPanel *>();
        QVERIFY(commission && panel);
        QVERIFY(!commission->isChecked()); // never on by default
        for (const bool ticked : {false, true}) {
            commission->setChecked(ticked);
            QString error;
            const std::optional<RobotRequest> choice = panel->choice(&error);
            QVERIFY2(choice.has_value(), qPrintable(error));
            QCOMPARE(choice->can.commissioning, ticked);

            QVERIFY(f.click("connectButton"));
            QTRY_VERIFY_WITH_TIMEOUT(c->lastCheck().has_value(), 20000);
            QVERIFY(!commission->isEnabled()); // not while connected
            QSignalSpy finished(c, &SessionController::runFinished);
            QTRY_VERIFY_WITH_TIMEOUT(f.button("runTrialButton")->isEnabled(), 20000);
            QVERIFY(f.click("runTrialButton"));
            QVERIFY(finished.wait(60000));
            if (!ticked) {
                const QString text = f.window->messageBar()->text();
                QVERIFY2(text.contains(QStringLiteral("node 1 (joint 1) has never been "
                                                      "commissioned")) &&
                             text.contains(QStringLiteral("First commissioning")),
                         qPrintable(text));
            } else {
                QVERIFY(!c->history().isEmpty());
                QVERIFY2(c->history().constLast().record.completed(),
                         qPrintable(c->history().constLast().record.message));
            }
            QVERIFY(f.click("connectButton")); // disconnect
            QTRY_VERIFY_WITH_TIMEOUT(!c->isOpen(), 10000);
            QVERIFY(commission->isEnabled());
        }
    }

    void missingInterface_failsWithAClearMessage()
    {
        WindowFixture f;
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        SessionController *c = f.window->controller();
        QSignalSpy failed(c, &SessionController::openFailed);
        f.chooseCan(QStringLiteral("socketcan"), QStringLiteral("learnidnoif0"),
                    QStringLiteral("1,2"));
        QVERIFY(f.click("connectButton"));
        QVERIFY(failed.wait(10000));
        const QString message = failed.constFirst().at(0).toString();
        QVERIFY2(message.contains(QStringLiteral("learnidnoif0")), qPrintable(message));
        QVERIFY(!c->isOpen());
        QVERIFY(f.button("connectButton")->isEnabled()); // usable again
        QVERIFY(f.window->messageBar()->text().contains(QStringLiteral("learnidnoif0")));
    }

    void sessionOnTheSimulatorOverVirtualcan()
    {
        const quint16 port = freeLoopbackPort();
        QVERIFY(port > 0);
        const QString interface = QStringLiteral("tcp://127.0.0.1:%1/can0").arg(port);
        RobotSimProcess sim(QStringLiteral(LEARNID_ROBOT_SIM_PATH));
        QVERIFY(sim.start(interface));

        WindowFixture f;
        QVERIFY(QTest::qWaitForWindowExposed(f.window.get()));
        SessionController *c = f.window->controller();
        f.chooseCan(QStringLiteral("virtualcan"), interface, QStringLiteral("1,2"));
        // As tst_can_e2e: CI shares 2 cores between two processes on a 2 ms SYNC clock.
        f.window->findChild<QSpinBox *>(QStringLiteral("canSyncTimeout"))->setValue(200);
        QVERIFY(f.click("connectButton"));
        QTRY_VERIFY_WITH_TIMEOUT(c->lastCheck().has_value(), 20000);
        QVERIFY(c->info()->robotDescription.contains(QStringLiteral("virtualcan")));
        QVERIFY(!c->info()->truth.has_value()); // no error-against-truth columns on a real bus

        QSignalSpy finished(c, &SessionController::runFinished);
        QTRY_VERIFY_WITH_TIMEOUT(f.button("runTrialButton")->isEnabled(), 20000);
        QVERIFY(f.click("runTrialButton"));
        QVERIFY(finished.wait(60000));
        QCOMPARE(c->history().size(), 1);
        QVERIFY2(c->history().constFirst().record.completed(),
                 qPrintable(c->history().constFirst().record.message));
        QVERIFY(c->history().constFirst().learned());
        const ConvergenceTableModel *table = f.window->tableModel();
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->columnOf(ConvergenceTableModel::Column::TruthError, 0), -1);

        QVERIFY(f.click("connectButton")); // disconnect
        QTRY_VERIFY_WITH_TIMEOUT(!c->isOpen(), 10000);
    }
};

QTEST_MAIN(TestCanRobotChoice)
#include "tst_ui_canrobot.moc"
