#include "CanTestBus.h"
#include "can/Nmt.h"

#include <QSignalSpy>
#include <QTest>

using namespace learnid;

Q_DECLARE_METATYPE(learnid::NmtCommand)

class TestNmt : public QObject
{
    Q_OBJECT

private slots:
    void commandFrames_carryCommandAndNode_data();
    void commandFrames_carryCommandAndNode();
    void master_sendsCommandsOnTheBus();
    void slave_acceptsCommandsForItselfOrForAll();
    void slave_ignoresOtherFrames();
    void stateAfterCommand_followsTheNmtStateMachine();
    void heartbeatByte_decodesStatesIgnoringToggleBit();
    void stateNames_areReadable();
};

void TestNmt::commandFrames_carryCommandAndNode_data()
{
    QTest::addColumn<NmtCommand>("command");
    QTest::addColumn<QByteArray>("payload");
    QTest::newRow("start") << NmtCommand::Start << QByteArray::fromHex("0105");
    QTest::newRow("stop") << NmtCommand::Stop << QByteArray::fromHex("0205");
    QTest::newRow("pre-operational")
        << NmtCommand::EnterPreOperational << QByteArray::fromHex("8005");
    QTest::newRow("reset node") << NmtCommand::ResetNode << QByteArray::fromHex("8105");
    QTest::newRow("reset communication")
        << NmtCommand::ResetCommunication << QByteArray::fromHex("8205");
}

void TestNmt::commandFrames_carryCommandAndNode()
{
    QFETCH(NmtCommand, command);
    QFETCH(QByteArray, payload);
    const QCanBusFrame f = nmtCommandFrame(command, 5);
    QCOMPARE(f.frameId(), 0u);
    QCOMPARE(f.payload(), payload);
    QCOMPARE(nmtCommandFor(f, 5), std::optional<NmtCommand>(command));
}

void TestNmt::master_sendsCommandsOnTheBus()
{
    test::CanTestBus net;
    Nmt nmt(&net.masterLink);
    QVERIFY(nmt.startNode(0));
    QVERIFY(nmt.stopNode(2));
    QVERIFY(nmt.enterPreOperational(3));
    QVERIFY(nmt.resetNode(4));
    QVERIFY(nmt.resetCommunication(5));
    QTRY_COMPARE_WITH_TIMEOUT(net.wire.size(), 5, 1000);
    QCOMPARE(net.wire[0].payload(), QByteArray::fromHex("0100"));
    QCOMPARE(net.wire[1].payload(), QByteArray::fromHex("0202"));
    QCOMPARE(net.wire[2].payload(), QByteArray::fromHex("8003"));
    QCOMPARE(net.wire[3].payload(), QByteArray::fromHex("8104"));
    QCOMPARE(net.wire[4].payload(), QByteArray::fromHex("8205"));
    net.master->disconnectDevice();
    QVERIFY(!nmt.startNode(1));
}

void TestNmt::slave_acceptsCommandsForItselfOrForAll()
{
    QCOMPARE(nmtCommandFor(nmtCommandFrame(NmtCommand::Start, 0), 7),
             std::optional<NmtCommand>(NmtCommand::Start));
    QCOMPARE(nmtCommandFor(nmtCommandFrame(NmtCommand::Start, 7), 7),
             std::optional<NmtCommand>(NmtCommand::Start));
    QCOMPARE(nmtCommandFor(nmtCommandFrame(NmtCommand::Start, 8), 7), std::nullopt);
}

void TestNmt::slave_ignoresOtherFrames()
{
    QCOMPARE(nmtCommandFor(QCanBusFrame(0x000, QByteArray::fromHex("01")), 1), std::nullopt);
    QCOMPARE(nmtCommandFor(QCanBusFrame(0x000, QByteArray::fromHex("0301")), 1), std::nullopt);
    QCOMPARE(nmtCommandFor(QCanBusFrame(0x701, QByteArray::fromHex("0101")), 1), std::nullopt);
}

void TestNmt::stateAfterCommand_followsTheNmtStateMachine()
{
    QCOMPARE(nmtStateAfter(NmtCommand::Start, NmtState::PreOperational), NmtState::Operational);
    QCOMPARE(nmtStateAfter(NmtCommand::Stop, NmtState::Operational), NmtState::Stopped);
    QCOMPARE(nmtStateAfter(NmtCommand::EnterPreOperational, NmtState::Stopped),
             NmtState::PreOperational);
    QCOMPARE(nmtStateAfter(NmtCommand::ResetNode, NmtState::Operational), NmtState::BootUp);
    QCOMPARE(nmtStateAfter(NmtCommand::ResetCommunication, NmtState::Stopped), NmtState::BootUp);
}

void TestNmt::heartbeatByte_decodesStatesIgnoringToggleBit()
{
    QCOMPARE(nmtStateFromByte(0x00), std::optional<NmtState>(NmtState::BootUp));
    QCOMPARE(nmtStateFromByte(0x04), std::optional<NmtState>(NmtState::Stopped));
    QCOMPARE(nmtStateFromByte(0x05), std::optional<NmtState>(NmtState::Operational));
    QCOMPARE(nmtStateFromByte(0x85), std::optional<NmtState>(NmtState::Operational));
    QCOMPARE(nmtStateFromByte(0x7F), std::optional<NmtState>(NmtState::PreOperational));
    QCOMPARE(nmtStateFromByte(0x06), std::nullopt);
}

void TestNmt::stateNames_areReadable()
{
    QCOMPARE(nmtStateName(NmtState::PreOperational), QString("pre-operational"));
    QCOMPARE(nmtStateName(NmtState::Operational), QString("operational"));
}

QTEST_GUILESS_MAIN(TestNmt)
#include "tst_nmt.moc"
