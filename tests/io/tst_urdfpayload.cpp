// The URDF with a payload link: urdfdom reads the fixed joint and the payload's inertial as
// written, and the model read back from the text gives the torques of the arm's model plus the
// payload (PayloadModel) at random states; names never clash, bad input names the link.

#include "../support/ErrorOf.h"
#include "../support/NumericAssert.h"
#include "../support/RandomStates.h"
#include "../support/SharedData.h"
#include "io/UrdfPayload.h"
#include "model/Payload.h"
#include "model/UrdfChain.h"

#include <QFile>
#include <QTest>
#include <random>
#include <urdf_parser/urdf_parser.h>

using namespace learnid;
using learnid::test::errorOf;

namespace {

PayloadBody tool()
{
    PayloadBody b;
    b.mass = 3.0;
    b.com = Eigen::Vector3d(0.05, -0.01, 0.08);
    b.inertiaAtCom << 0.012, 0.001, -0.002, 0.001, 0.015, 0.0005, -0.002, 0.0005, 0.009;
    return b;
}

QByteArray fileText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

JointTerms friction()
{
    return JointTerms{false, true, true, true};
}

} // namespace

class TestUrdfPayload : public QObject
{
    Q_OBJECT

private slots:
    void urdfdom_readsThePayloadLinkAsWritten();
    void readBack_givesTheArmPlusPayloadTorques();
    void namedLink_withALeafBelow_keepsTheOtherLinks();
    void fixedFlangeLink_carriesThePayloadInItsFrame();
    void takenNames_getASuffix();
    void badInput_namesTheLink();
};

