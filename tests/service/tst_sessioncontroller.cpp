#include "io/TrialCsv.h"
#include "service/SessionController.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <functional>

using namespace learnid;

namespace {

// Opens the default scenario and waits for the worker's first pre-trial check.
bool openDefaultScenario(SessionController &c)
{
    const Scenario defaults;
    QSignalSpy checked(&c, &SessionController::checkChanged);
    c.open(defaults);
    return checked.wait(20000);
}

// Stands in for the window: notes the events posted to it, by type, in the order handled. Its
// paint (UpdateRequest) takes 100 ms and then delivers what the worker sent the controller in
// the meantime: had the next trial started, its trialStarted would be noted before the paint.
class PostedEventRecorder : public QObject
{
public:
    PostedEventRecorder(QStringList *order, QObject *controller,
                        std::function<void()> afterPaint = {})
        : m_order(order)
        , m_controller(controller)
        , m_afterPaint(std::move(afterPaint))
    {}
    bool event(QEvent *e) override
    {
        if (e->type() == QEvent::UpdateRequest) {
            QThread::msleep(100);
            QCoreApplication::sendPostedEvents(m_controller, QEvent::MetaCall);
            if (m_afterPaint)
                m_afterPaint();
        }
        *m_order << QStringLiteral("window %1").arg(int(e->type()));
        return true;
    }

private:
    QStringList *m_order;
    QObject *m_controller;
    std::function<void()> m_afterPaint;
};

} // namespace

class TestSessionController : public QObject
{
    Q_OBJECT

private slots:
    void open_plansAndChecksTheFirstTrial()
    {
        SessionController c;
        QVERIFY(openDefaultScenario(c));
        QVERIFY(c.isOpen());
        QVERIFY(c.lastCheck()->passed());
        QCOMPARE(c.estimates().size(), 1);
        QVERIFY(c.info()->truth.has_value());
        QCOMPARE(c.info()->parameters.size(), 3);
    }

