// What a path shows of a payload on the KUKA LWR4+'s flange, before it runs.
//
// Turning only about a vertical wrist axis z (omega = w e_z, the flange's origin still, gravity
// g = -g0 e_z in the flange frame), the wrench the payload puts on the flange, about its origin, is
//   f = w' e_z x mc + w^2 e_z x (e_z x mc) + m g0 e_z        (m, m cx, m cy only)
//   n = w' I e_z + w^2 e_z x (I e_z) + mc x g0 e_z          (Ixz, Iyz, Izz, m cx, m cy)
// so m cz (the centre of mass along the wrist axis, which gravity pulls along) and Ixx, Ixy, Iyy
// never reach a joint torque: their regressor columns are zero, whatever the path's speed.
// A path that tilts and turns the wrist sees the mass and the whole centre of mass.

#include "../support/ErrorOf.h"
#include "PayloadPaths.h"
#include "identify/PayloadObservability.h"
#include "model/Payload.h"

#include <QTest>

using namespace learnid;

class TestPayloadObservability : public QObject
{
    Q_OBJECT

private slots:
    void wristTurningAboutVerticalAxis_cannotSeeComAlongItNorIxxIxyIyy();
    void pathTiltingTheWrist_seesMassAndCentreOfMass();
    void badRows_areRefused();
};

void TestPayloadObservability::wristTurningAboutVerticalAxis_cannotSeeComAlongItNorIxxIxyIyy()
{
    const auto arm = test::kukaArm();
    if (!arm)
        QSKIP(qPrintable(test::sharedDataMissing()));
    // The pose really holds the flange's z axis vertical.
    const auto poses = arm->dynamics().framePoses(test::holdWristVertical(*arm));
    QVERIFY(std::abs(poses.back().linear().col(2).z()) > 1.0 - 1e-12);

    const PayloadModel model(arm, arm->cadStandard());
    const test::JointPath path = test::wristTurnPath(*arm);
    // The equations above: those four columns vanish at every sample.
    double zeroColumns = 0.0, others = 0.0;
    for (Eigen::Index k = 0; k < path.q.cols(); k += 10) {
        const Eigen::MatrixXd y = model.regressorAt(path.q.col(k), path.qd.col(k), path.qdd.col(k));
        for (const int c : {3, 4, 5, 6})
            zeroColumns = std::max(zeroColumns, y.col(c).cwiseAbs().maxCoeff());
        others = std::max(others, y.cwiseAbs().maxCoeff());
    }
    QVERIFY2(zeroColumns < 1e-12 * others,
             qPrintable(QStringLiteral("%1 against %2").arg(zeroColumns).arg(others)));

    const PayloadObservability o = payloadPathObservability(model, path.q, path.qd, path.qdd);
    QCOMPARE(o.rank, 6);
    for (const int c : {3, 4, 5, 6})
        QVERIFY2(o.determined[size_t(c)] < 1e-6, qPrintable(QString::number(c)));
    for (const int c : {0, 1, 2, 7, 8, 9})
        QVERIFY2(o.determined[size_t(c)] > 0.99, qPrintable(QString::number(c)));
    QVERIFY(o.massIdentified());
    QVERIFY(!o.comIdentified());
    QVERIFY(!o.inertiaIdentified());
    // The unseen directions are exactly those parameters.
    QCOMPARE(o.unseen.cols(), 4);
    for (const int c : {0, 1, 2, 7, 8, 9})
        QVERIFY(o.unseen.row(c).norm() < 1e-6 * o.unseen.norm());
    const QStringList advice = o.advice(QStringLiteral("lwr_7_link"));
    QCOMPARE(advice.size(), 2);
    QVERIFY2(advice[0].contains(QStringLiteral("along the z axis of lwr_7_link")) &&
                 advice[0].contains(QStringLiteral("tilt the wrist")),
             qPrintable(advice[0]));
    QVERIFY2(advice[1].contains(QStringLiteral("Ixx, Ixy, Iyy")), qPrintable(advice[1]));
}

void TestPayloadObservability::pathTiltingTheWrist_seesMassAndCentreOfMass()
{
    const auto arm = test::kukaArm();
    if (!arm)
        QSKIP(qPrintable(test::sharedDataMissing()));
    const PayloadModel model(arm, arm->cadStandard());
    const test::JointPath path = test::richPath(*arm);
    const PayloadObservability o = payloadPathObservability(model, path.q, path.qd, path.qdd);
    for (int c = 0; c < 4; ++c)
        QVERIFY2(o.determined[size_t(c)] > 0.99,
                 qPrintable(QStringLiteral("%1: %2").arg(c).arg(o.determined[size_t(c)])));
    QVERIFY(o.massIdentified() && o.comIdentified());
    QVERIFY(o.advice(QStringLiteral("lwr_7_link")).filter(QStringLiteral("centre")).isEmpty());
    qInfo("rank %d, condition %.1f; inertia shares %.2f %.2f %.2f %.2f %.2f %.2f", o.rank,
          o.condition, o.determined[4], o.determined[5], o.determined[6], o.determined[7],
          o.determined[8], o.determined[9]);
}

void TestPayloadObservability::badRows_areRefused()
{
    QVERIFY(test::errorOf([] {
                payloadObservability(Eigen::MatrixXd::Zero(5, 9));
            }).contains(QStringLiteral("10 columns")));
    Eigen::MatrixXd rows = Eigen::MatrixXd::Identity(10, 10);
    rows(3, 3) = NAN;
    QVERIFY(
        test::errorOf([&] { payloadObservability(rows); }).contains(QStringLiteral("not finite")));
    QVERIFY(test::errorOf([] {
                payloadObservability(Eigen::MatrixXd::Identity(10, 10), 1.5);
            }).contains(QStringLiteral("between 0 and 1")));
}

QTEST_GUILESS_MAIN(TestPayloadObservability)
#include "tst_payloadobservability.moc"
