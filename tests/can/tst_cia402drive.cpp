#include "can/Cia402Drive.h"

#include <QTest>

using namespace learnid;
using cia402::State;

namespace {

/// A drive brought to state by the usual controlwords.
Cia402Drive driveIn(State state)
{
    Cia402Drive d;
    if (state == State::NotReadyToSwitchOn)
        return d;
    d.initialise();
    switch (state) {
    case State::ReadyToSwitchOn:
        d.applyControlword(0x06);
        break;
    case State::SwitchedOn:
        d.applyControlword(0x06);
        d.applyControlword(0x07);
        break;
    case State::OperationEnabled:
        d.applyControlword(0x06);
        d.applyControlword(0x0F);
        break;
    case State::QuickStopActive:
        d.applyControlword(0x06);
        d.applyControlword(0x0F);
        d.applyControlword(0x02);
        break;
    case State::FaultReactionActive:
        d.raiseFault();
        break;
    case State::Fault:
        d.raiseFault();
        d.completeFaultReaction();
        break;
    default:
        break;
    }
    return d;
}

} // namespace

class TestCia402Drive : public QObject
{
    Q_OBJECT

private slots:
    void transitions_followTheCiA402StateMachine_data();
    void transitions_followTheCiA402StateMachine();
    void statusword_reportsTheStateToTheMaster();
    void fault_reactsThenWaitsForARisingFaultResetEdge();
    void faultResetBitOutsideFault_isNoCommand();
    void initialise_onlyLeavesNotReadyToSwitchOn();
    void powerApplied_inOperationEnabledAndQuickStopOnly();
};

void TestCia402Drive::transitions_followTheCiA402StateMachine_data()
{
    QTest::addColumn<State>("from");
    QTest::addColumn<quint16>("controlword");
    QTest::addColumn<State>("to");
    QTest::newRow("2 shutdown") << State::SwitchOnDisabled << quint16(0x06)
                                << State::ReadyToSwitchOn;
    QTest::newRow("3 switch on") << State::ReadyToSwitchOn << quint16(0x07) << State::SwitchedOn;
    QTest::newRow("3+4 switch on and enable")
        << State::ReadyToSwitchOn << quint16(0x0F) << State::OperationEnabled;
    QTest::newRow("4 enable operation")
        << State::SwitchedOn << quint16(0x0F) << State::OperationEnabled;
    QTest::newRow("5 disable operation")
        << State::OperationEnabled << quint16(0x07) << State::SwitchedOn;
    QTest::newRow("6 shutdown") << State::SwitchedOn << quint16(0x06) << State::ReadyToSwitchOn;
    QTest::newRow("7 disable voltage")
        << State::ReadyToSwitchOn << quint16(0x00) << State::SwitchOnDisabled;
    QTest::newRow("7 quick stop") << State::ReadyToSwitchOn << quint16(0x02)
                                  << State::SwitchOnDisabled;
    QTest::newRow("8 shutdown") << State::OperationEnabled << quint16(0x06)
                                << State::ReadyToSwitchOn;
    QTest::newRow("9 disable voltage")
        << State::OperationEnabled << quint16(0x00) << State::SwitchOnDisabled;
    QTest::newRow("10 disable voltage")
        << State::SwitchedOn << quint16(0x00) << State::SwitchOnDisabled;
    QTest::newRow("10 quick stop") << State::SwitchedOn << quint16(0x02) << State::SwitchOnDisabled;
    QTest::newRow("11 quick stop")
        << State::OperationEnabled << quint16(0x02) << State::QuickStopActive;
    QTest::newRow("12 disable voltage")
        << State::QuickStopActive << quint16(0x00) << State::SwitchOnDisabled;
    QTest::newRow("16 enable operation")
        << State::QuickStopActive << quint16(0x0F) << State::OperationEnabled;
    QTest::newRow("no skipping: enable from disabled")
        << State::SwitchOnDisabled << quint16(0x0F) << State::SwitchOnDisabled;
    QTest::newRow("quick stop active ignores shutdown")
        << State::QuickStopActive << quint16(0x06) << State::QuickStopActive;
    QTest::newRow("not ready ignores commands")
        << State::NotReadyToSwitchOn << quint16(0x06) << State::NotReadyToSwitchOn;
    QTest::newRow("fault reaction ignores commands")
        << State::FaultReactionActive << quint16(0x80) << State::FaultReactionActive;
}

void TestCia402Drive::transitions_followTheCiA402StateMachine()
{
    QFETCH(State, from);
    QFETCH(quint16, controlword);
    QFETCH(State, to);
    Cia402Drive d = driveIn(from);
    QCOMPARE(d.state(), from);
    QCOMPARE(d.applyControlword(controlword), to);
    QCOMPARE(d.state(), to);
}

void TestCia402Drive::statusword_reportsTheStateToTheMaster()
{
    for (const State s : {State::NotReadyToSwitchOn, State::SwitchOnDisabled,
                          State::ReadyToSwitchOn, State::SwitchedOn, State::OperationEnabled,
                          State::QuickStopActive, State::FaultReactionActive, State::Fault}) {
        const Cia402Drive d = driveIn(s);
        QCOMPARE(cia402::stateFromStatusword(d.statusword()), s);
        QVERIFY(d.statusword() & cia402::statusRemote);
    }
    QCOMPARE(driveIn(State::OperationEnabled).statusword(), quint16(0x0237));
    QCOMPARE(driveIn(State::SwitchOnDisabled).statusword(), quint16(0x0240));
}

void TestCia402Drive::fault_reactsThenWaitsForARisingFaultResetEdge()
{
    Cia402Drive d = driveIn(State::OperationEnabled);
    d.applyControlword(0x8F); // bit 7 already high when the fault comes
    d.raiseFault();
    QCOMPARE(d.state(), State::FaultReactionActive);
    d.completeFaultReaction();
    QCOMPARE(d.state(), State::Fault);
    QCOMPARE(d.applyControlword(0x80), State::Fault);            // no edge: bit 7 stayed high
    QCOMPARE(d.applyControlword(0x0F), State::Fault);            // ordinary commands do nothing
    QCOMPARE(d.applyControlword(0x80), State::SwitchOnDisabled); // rising edge: 15
}

void TestCia402Drive::faultResetBitOutsideFault_isNoCommand()
{
    Cia402Drive d = driveIn(State::SwitchOnDisabled);
    QCOMPARE(d.applyControlword(0x86), State::SwitchOnDisabled);
    QCOMPARE(d.applyControlword(0x06), State::ReadyToSwitchOn);
}

void TestCia402Drive::initialise_onlyLeavesNotReadyToSwitchOn()
{
    Cia402Drive d;
    QCOMPARE(d.state(), State::NotReadyToSwitchOn);
    d.initialise();
    QCOMPARE(d.state(), State::SwitchOnDisabled);
    d.applyControlword(0x06);
    d.initialise();
    QCOMPARE(d.state(), State::ReadyToSwitchOn);
}

void TestCia402Drive::powerApplied_inOperationEnabledAndQuickStopOnly()
{
    QVERIFY(driveIn(State::OperationEnabled).powerApplied());
    QVERIFY(driveIn(State::QuickStopActive).powerApplied());
    QVERIFY(!driveIn(State::SwitchedOn).powerApplied());
    QVERIFY(!driveIn(State::Fault).powerApplied());
}

QTEST_GUILESS_MAIN(TestCia402Drive)
#include "tst_cia402drive.moc"
