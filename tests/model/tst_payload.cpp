// A payload fixed to a link: its regressor is that link's 10 columns and the arm's torque the
// fixed model's. Checked against the URDF reader merging a payload link fixed to the KUKA LWR4+'s
// flange (urdfdom, the fixed joint's and the inertial's poses), whose expected parameters the
// test computes itself by the parallel axis theorem.

#include "../support/ErrorOf.h"
#include "../support/NumericAssert.h"
#include "../support/RandomStates.h"
#include "../support/SharedData.h"
#include "model/Payload.h"
#include "model/UrdfChain.h"

#include <QFile>
#include <QTest>

using namespace learnid;

namespace {

// The payload as a URDF link fixed to the flange: a 3 kg body, its inertial frame turned and
// moved, its inertia not diagonal.
const QByteArray payloadLinks = R"(
  <joint name="tool_mount" type="fixed"><parent link="lwr_7_link"/><child link="tool"/>
    <origin xyz="0.05 0.01 0.02" rpy="0.3 -0.2 0.5"/></joint>
  <link name="tool"><inertial><origin xyz="0.01 -0.02 0.03" rpy="0.1 0.2 -0.3"/>
    <mass value="3"/>
    <inertia ixx="0.012" ixy="0.001" ixz="-0.002" iyy="0.015" iyz="0.0005" izz="0.009"/>
  </inertial></link>
</robot>)";

