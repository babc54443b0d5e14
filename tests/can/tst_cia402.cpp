#include "can/Cia402.h"
#include "can/Cia402Drive.h"

#include <QTest>

using namespace learnid;
using namespace learnid::cia402;

Q_DECLARE_METATYPE(learnid::cia402::Command)

class TestCia402 : public QObject
{
    Q_OBJECT

private slots:
    void statusword_decodesEveryState_data();
    void statusword_decodesEveryState();
    void controlwords_matchCiA402_data();
    void controlwords_matchCiA402();
    void controlword_decodesToItsCommand_data();
    void controlword_decodesToItsCommand();
    void walkTowardsOperationEnabled_reachesItFromEveryStableState_data();
    void walkTowardsOperationEnabled_reachesItFromEveryStableState();
    void walkTowardsOperationEnabled_waitsInTransientStates();
    void walkTowardsDisabled_removesPower();
    void stateNames_areTheCiA402Names();
};

void TestCia402::statusword_decodesEveryState_data()
{
    QTest::addColumn<quint16>("statusword");
    QTest::addColumn<State>("state");
    QTest::newRow("not ready") << quint16(0x0000) << State::NotReadyToSwitchOn;
    QTest::newRow("not ready, other bits") << quint16(0xFFB0) << State::NotReadyToSwitchOn;
    QTest::newRow("switch on disabled") << quint16(0x0040) << State::SwitchOnDisabled;
    QTest::newRow("switch on disabled, remote") << quint16(0x0250) << State::SwitchOnDisabled;
    QTest::newRow("ready") << quint16(0x0021) << State::ReadyToSwitchOn;
    QTest::newRow("ready, voltage") << quint16(0x0231) << State::ReadyToSwitchOn;
    QTest::newRow("switched on") << quint16(0x0233) << State::SwitchedOn;
    QTest::newRow("operation enabled") << quint16(0x0237) << State::OperationEnabled;
    QTest::newRow("operation enabled, target reached")
        << quint16(0x1637) << State::OperationEnabled;
    QTest::newRow("quick stop active") << quint16(0x0217) << State::QuickStopActive;
    QTest::newRow("fault reaction active") << quint16(0x021F) << State::FaultReactionActive;
    QTest::newRow("fault") << quint16(0x0208) << State::Fault;
    QTest::newRow("fault, warning") << quint16(0x02A8) << State::Fault;
    QTest::newRow("nonsense x1x1 0001") << quint16(0x0061) << State::Unknown;
    QTest::newRow("nonsense 0010") << quint16(0x0002) << State::Unknown;
}

void TestCia402::statusword_decodesEveryState()
{
    QFETCH(quint16, statusword);
    QFETCH(State, state);
    QCOMPARE(stateFromStatusword(statusword), state);
}

void TestCia402::controlwords_matchCiA402_data()
{
    QTest::addColumn<Command>("command");
    QTest::addColumn<quint16>("controlword");
    QTest::newRow("shutdown") << Command::Shutdown << quint16(0x06);
    QTest::newRow("switch on") << Command::SwitchOn << quint16(0x07);
    QTest::newRow("enable operation") << Command::EnableOperation << quint16(0x0F);
    QTest::newRow("disable voltage") << Command::DisableVoltage << quint16(0x00);
    QTest::newRow("quick stop") << Command::QuickStop << quint16(0x02);
    QTest::newRow("disable operation") << Command::DisableOperation << quint16(0x07);
    QTest::newRow("fault reset") << Command::FaultReset << quint16(0x80);
}

void TestCia402::controlwords_matchCiA402()
{
    QFETCH(Command, command);
    QFETCH(quint16, controlword);
    QCOMPARE(cia402::controlword(command), controlword);
}

