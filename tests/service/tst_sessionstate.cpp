// The workflow's rules (allowedActions) as a table: state and facts in, allowed steps out.
#include "service/SessionState.h"

#include <QTest>

using namespace learnid;

namespace {

SessionFacts everything()
{
    SessionFacts f;
    f.checkPassed = f.learned = f.ranTrial = f.accepted = f.applied = f.scenarioValid = true;
    return f;
}

} // namespace

class TestSessionState : public QObject
{
    Q_OBJECT

private slots:
    void notConnected_allowsConnectAndEditingOnly();
    void connecting_allowsEditingTheScenarioOnly();
    void whileSomethingRuns_nothingElseStarts_data();
    void whileSomethingRuns_nothingElseStarts();
    void idle_eachStepNeedsItsFact();
    void stop_onlyWhileATrialRuns();
};

void TestSessionState::notConnected_allowsConnectAndEditingOnly()
{
    const AllowedActions a = allowedActions(SessionState::NotConnected, everything());
    AllowedActions expected;
    expected.connect = true;
    expected.editScenario = true;
    expected.exportTrialData = true; // what ran before a disconnect can still be saved
    QVERIFY(a == expected);
    QVERIFY(!isConnected(SessionState::NotConnected));
    QVERIFY(!isConnected(SessionState::Connecting));
}

void TestSessionState::whileSomethingRuns_nothingElseStarts_data()
{
    QTest::addColumn<SessionState>("state");
    QTest::newRow("running a trial") << SessionState::RunningTrial;
    QTest::newRow("stopping") << SessionState::Stopping;
    QTest::newRow("applying") << SessionState::Applying;
}

void TestSessionState::whileSomethingRuns_nothingElseStarts()
{
    QFETCH(SessionState, state);
    const AllowedActions a = allowedActions(state, everything());
    QVERIFY(!a.connect && !a.disconnect && !a.newSession && !a.editScenario);
    QVERIFY(!a.run && !a.accept && !a.apply && !a.revert);
}

void TestSessionState::connecting_allowsEditingTheScenarioOnly()
{
    // An edit re-opens the session with the new scenario; the last open wins.
    const AllowedActions a = allowedActions(SessionState::Connecting, everything());
    QVERIFY(a.editScenario);
    QVERIFY(!a.connect && !a.disconnect && !a.newSession && !a.stop);
    QVERIFY(!a.run && !a.accept && !a.apply && !a.revert);
}

void TestSessionState::idle_eachStepNeedsItsFact()
{
    const SessionState idle = SessionState::Idle;
    QVERIFY(allowedActions(idle, everything()).run);
    SessionFacts f = everything();
    f.checkPassed = false;
    QVERIFY(!allowedActions(idle, f).run);
    f = everything();
    f.learned = false;
    QVERIFY(!allowedActions(idle, f).accept);
    f = everything();
    f.accepted = false;
    QVERIFY(!allowedActions(idle, f).apply);
    QVERIFY(!allowedActions(idle, f).exportParameters);
    f = everything();
    f.applied = false;
    QVERIFY(!allowedActions(idle, f).revert);
    f = everything();
    f.scenarioValid = false;
    QVERIFY(!allowedActions(idle, f).newSession);
    QVERIFY(allowedActions(idle, f).disconnect);
    QVERIFY(!allowedActions(idle, everything()).connect);
}

void TestSessionState::stop_onlyWhileATrialRuns()
{
    for (const SessionState s :
         {SessionState::NotConnected, SessionState::Connecting, SessionState::Idle,
          SessionState::Stopping, SessionState::Applying})
        QVERIFY(!allowedActions(s, everything()).stop);
    QVERIFY(allowedActions(SessionState::RunningTrial, everything()).stop);
    // Exports read what the service holds and may run beside a trial.
    QVERIFY(allowedActions(SessionState::RunningTrial, everything()).exportParameters);
}

QTEST_GUILESS_MAIN(TestSessionState)
#include "tst_sessionstate.moc"