    void runTrial_deliversValueCopiesOffTheGuiThread()
    {
        SessionController c;
        QVERIFY(openDefaultScenario(c));
        QSignalSpy finished(&c, &SessionController::runFinished);
        QSignalSpy progress(&c, &SessionController::progress);
        c.runTrial();
        QVERIFY(c.isBusy());
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.constFirst().at(0).toBool(), true);
        QVERIFY(!c.isBusy());
        QVERIFY(!progress.isEmpty());
        QCOMPARE(c.history().size(), 1);
        QCOMPARE(c.estimates().size(), 2);
    }

    void trialSamples_stayWithTheSessionAndExportFromThere()
    {
        SessionController c;
        QVERIFY(openDefaultScenario(c));
        QSignalSpy trial(&c, &SessionController::trialFinished);
        QSignalSpy finished(&c, &SessionController::runFinished);
        c.runTrial();
        QVERIFY(finished.wait(20000));
        const TrialResult &kept = c.history().constFirst();
        const int samples = kept.record.samples();
        QVERIFY(samples > 1000);
        QCOMPARE(kept.plan().samples(), samples);
        QCOMPARE(kept.record.q.size(), 0); // the GUI thread holds no samples ...
        QCOMPARE(kept.plan().desired.q.size(), 0);
        QCOMPARE(kept.maxTrackingErrorDeg.size(), 2); // ... but every figure
        QVERIFY(kept.learned());
        // The curves the plot draws came with the trial: one per joint, whose peak is the
        // trial's max tracking error.
        const auto curves = trial.constFirst().at(1).value<QList<TrackingErrorCurve>>();
        QCOMPARE(curves.size(), 2);
        for (const TrackingErrorCurve &curve : curves)
            QCOMPARE(curve.maxAbsDeg, kept.maxTrackingErrorDeg[curve.joint]);

        QTemporaryDir out;
        QSignalSpy exported(&c, &SessionController::trialCsvExported);
        c.exportTrialCsv(out.filePath(QStringLiteral("csv")));
        QVERIFY(exported.wait(20000));
        QCOMPARE(exported.constFirst().at(1).toInt(), 1);
        QCOMPARE(exported.constFirst().at(2).toString(), QString());
        const TrialRecordCsv csv =
            readTrialCsvFile(out.filePath(QStringLiteral("csv/trial-000.csv")));
        QCOMPARE(csv.samples(), samples);
        QCOMPARE(csv.trackingErrorDeg.row(0).cwiseAbs().maxCoeff(), kept.maxTrackingErrorDeg[0]);
    }

    void faultedTrial_isKeptAndLeavesTheEstimate()
    {
        SessionController c;
        SimulatedFaults faults;
        faults.driveFaultAtSample = 300;
        c.setSimulatedFaults(faults);
        QVERIFY(openDefaultScenario(c));
        QSignalSpy finished(&c, &SessionController::runFinished);
        c.runTrial();
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.constFirst().at(0).toBool(), false);
        QCOMPARE(c.history().constFirst().status(), TrialStatus::Faulted);
        QCOMPARE(c.history().constFirst().record.samples(), 301);
        QCOMPARE(c.estimates().size(), 1);
    }

    // The explicit state through a whole workflow, and the applied estimate known by index.
    void workflow_walksTheStatesAndKnowsTheAppliedEstimate()
    {
        SessionController c;
        QList<SessionState> states;
        connect(&c, &SessionController::stateChanged, &c, [&] {
            if (states.isEmpty() || states.constLast() != c.state())
                states << c.state();
        });
        QCOMPARE(c.state(), SessionState::NotConnected);
        QVERIFY(c.allowedActions().connect && !c.allowedActions().run);
        QVERIFY(openDefaultScenario(c));
        QCOMPARE(states, (QList<SessionState>{SessionState::Connecting, SessionState::Idle}));
        QVERIFY(c.allowedActions().run && !c.allowedActions().accept);

        QSignalSpy finished(&c, &SessionController::runFinished);
        c.runTrials(2);
        QCOMPARE(c.state(), SessionState::RunningTrial);
        QVERIFY(c.allowedActions().stop && !c.allowedActions().run);
        QVERIFY(finished.wait(20000));
        QCOMPARE(c.state(), SessionState::Idle);
        QVERIFY(c.allowedActions().accept && !c.allowedActions().apply);

        QSignalSpy accepted(&c, &SessionController::acceptedChanged);
        c.accept(1);
        QVERIFY(accepted.wait(20000));
        QVERIFY(c.allowedActions().apply);
        states.clear();
        QSignalSpy applied(&c, &SessionController::applied);
        c.apply();
        QCOMPARE(c.state(), SessionState::Applying);
        QVERIFY(applied.wait(20000));
        QCOMPARE(states, (QList<SessionState>{SessionState::Applying, SessionState::Idle}));
        QCOMPARE(c.appliedEstimateIndex(), 1);
        QVERIFY(c.allowedActions().revert);
        c.accept(2);
        QVERIFY(accepted.wait(20000));
        c.apply();
        QVERIFY(applied.wait(20000));
        QCOMPARE(c.appliedEstimateIndex(), 2);
        c.revert();
        QVERIFY(applied.wait(20000));
        QCOMPARE(c.appliedEstimateIndex(), 1); // back to the set applied before

        // Stop at once after Run: even before the worker starts the series, it is not lost.
        states.clear();
        const qsizetype ran = c.history().size();
        c.runTrials(3);
        c.stop();
        QCOMPARE(c.state(), SessionState::Stopping);
        QVERIFY(!c.allowedActions().stop && !c.allowedActions().run);
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.constLast().at(0).toBool(), false);
        QCOMPARE(states, (QList<SessionState>{SessionState::RunningTrial, SessionState::Stopping,
                                              SessionState::Idle}));
        // At most the trial under way when it came: stopped at its next sample, or finished
        // already when this thread lost its core between Run and Stop (a paper-arm trial takes
        // a few tens of ms of the worker's CPU), but never a second trial of the series.
        QVERIFY(c.history().size() <= ran + 1);
        QVERIFY(c.history().size() == ran ||
                c.history().constLast().status() == TrialStatus::Cancelled ||
                c.history().constLast().status() == TrialStatus::Completed);

        QSignalSpy closed(&c, &SessionController::closed);
        c.close();
        QVERIFY(closed.wait(20000));
        QCOMPARE(c.state(), SessionState::NotConnected);
    }

    void series_startsEachTrialAfterTheWindowsUpdate()
    {
        // What the window's update leaves for later (layout, paint) is posted; paint at
        // Qt::LowEventPriority. The next trial of a series must start after all of it.
        SessionController c;
        QVERIFY(openDefaultScenario(c));
        QStringList order;
        PostedEventRecorder window(&order, &c);
        connect(&c, &SessionController::trialFinished, &c, [&](const TrialResult &t) {
            order << QStringLiteral("finished %1").arg(t.index);
            QCoreApplication::postEvent(&window, new QEvent(QEvent::User), Qt::NormalEventPriority);
            QCoreApplication::postEvent(&window, new QEvent(QEvent::UpdateRequest),
                                        Qt::LowEventPriority);
        });
        connect(&c, &SessionController::trialStarted, &c,
                [&](int index) { order << QStringLiteral("started %1").arg(index); });
        QSignalSpy finished(&c, &SessionController::runFinished);
        QSignalSpy checked(&c, &SessionController::checkChanged);
        c.runTrials(3);
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.constLast().at(0).toBool(), true);
        QTRY_COMPARE(order.size(), 12); // the last trial's window events come after runFinished
        QCOMPARE(order, (QStringList{"started 0", "finished 0", "window 1000", "window 77",
                                     "started 1", "finished 1", "window 1000", "window 77",
                                     "started 2", "finished 2", "window 1000", "window 77"}));
        QVERIFY(checked.size() == 1 || checked.wait(20000)); // the trial after the series, once
        QTest::qWait(50);
        QCOMPARE(checked.size(), 1);
        QVERIFY(c.lastCheck()->passed());
    }

    void stopBetweenTrials_endsTheSeriesAndChecksTheNextTrial_data()
    {
        QTest::addColumn<bool>("duringPaint");
        QTest::newRow("Stop as the trial's figures arrive") << false;
        QTest::newRow("Stop while the window paints them") << true;
    }

    void stopBetweenTrials_endsTheSeriesAndChecksTheNextTrial()
    {
        QFETCH(bool, duringPaint);
        SessionController c;
        QVERIFY(openDefaultScenario(c));
        QStringList order;
        PostedEventRecorder window(&order, &c, [&c, duringPaint] {
            if (duringPaint)
                c.stop();
        });
        connect(&c, &SessionController::trialFinished, &c, [&c, &window, duringPaint] {
            if (!duringPaint)
                c.stop();
            QCoreApplication::postEvent(&window, new QEvent(QEvent::UpdateRequest),
                                        Qt::LowEventPriority);
        });
        QSignalSpy finished(&c, &SessionController::runFinished);
        QSignalSpy checked(&c, &SessionController::checkChanged);
        c.runTrials(3);
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.constLast().at(0).toBool(), false);
        QCOMPARE(c.state(), SessionState::Idle);
        QCOMPARE(c.history().size(), 1); // the trial under way when Stop came, completed
        QCOMPARE(c.history().constFirst().status(), TrialStatus::Completed);
        QCOMPARE(c.estimates().size(), 2);
        QVERIFY(checked.size() == 1 || checked.wait(20000));
        QTest::qWait(50);
        QCOMPARE(checked.size(), 1);
        QVERIFY(c.lastCheck()->passed());
        QVERIFY(c.canRun());
    }

    void applyWithoutAccept_isRefused()
    {
        SessionController c;
        QVERIFY(openDefaultScenario(c));
        QSignalSpy failed(&c, &SessionController::operationFailed);
        c.apply();
        QVERIFY(failed.wait(20000));
        QCOMPARE(failed.constFirst().at(0).value<SessionOperation>(), SessionOperation::Apply);
        QVERIFY(!c.isBusy());
        QCOMPARE(c.storedParameters().size(), 0);
    }

    void payloadScenario_isRefusedNamingThePayloadStepAndTheCli()
    {
        // The arm's session does not learn a payload (the payload step does, PayloadRunJob): a
        // scenario with a payload section is refused, not run as the arm's session with its
        // payload section ignored.
        SessionController c;
        Scenario s;
        s.payload.enabled = true;
        QSignalSpy failed(&c, &SessionController::openFailed);
        c.open(s);
        QVERIFY(failed.wait(20000));
        const QString message = failed.constFirst().at(0).toString();
        QVERIFY2(message.startsWith(QStringLiteral("payload:")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("payload step")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("learnid-cli run")), qPrintable(message));
        QVERIFY(!c.isOpen());
    }
};

QTEST_MAIN(TestSessionController)
#include "tst_sessioncontroller.moc"
