#include "UiTestSupport.h"

#include "service/SessionController.h"
#include "ui/ConvergenceTableModel.h"
#include "ui/FileController.h"
#include "ui/MainActions.h"
#include "ui/MessageBar.h"
#include "ui/PreTrialCheckView.h"
#include "ui/RunPanel.h"
#include "ui/ScenarioForm.h"
#include "ui/TrackingErrorPlot.h"

#include <QAction>
#include <QLineEdit>
#include <QSignalSpy>
#include <QtTest>

using namespace learnid;
using namespace learnid::test;

/// Each failure ends in a clear message and a window that still works.
class TestMainWindowFailures : public QObject
{
    Q_OBJECT

private:
    static void type(MainWindow *w, const char *key, const QString &text)
    {
        auto *edit = w->findChild<QLineEdit *>(QLatin1String(key));
        QVERIFY(edit);
        edit->selectAll();
        QTest::keyClicks(edit, text);
    }

    static bool connectAndCheck(WindowFixture &f)
    {
        SessionController *c = f.window->controller();
        QSignalSpy checked(c, &SessionController::checkChanged);
        if (!f.click("connectButton"))
            return false;
        return checked.wait(20000);
    }

    static bool runOne(WindowFixture &f)
    {
        QSignalSpy finished(f.window->controller(), &SessionController::runFinished);
        return f.click("runTrialButton") && finished.wait(20000);
    }

private slots:
    void badInput_isRefusedAtTheFieldAndConnectSaysWhy()
    {
        WindowFixture f;
        type(f.window.get(), "controller.lambda", QStringLiteral("fast"));
        QVERIFY(!f.window->form()->reasonFor(QStringLiteral("controller.lambda")).isEmpty());
        QVERIFY(f.click("connectButton"));
        QCOMPARE(f.window->messageBar()->severity(), MessageBar::Severity::Error);
        QVERIFY(f.window->messageBar()->text().contains(QStringLiteral("controller.lambda")));
        QVERIFY(!f.window->controller()->isOpen());
        type(f.window.get(), "controller.lambda", QStringLiteral("200"));
        QVERIFY(connectAndCheck(f));
        QVERIFY(f.window->controller()->lastCheck()->passed());
    }

    void failingCheck_disablesRunAndSaysWhy()
    {
        WindowFixture f;
        QVERIFY(connectAndCheck(f));
        SessionController *c = f.window->controller();
        QSignalSpy checked(c, &SessionController::checkChanged);
        // The paper's lambda = 40 with the true inertia: the closed loop is unstable.
        type(f.window.get(), "robot.initialParameters", QStringLiteral("20, 5, 8"));
        type(f.window.get(), "controller.lambda", QStringLiteral("40"));
        QTRY_VERIFY_WITH_TIMEOUT(c->lastCheck() && c->isOpen() &&
                                     c->info()->scenario.controller.lambda == 40.0 &&
                                     c->lastCheck()->passed() == false,
                                 20000);
        QVERIFY(!f.button("runTrialButton")->isEnabled());
        QVERIFY(!f.button("runAllButton")->isEnabled());
        QVERIFY(!f.window->actions()->runTrial->isEnabled());
        const QString verdict = f.window->checkView()->verdictText();
        QVERIFY2(verdict.contains(QStringLiteral("refused")), qPrintable(verdict));
        QVERIFY(f.window->runPanel()->status().contains(c->lastCheck()->reason()));
        type(f.window.get(), "controller.lambda", QStringLiteral("200"));
        QTRY_VERIFY_WITH_TIMEOUT(f.button("runTrialButton")->isEnabled(), 20000);
    }