Eigen::Matrix3d rpy(double r, double p, double y)
{
    return (Eigen::AngleAxisd(y, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(p, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(r, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

// The payload's 10 parameters in the flange frame, by hand: the centre of mass placed through
// both poses, the inertia turned into the flange's axes, then moved to its origin.
InertialParameters expectedPayload()
{
    const Eigen::Matrix3d mount = rpy(0.3, -0.2, 0.5);
    const Eigen::Matrix3d local = mount * rpy(0.1, 0.2, -0.3);
    const Eigen::Vector3d c =
        Eigen::Vector3d(0.05, 0.01, 0.02) + mount * Eigen::Vector3d(0.01, -0.02, 0.03);
    Eigen::Matrix3d ic;
    ic << 0.012, 0.001, -0.002, 0.001, 0.015, 0.0005, -0.002, 0.0005, 0.009;
    const double m = 3.0;
    const Eigen::Matrix3d io =
        local * ic * local.transpose() +
        m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    InertialParameters pi;
    pi << m, m * c.x(), m * c.y(), m * c.z(), io(0, 0), io(0, 1), io(1, 1), io(0, 2), io(1, 2),
        io(2, 2);
    return pi;
}

QByteArray kukaUrdf()
{
    QFile file(test::sharedDataFile(QStringLiteral("kuka-lwr4/kuka_lwr4.urdf")));
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

JointTerms friction()
{
    return JointTerms{false, true, true, true};
}

} // namespace

class TestPayload : public QObject
{
    Q_OBJECT

private slots:
    void body_roundTripsThroughItsTenParameters();
    void payloadRegressor_matchesTheUrdfWithThePayloadMerged();
    void namedLink_takesThatLinksColumns();
    void fixedLink_payloadInItsFrameEqualsTheUrdfWithThePayloadOnIt();
    void badInput_namesTheLinkAndTheMass();
};

void TestPayload::body_roundTripsThroughItsTenParameters()
{
    PayloadBody body;
    body.mass = 3.0;
    body.com = Eigen::Vector3d(0.05, -0.01, 0.08);
    body.inertiaAtCom << 0.02, 0.001, 0.0, 0.001, 0.03, -0.002, 0.0, -0.002, 0.01;
    const InertialParameters pi = body.parameters();
    // m c and the parallel axis theorem, one entry by hand: Ixx = Ic_xx + m (cy^2 + cz^2).
    LEARNID_COMPARE_NEAR(pi[1], 0.15, 1e-15);
    LEARNID_COMPARE_NEAR(pi[4], 0.02 + 3.0 * (0.0001 + 0.0064), 1e-15);
    LEARNID_COMPARE_NEAR(pi[5], 0.001 - 3.0 * 0.05 * -0.01, 1e-15);
    const PayloadBody back = payloadBody(pi);
    LEARNID_COMPARE_NEAR(back.mass, 3.0, 1e-15);
    LEARNID_COMPARE_MATRIX(back.com, body.com, 1e-15);
    LEARNID_COMPARE_MATRIX(back.inertiaAtCom, body.inertiaAtCom, 1e-15);
}

void TestPayload::payloadRegressor_matchesTheUrdfWithThePayloadMerged()
{
    const QByteArray arm = kukaUrdf();
    if (arm.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    QByteArray loaded = arm;
    loaded.replace("</robot>", payloadLinks);
    const auto armModel = std::make_shared<const ChainModel>(
        parseUrdfChain(arm, QStringLiteral("lwr4")), friction(), QStringLiteral("lwr4"));
    const ChainModel loadedModel(
        parseUrdfChain(loaded, QStringLiteral("lwr4 with tool"), {}, QStringLiteral("lwr_7_link")),
        friction(), QStringLiteral("lwr4"));
    const PayloadModel payload(armModel, armModel->cadStandard());
    QCOMPARE(payload.link(), QStringLiteral("lwr_7_link"));
    QCOMPARE(payload.joint(), 6);
    const InertialParameters expected = expectedPayload();
    LEARNID_COMPARE_MATRIX(payload.standardWith(expected), loadedModel.cadStandard(), 1e-13);

    Eigen::MatrixXd y(7, loadedModel.standardCount());
    test::forRandomStates(7, 25, 20, [&](const auto &q, const auto &qd, const auto &qdd) {
        loadedModel.standardRegressor(q, qd, qdd, y);
        const Eigen::VectorXd tau = y * loadedModel.cadStandard();
        LEARNID_COMPARE_MATRIX(payload.torqueAt(q, qd, qdd, expected), tau, 1e-10);
        LEARNID_COMPARE_MATRIX(payload.armTorqueAt(q, qd, qdd) +
                                   payload.regressorAt(q, qd, qdd) * expected,
                               tau, 1e-10);
    });
}

void TestPayload::namedLink_takesThatLinksColumns()
{
    const QByteArray arm = kukaUrdf();
    if (arm.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const auto armModel = std::make_shared<const ChainModel>(
        parseUrdfChain(arm, QStringLiteral("lwr4")), friction(), QStringLiteral("lwr4"));
    const PayloadModel payload(armModel, armModel->cadStandard(), QStringLiteral("lwr_5_link"));
    QCOMPARE(payload.joint(), 4);
    const Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(7, -0.6, 0.9);
    const Eigen::VectorXd qd = Eigen::VectorXd::LinSpaced(7, 0.4, -0.5);
    const Eigen::VectorXd qdd = Eigen::VectorXd::LinSpaced(7, 1.0, 2.0);
    Eigen::MatrixXd full(7, armModel->standardCount());
    armModel->standardRegressor(q, qd, qdd, full);
    LEARNID_COMPARE_MATRIX(payload.regressorAt(q, qd, qdd), full.middleCols(40, 10), 0.0);
}

void TestPayload::fixedLink_payloadInItsFrameEqualsTheUrdfWithThePayloadOnIt()
{
    QByteArray arm = kukaUrdf();
    if (arm.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    QByteArray loaded = arm;
    loaded.replace("</robot>", payloadLinks);
    // The arm with the tool frame alone: the same mount, a link without mass.
    QByteArray flange = payloadLinks;
    flange.replace(flange.indexOf("<inertial>"),
                   flange.indexOf("</inertial>") + 11 - flange.indexOf("<inertial>"), "");
    arm.replace("</robot>", flange);
    const auto armModel = std::make_shared<const ChainModel>(
        parseUrdfChain(arm, QStringLiteral("lwr4 with flange"), {}, QStringLiteral("lwr_7_link")),
        friction(), QStringLiteral("lwr4"));
    const ChainModel loadedModel(
        parseUrdfChain(loaded, QStringLiteral("lwr4 with tool"), {}, QStringLiteral("lwr_7_link")),
        friction(), QStringLiteral("lwr4"));
    const PayloadModel payload(armModel, armModel->cadStandard(), QStringLiteral("tool"));
    QCOMPARE(payload.link(), QStringLiteral("tool"));
    QCOMPARE(payload.joint(), 6);
    // The payload in the tool's own frame, by hand: only its inertial pose.
    const Eigen::Matrix3d local = rpy(0.1, 0.2, -0.3);
    const Eigen::Vector3d c(0.01, -0.02, 0.03);
    Eigen::Matrix3d ic;
    ic << 0.012, 0.001, -0.002, 0.001, 0.015, 0.0005, -0.002, 0.0005, 0.009;
    const InertialParameters inTool = inertialParameters(3.0, c, local * ic * local.transpose());
    LEARNID_COMPARE_MATRIX(payloadInBody(payload.payloadLink(), inTool), expectedPayload(), 1e-15);
    LEARNID_COMPARE_MATRIX(payload.standardWith(inTool), loadedModel.cadStandard(), 1e-13);
    LEARNID_COMPARE_MATRIX(
        payloadBaseShift(*armModel, QStringLiteral("tool"), inTool),
        armModel->baseFromStandard(loadedModel.cadStandard() - armModel->cadStandard()), 1e-13);
    Eigen::MatrixXd y(7, loadedModel.standardCount());
    test::forRandomStates(7, 27, 10, [&](const auto &q, const auto &qd, const auto &qdd) {
        loadedModel.standardRegressor(q, qd, qdd, y);
        LEARNID_COMPARE_MATRIX(payload.armTorqueAt(q, qd, qdd) +
                                   payload.regressorAt(q, qd, qdd) * inTool,
                               y * loadedModel.cadStandard(), 1e-10);
    });
}

void TestPayload::badInput_namesTheLinkAndTheMass()
{
    const QByteArray arm = kukaUrdf();
    if (arm.isEmpty())
        QSKIP(qPrintable(test::sharedDataMissing()));
    const auto armModel = std::make_shared<const ChainModel>(
        parseUrdfChain(arm, QStringLiteral("lwr4")), friction(), QStringLiteral("lwr4"));
    const QString unknown = test::errorOf(
        [&] { PayloadModel(armModel, armModel->cadStandard(), QStringLiteral("gripper")); });
    QVERIFY2(unknown.contains(QStringLiteral("'gripper'")) &&
                 unknown.contains(QStringLiteral("lwr_7_link")),
             qPrintable(unknown));
    InertialParameters pi = InertialParameters::Zero();
    pi[0] = -1.0;
    const QString mass = test::errorOf([&] { payloadBody(pi); });
    QVERIFY2(mass.contains(QStringLiteral("mass")), qPrintable(mass));
    pi[0] = NAN;
    QVERIFY(test::errorOf([&] { payloadBody(pi); }).contains(QStringLiteral("not finite")));
    const QString size = test::errorOf([&] { PayloadModel(armModel, Eigen::VectorXd::Zero(3)); });
    QVERIFY2(size.contains(QStringLiteral("91")), qPrintable(size));
}

QTEST_GUILESS_MAIN(TestPayload)
#include "tst_payload.moc"