void TestCia402::controlword_decodesToItsCommand_data()
{
    QTest::addColumn<quint16>("controlword");
    QTest::addColumn<Command>("command");
    QTest::newRow("0x00") << quint16(0x00) << Command::DisableVoltage;
    QTest::newRow("0x0D: voltage bit clear") << quint16(0x0D) << Command::DisableVoltage;
    QTest::newRow("0x02") << quint16(0x02) << Command::QuickStop;
    QTest::newRow("0x0B: quick stop bit clear") << quint16(0x0B) << Command::QuickStop;
    QTest::newRow("0x06") << quint16(0x06) << Command::Shutdown;
    QTest::newRow("0x0E: switch on bit clear") << quint16(0x0E) << Command::Shutdown;
    QTest::newRow("0x07") << quint16(0x07) << Command::SwitchOn;
    QTest::newRow("0x0F") << quint16(0x0F) << Command::EnableOperation;
    QTest::newRow("0x1F: mode bit set") << quint16(0x1F) << Command::EnableOperation;
}

void TestCia402::controlword_decodesToItsCommand()
{
    QFETCH(quint16, controlword);
    QFETCH(Command, command);
    QCOMPARE(commandFromControlword(controlword), command);
}

void TestCia402::walkTowardsOperationEnabled_reachesItFromEveryStableState_data()
{
    QTest::addColumn<QList<quint16>>("setup"); // controlwords that bring the drive there
    QTest::addColumn<bool>("fault");
    QTest::addColumn<int>("steps");
    QTest::newRow("switch on disabled") << QList<quint16>{} << false << 3;
    QTest::newRow("ready to switch on") << QList<quint16>{0x06} << false << 2;
    QTest::newRow("switched on") << QList<quint16>{0x06, 0x07} << false << 1;
    QTest::newRow("operation enabled") << QList<quint16>{0x06, 0x0F} << false << 0;
    QTest::newRow("quick stop active") << QList<quint16>{0x06, 0x0F, 0x02} << false << 4;
    QTest::newRow("fault") << QList<quint16>{0x06, 0x0F} << true << 4;
}

void TestCia402::walkTowardsOperationEnabled_reachesItFromEveryStableState()
{
    QFETCH(QList<quint16>, setup);
    QFETCH(bool, fault);
    QFETCH(int, steps);
    Cia402Drive drive;
    drive.initialise();
    for (const quint16 cw : setup)
        drive.applyControlword(cw);
    if (fault) {
        drive.raiseFault();
        drive.completeFaultReaction();
    }
    int taken = 0;
    // The master only sees the statusword.
    while (const auto command =
               nextCommandTowardsOperationEnabled(stateFromStatusword(drive.statusword()))) {
        drive.applyControlword(controlword(*command));
        QVERIFY(++taken <= 4);
    }
    QCOMPARE(drive.state(), State::OperationEnabled);
    QCOMPARE(taken, steps);
}

void TestCia402::walkTowardsOperationEnabled_waitsInTransientStates()
{
    QCOMPARE(nextCommandTowardsOperationEnabled(State::NotReadyToSwitchOn), std::nullopt);
    QCOMPARE(nextCommandTowardsOperationEnabled(State::FaultReactionActive), std::nullopt);
    QCOMPARE(nextCommandTowardsOperationEnabled(State::Unknown), std::nullopt);
    QCOMPARE(nextCommandTowardsOperationEnabled(State::OperationEnabled), std::nullopt);
}

void TestCia402::walkTowardsDisabled_removesPower()
{
    for (const State s : {State::ReadyToSwitchOn, State::SwitchedOn, State::OperationEnabled,
                          State::QuickStopActive})
        QCOMPARE(nextCommandTowardsDisabled(s), std::optional<Command>(Command::DisableVoltage));
    for (const State s : {State::SwitchOnDisabled, State::NotReadyToSwitchOn, State::Fault})
        QCOMPARE(nextCommandTowardsDisabled(s), std::nullopt);
}

void TestCia402::stateNames_areTheCiA402Names()
{
    QCOMPARE(stateName(State::SwitchOnDisabled), QString("Switch on disabled"));
    QCOMPARE(stateName(State::OperationEnabled), QString("Operation enabled"));
    QCOMPARE(stateName(State::FaultReactionActive), QString("Fault reaction active"));
}

QTEST_GUILESS_MAIN(TestCia402)
#include "tst_cia402.moc"
