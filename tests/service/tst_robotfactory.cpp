// The one robot factory: each kind of request makes its robot, or says why not.
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "service/RobotFactory.h"
#include "service/SessionExport.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace learnid;

class TestRobotFactory : public QObject
{
    Q_OBJECT

private slots:
    void simulated_isTheScenariosRobot();
    void can_unreachableBus_saysSoWithoutThrowing();
    void replay_unreadableLog_namesFileAndLine();
    void dcfPath_isBesideTheParameterFile();
};

void TestRobotFactory::simulated_isTheScenariosRobot()
{
    const Scenario scenario;
    const RobotConnection c =
        makeRobot({}, scenario, makeRobotModel(scenario.model, scenario.urdf));
    QVERIFY(c.robot && c.simulated);
    QCOMPARE(c.robot.get(), static_cast<Robot *>(c.simulated.get()));
    QVERIFY(c.connectError.isEmpty());
    QCOMPARE(c.robot->trueParameters().value(), scenario.simulation.trueParameters);
}

void TestRobotFactory::can_unreachableBus_saysSoWithoutThrowing()
{
    const Scenario scenario;
    RobotRequest request;
    request.kind = RobotRequest::Kind::Can;
    request.can.plugin = QStringLiteral("nosuchplugin");
    request.can.interface = QStringLiteral("can0");
    const RobotConnection c =
        makeRobot(request, scenario, makeRobotModel(scenario.model, scenario.urdf));
    QVERIFY(!c.robot && !c.simulated);
    QVERIFY2(c.connectError.contains(QLatin1String("nosuchplugin")), qPrintable(c.connectError));
}

void TestRobotFactory::replay_unreadableLog_namesFileAndLine()
{
    QTemporaryDir dir;
    const QString log = dir.filePath(QStringLiteral("trial-000.log"));
    QFile f(log);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("(1.000000) can0 080#01\nnot a frame\n");
    f.close();
    const Scenario scenario;
    RobotRequest request;
    request.kind = RobotRequest::Kind::Replay;
    request.candumpFiles = {log};
    try {
        makeRobot(request, scenario, makeRobotModel(scenario.model, scenario.urdf));
        QFAIL("no error");
    } catch (const Error &e) {
        QVERIFY2(e.message().startsWith(log + QStringLiteral(":2: ")), qPrintable(e.message()));
    }
}

void TestRobotFactory::dcfPath_isBesideTheParameterFile()
{
    QCOMPARE(dcfPathFor(QStringLiteral("/tmp/out/params.json")),
             QStringLiteral("/tmp/out/params.dcf"));
    QCOMPARE(dcfPathFor(QStringLiteral("/tmp/out/robot.v2.json")),
             QStringLiteral("/tmp/out/robot.v2.dcf"));
}

QTEST_GUILESS_MAIN(TestRobotFactory)
#include "tst_robotfactory.moc"