void TestUrdfPayload::urdfdom_readsThePayloadLinkAsWritten()
{
    const QString path = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (path.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const QByteArray arm = fileText(path);
    const SerialChain chain = parseUrdfChain(arm, path);
    const PayloadBody body = tool();
    const QByteArray out = urdfWithPayload(arm, path, chain, {}, body.parameters(),
                                           QStringLiteral("payload identified -- by a test"));
    QVERIFY(out.startsWith(arm.left(arm.lastIndexOf("</robot>")))); // the arm's text kept
    QVERIFY(out.contains("<!-- payload identified - - by a test -->"));
    const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(out.toStdString());
    QVERIFY(model);
    const urdf::LinkConstSharedPtr payload = model->getLink("payload");
    QVERIFY(payload && payload->inertial);
    QCOMPARE(QString::fromStdString(payload->parent_joint->name), QStringLiteral("payload_joint"));
    QCOMPARE(payload->parent_joint->type, urdf::Joint::FIXED);
    QCOMPARE(QString::fromStdString(payload->getParent()->name), QStringLiteral("lwr_7_link"));
    const urdf::Pose &mount = payload->parent_joint->parent_to_joint_origin_transform;
    QCOMPARE(mount.position.x * mount.position.x + mount.position.y * mount.position.y +
                 mount.position.z * mount.position.z,
             0.0);
    const urdf::Inertial &i = *payload->inertial;
    QCOMPARE(i.mass, body.mass); // shortest round-trip text: the same doubles
    QCOMPARE(i.origin.position.x, body.com.x());
    QCOMPARE(i.origin.position.y, body.com.y());
    QCOMPARE(i.origin.position.z, body.com.z());
    QCOMPARE(i.ixx, body.inertiaAtCom(0, 0));
    QCOMPARE(i.ixy, body.inertiaAtCom(0, 1));
    QCOMPARE(i.ixz, body.inertiaAtCom(0, 2));
    QCOMPARE(i.iyy, body.inertiaAtCom(1, 1));
    QCOMPARE(i.iyz, body.inertiaAtCom(1, 2));
    QCOMPARE(i.izz, body.inertiaAtCom(2, 2));
}

void TestUrdfPayload::readBack_givesTheArmPlusPayloadTorques()
{
    const QString path = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (path.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const QByteArray arm = fileText(path);
    const auto armModel = std::make_shared<const ChainModel>(parseUrdfChain(arm, path), friction(),
                                                             QStringLiteral("lwr4"));
    const InertialParameters pi = tool().parameters();
    const QByteArray out = urdfWithPayload(arm, path, armModel->chain(), {}, pi, {});
    // Read back as `--robot` reads a URDF: the default base and tip.
    const ChainModel loaded(parseUrdfChain(out, QStringLiteral("with payload")), friction(),
                            QStringLiteral("lwr4"));
    const PayloadModel payload(armModel, armModel->cadStandard());
    Eigen::MatrixXd y(7, loaded.standardCount());
    test::forRandomStates(7, 25, 20, [&](const auto &q, const auto &qd, const auto &qdd) {
        loaded.standardRegressor(q, qd, qdd, y);
        LEARNID_COMPARE_MATRIX(y * loaded.cadStandard(), payload.torqueAt(q, qd, qdd, pi), 1e-10);
    });
}

void TestUrdfPayload::fixedFlangeLink_carriesThePayloadInItsFrame()
{
    const QString path = test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf"));
    if (path.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    // A massless tool frame fixed to the flange, turned and moved.
    QByteArray arm = fileText(path);
    arm.replace("</robot>", R"(<joint name="tool0_joint" type="fixed"><parent link="lwr_7_link"/>
        <child link="tool0"/><origin xyz="0.02 -0.01 0.1" rpy="0.4 -0.3 1.2"/></joint>
      <link name="tool0"/></robot>)");
    const auto armModel = std::make_shared<const ChainModel>(
        parseUrdfChain(arm, path, {}, QStringLiteral("lwr_7_link")), friction(),
        QStringLiteral("lwr4"));
    const InertialParameters pi = tool().parameters(); // in tool0's frame
    const QByteArray out =
        urdfWithPayload(arm, path, armModel->chain(), QStringLiteral("tool0"), pi, {});
    QVERIFY(out.contains("<parent link=\"tool0\"/>"));
    const ChainModel loaded(
        parseUrdfChain(out, QStringLiteral("with payload"), {}, QStringLiteral("lwr_7_link")),
        friction(), QStringLiteral("lwr4"));
    const PayloadModel payload(armModel, armModel->cadStandard(), QStringLiteral("tool0"));
    Eigen::MatrixXd y(7, loaded.standardCount());
    test::forRandomStates(7, 26, 20, [&](const auto &q, const auto &qd, const auto &qdd) {
        loaded.standardRegressor(q, qd, qdd, y);
        LEARNID_COMPARE_MATRIX(y * loaded.cadStandard(), payload.torqueAt(q, qd, qdd, pi), 1e-10);
    });
}

void TestUrdfPayload::namedLink_withALeafBelow_keepsTheOtherLinks()
{
    // The double pendulum: a tool fixed below link2; the payload goes on link1, mid-chain.
    const QString path = QStringLiteral(":/robots/double-pendulum.urdf");
    const QByteArray arm = fileText(path);
    QVERIFY(!arm.isEmpty());
    const SerialChain chain = parseUrdfChain(arm, path);
    const InertialParameters pi = tool().parameters();
    const QByteArray out = urdfWithPayload(arm, path, chain, QStringLiteral("link1"), pi, {});
    const SerialChain back = parseUrdfChain(out, path, chain.baseLink, chain.tipLink);
    LEARNID_COMPARE_MATRIX(back.joints[0].inertial, chain.joints[0].inertial + pi, 1e-12);
    LEARNID_COMPARE_MATRIX(back.joints[1].inertial, chain.joints[1].inertial, 0.0);
}

void TestUrdfPayload::takenNames_getASuffix()
{
    const QString path = QStringLiteral(":/robots/double-pendulum.urdf");
    QByteArray arm = fileText(path);
    arm.replace("</robot>", R"(<joint name="payload_joint" type="fixed"><parent link="link2"/>
      <child link="payload"/></joint><link name="payload"/></robot>)");
    const SerialChain chain = parseUrdfChain(arm, path, {}, QStringLiteral("tool"));
    const QByteArray out =
        urdfWithPayload(arm, path, chain, QStringLiteral("link2"), tool().parameters(), {});
    QVERIFY(out.contains(R"(<link name="payload_2">)"));
    QVERIFY(out.contains(R"(<joint name="payload_joint_2" type="fixed">)"));
}

void TestUrdfPayload::badInput_namesTheLink()
{
    const QString path = QStringLiteral(":/robots/double-pendulum.urdf");
    const QByteArray arm = fileText(path);
    const SerialChain chain = parseUrdfChain(arm, path);
    const QString unknown = errorOf([&] {
        urdfWithPayload(arm, path, chain, QStringLiteral("gripper"), tool().parameters(), {});
    });
    QVERIFY2(unknown.contains(QStringLiteral("'gripper'")), qPrintable(unknown));
    InertialParameters notABody = tool().parameters();
    notABody[4] = -1.0; // Ixx < 0
    const QString body = errorOf([&] { urdfWithPayload(arm, path, chain, {}, notABody, {}); });
    QVERIFY2(body.contains(QStringLiteral("\"link2\"")) &&
                 body.contains(QStringLiteral("not a real body")),
             qPrintable(body));
}

QTEST_GUILESS_MAIN(TestUrdfPayload)
#include "tst_urdfpayload.moc"