    void stopDuringATrial_endsItSafelyAndKeepsItsData()
    {
        WindowFixture f;
        // A slow simulation (fine RK4) so the trial is still running when Stop arrives.
        Scenario slow = *f.window->form()->scenario();
        slow.simulation.substeps = 400;
        f.window->form()->setScenario(slow);
        QVERIFY(connectAndCheck(f));
        SessionController *c = f.window->controller();
        QSignalSpy finished(c, &SessionController::runFinished);
        QSignalSpy progress(c, &SessionController::progress);
        QVERIFY(f.click("runTrialButton"));
        QVERIFY(progress.wait(20000));
        QVERIFY(f.click("stopButton"));
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.constLast().at(0).toBool(), false);
        const TrialResult &t = c->history().constLast();
        QCOMPARE(t.status(), TrialStatus::Cancelled);
        QVERIFY(t.record.samples() > 0 && t.record.samples() < t.plan().samples());
        QCOMPARE(c->estimates().size(), 1);
        QCOMPARE(f.window->messageBar()->severity(), MessageBar::Severity::Error);
        QVERIFY(f.window->messageBar()->text().contains(trialStatusName(TrialStatus::Cancelled)));
        QCOMPARE(f.window->plot()->trialCount(), 1);          // its data are shown
        QTRY_VERIFY(f.button("runTrialButton")->isEnabled()); // usable again
    }

    void robotFault_isShownAndTheNextTrialRuns()
    {
        WindowFixture f;
        SimulatedFaults faults;
        faults.driveFaultAtSample = 400;
        f.window->controller()->setSimulatedFaults(faults);
        QVERIFY(connectAndCheck(f));
        SessionController *c = f.window->controller();
        QVERIFY(runOne(f));
        QCOMPARE(c->history().constLast().status(), TrialStatus::Faulted);
        QVERIFY(f.window->messageBar()->text().contains(QStringLiteral("fault")));
        QCOMPARE(f.window->tableModel()->rowCount(), 1);
        c->setSimulatedFaults({});
        QTRY_VERIFY(f.button("runTrialButton")->isEnabled());
        QVERIFY(runOne(f));
        QCOMPARE(c->history().constLast().status(), TrialStatus::Completed);
        QCOMPARE(f.window->tableModel()->rowCount(), 2);
    }

    void refusedApply_reportsTheExactFailure()
    {
        WindowFixture f;
        SimulatedFaults faults;
        faults.refuseApply = true;
        f.window->controller()->setSimulatedFaults(faults);
        QVERIFY(connectAndCheck(f));
        QVERIFY(runOne(f));
        QVERIFY(f.click("acceptButton"));
        QTRY_VERIFY(f.button("applyButton")->isEnabled());
        f.window->setApplyConfirmation([](const ApplyPreview &) { return true; });
        QSignalSpy failed(f.window->controller(), &SessionController::operationFailed);
        QVERIFY(f.click("applyButton"));
        QVERIFY(failed.wait(20000));
        QVERIFY(f.window->messageBar()->text().contains(QStringLiteral("refused")));
        QCOMPARE(f.window->controller()->storedParameters().size(), 0);
        QTRY_VERIFY(f.button("applyButton")->isEnabled());
    }

    void declinedConfirmation_writesNothing()
    {
        WindowFixture f;
        QVERIFY(connectAndCheck(f));
        QVERIFY(runOne(f));
        QVERIFY(f.click("acceptButton"));
        QTRY_VERIFY(f.button("applyButton")->isEnabled());
        f.window->setApplyConfirmation([](const ApplyPreview &) { return false; });
        QVERIFY(f.click("applyButton"));
        QVERIFY(!f.window->controller()->isBusy());
        QCOMPARE(f.window->controller()->storedParameters().size(), 0);
    }

    void exportToAnUnwritablePath_saysWhereAndWhy()
    {
        WindowFixture f;
        QVERIFY(connectAndCheck(f));
        QVERIFY(runOne(f));
        QVERIFY(f.click("acceptButton"));
        QTRY_VERIFY(f.window->controller()->acceptedIndex().has_value());
        QTemporaryDir out;
        const QString file = out.filePath(QStringLiteral("plain-file"));
        QFile(file).open(QIODevice::WriteOnly);
        const QString bad = file + QStringLiteral("/params.json");
        QSignalSpy done(f.window->files(), &FileController::finished);
        f.window->files()->exportParameterFileTo(bad);
        QVERIFY(done.wait(20000));
        QCOMPARE(done.constLast().at(1).toBool(), false);
        QCOMPARE(f.window->messageBar()->severity(), MessageBar::Severity::Error);
        QVERIFY(f.window->messageBar()->text().contains(QStringLiteral("plain-file")));
        QVERIFY(!QFile::exists(bad));
        f.window->files()->exportReportTo(file + QStringLiteral("/report.pdf"));
        QCOMPARE(done.constLast().at(1).toBool(), false);
        const int before = int(done.size());
        f.window->files()->exportTrialCsvTo(file + QStringLiteral("/trials"));
        QTRY_COMPARE_WITH_TIMEOUT(int(done.size()), before + 1,
                                  20000); // answered by the session's thread
        QCOMPARE(done.constLast().at(1).toBool(), false);
        QVERIFY2(done.constLast().at(0).toString().contains(QStringLiteral("plain-file")),
                 qPrintable(done.constLast().at(0).toString()));
        // The window still exports to a good path.
        f.window->files()->exportParameterFileTo(out.filePath(QStringLiteral("ok.json")));
        QVERIFY(done.wait(20000));
        QVERIFY(done.constLast().at(1).toBool());
    }
};

QTEST_MAIN(TestMainWindowFailures)
#include "tst_ui_mainwindowfailures.moc"
