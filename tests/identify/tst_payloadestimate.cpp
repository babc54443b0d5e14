// The payload estimated from rows of its regressor on the KUKA LWR4+'s flange: a 3 kg body 5 cm
// off the flange axis, torques with 1 % of each joint's limit as white noise, weighted by it.
// A path that tilts and turns the wrist recovers mass and centre of mass; the standard errors
// match the spread over noise seeds; a path turning only about the vertical wrist axis reports
// m cz and Ixx, Ixy, Iyy as unseen and keeps the centre of mass along that axis at the prior.

#include "../support/ErrorOf.h"
#include "../support/NumericAssert.h"
#include "PayloadPaths.h"
#include "identify/PayloadEstimate.h"
#include "model/PhysicalConsistency.h"

#include <Eigen/Eigenvalues>
#include <QTest>
#include <random>

using namespace learnid;

namespace {

PayloadBody truePayload()
{
    PayloadBody b;
    b.mass = 3.0;
    b.com = Eigen::Vector3d(0.05, 0.0, 0.08);
    b.inertiaAtCom << 0.012, 0.001, 0.0, 0.001, 0.011, 0.0, 0.0, 0.0, 0.006;
    return b;
}

PayloadPrior technicianPrior()
{
    PayloadPrior p;
    p.mass = 2.5;
    p.com = Eigen::Vector3d(0.0, 0.0, 0.05);
    return p;
}

struct Rows
{
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
};

// Y_k pi + noise, each joint's rows divided by its noise (1 % of its effort limit).
Rows noisyRows(const PayloadModel &model, const test::JointPath &path,
               const InertialParameters &payload, unsigned seed)
{
    const int n = model.dof();
    std::mt19937 random(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    Rows r{Eigen::MatrixXd(path.q.cols() * n, 10), Eigen::VectorXd(path.q.cols() * n)};
    for (Eigen::Index k = 0; k < path.q.cols(); ++k) {
        const Eigen::MatrixXd y = model.regressorAt(path.q.col(k), path.qd.col(k), path.qdd.col(k));
        for (int j = 0; j < n; ++j) {
            const double sigma = 0.01 * model.arm().chain().joints[size_t(j)].effortLimit;
            r.a.row(k * n + j) = y.row(j) / sigma;
            r.b[k * n + j] = (y.row(j).dot(payload) + sigma * normal(random)) / sigma;
        }
    }
    return r;
}

} // namespace

class TestPayloadEstimate : public QObject
{
    Q_OBJECT

private slots:
    void wristTurningPath_recoversMassAndCentreOfMass();
    void standardErrors_matchTheSpreadOverNoiseSeeds();
    void verticalWristPath_keepsTheUnseenCentreOfMassAtThePrior();
    void badPrior_namesTheField();
};

void TestPayloadEstimate::wristTurningPath_recoversMassAndCentreOfMass()
{
    const auto arm = test::kukaArm();
    if (!arm)
        QSKIP(qPrintable(test::sharedDataMissing()));
    const PayloadModel model(arm, arm->cadStandard());
    const test::JointPath path = test::richPath(*arm);
    const Rows rows = noisyRows(model, path, truePayload().parameters(), 1);
    const PayloadEstimate e = estimatePayload(rows.a, rows.b, technicianPrior());
    QVERIFY(e.converged);
    LEARNID_COMPARE_NEAR(e.body.mass, 3.0, 0.03);
    QVERIFY2((e.body.com - truePayload().com).norm() < 0.003,
             qPrintable(QStringLiteral("centre of mass off by %1 m")
                            .arg((e.body.com - truePayload().com).norm())));
    for (int i = 0; i < 4; ++i)
        QVERIFY(e.bodyIdentified[size_t(i)]);
    // A real body inside the bound: the pseudo-inertia positive definite, the mass inside.
    const Eigen::Vector4d eig =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(pseudoInertia(e.parameters)).eigenvalues();
    QVERIFY(eig.minCoeff() > 0.0);
    QVERIFY(technicianPrior().bound.ellipsoid().fitShare(e.parameters) > 0.0);
    QVERIFY(e.comInsideBound);
    const PayloadBody lsBody = payloadBody(e.leastSquares);
    qInfo("least squares: Ic diag %.4f %.4f %.4f", lsBody.inertiaAtCom(0, 0),
          lsBody.inertiaAtCom(1, 1), lsBody.inertiaAtCom(2, 2));
    qInfo("mass %.4f kg (se %.4f), c (%.4f, %.4f, %.4f) m; Ic diag %.4f %.4f %.4f (true 0.012 "
          "0.011 0.006, se %.4f %.4f %.4f)",
          e.body.mass, e.bodyStandardError[0], e.body.com.x(), e.body.com.y(), e.body.com.z(),
          e.bodyValue[4], e.bodyValue[6], e.bodyValue[9], e.bodyStandardError[4],
          e.bodyStandardError[6], e.bodyStandardError[9]);
}

void TestPayloadEstimate::standardErrors_matchTheSpreadOverNoiseSeeds()
{
    const auto arm = test::kukaArm();
    if (!arm)
        QSKIP(qPrintable(test::sharedDataMissing()));
    const PayloadModel model(arm, arm->cadStandard());
    const test::JointPath path = test::richPath(*arm, 3.0);
    const int seeds = 12;
    Eigen::MatrixXd ls(seeds, 10);
    Eigen::Matrix<double, 10, 10> covariance = Eigen::Matrix<double, 10, 10>::Zero();
    for (int s = 0; s < seeds; ++s) {
        const Rows rows = noisyRows(model, path, truePayload().parameters(), 100 + unsigned(s));
        const PayloadEstimate e = estimatePayload(rows.a, rows.b, technicianPrior());
        ls.row(s) = e.leastSquares.transpose();
        covariance += e.covariance / seeds;
    }
    // Mass and first moments: the empirical standard deviation against the predicted one; with
    // 12 seeds the ratio lies within 0.55 to 1.45 with 99 % probability (chi-square, 11 dof).
    for (int i = 0; i < 4; ++i) {
        const Eigen::VectorXd c = ls.col(i).array() - ls.col(i).mean();
        const double spread = std::sqrt(c.squaredNorm() / (seeds - 1));
        const double ratio = spread / std::sqrt(covariance(i, i));
        QVERIFY2(ratio > 0.55 && ratio < 1.45,
                 qPrintable(QStringLiteral("parameter %1: spread %2, predicted %3")
                                .arg(i)
                                .arg(spread)
                                .arg(std::sqrt(covariance(i, i)))));
    }
}

void TestPayloadEstimate::verticalWristPath_keepsTheUnseenCentreOfMassAtThePrior()
{
    const auto arm = test::kukaArm();
    if (!arm)
        QSKIP(qPrintable(test::sharedDataMissing()));
    const PayloadModel model(arm, arm->cadStandard());
    const test::JointPath path = test::wristTurnPath(*arm);
    const Rows rows = noisyRows(model, path, truePayload().parameters(), 2);
    const PayloadPrior prior = technicianPrior();
    const PayloadEstimate e = estimatePayload(rows.a, rows.b, prior);
    QVERIFY(e.bodyIdentified[0] && e.bodyIdentified[1] && e.bodyIdentified[2]);
    QVERIFY(!e.bodyIdentified[3]);
    for (int i = 4; i < 10; ++i)
        QVERIFY(!e.bodyIdentified[size_t(i)]);
    LEARNID_COMPARE_NEAR(e.body.mass, 3.0, 0.03);
    LEARNID_COMPARE_NEAR(e.body.com.x(), 0.05, 0.003);
    LEARNID_COMPARE_NEAR(e.body.com.y(), 0.0, 0.003);
    // Unseen: the least-squares fit keeps m cz at the prior body's (carried at the fitted mass:
    // cz0 m), the plausible body keeps its centre of mass along the wrist axis where the
    // technician put it.
    LEARNID_COMPARE_NEAR(e.anchor[3] / e.anchor[0], prior.com.z(), 1e-12);
    LEARNID_COMPARE_NEAR(e.leastSquares[3], e.anchor[3], 1e-9);
    QVERIFY2(std::abs(e.body.com.z() - prior.com.z()) < 0.0005,
             qPrintable(QStringLiteral("cz %1, prior %2").arg(e.body.com.z()).arg(prior.com.z())));
}

void TestPayloadEstimate::badPrior_namesTheField()
{
    const Eigen::MatrixXd a = Eigen::MatrixXd::Identity(10, 10);
    const Eigen::VectorXd b = Eigen::VectorXd::Zero(10);
    PayloadPrior p = technicianPrior();
    p.mass = 0.0;
    QVERIFY(test::errorOf([&] {
                estimatePayload(a, b, p);
            }).startsWith(QStringLiteral("payload.prior.mass:")));
    p = technicianPrior();
    p.com.y() = NAN;
    QVERIFY(test::errorOf([&] {
                estimatePayload(a, b, p);
            }).startsWith(QStringLiteral("payload.prior.com:")));
    p = technicianPrior();
    p.bound.radius = 0.04; // the prior at 5 cm lies outside
    const QString outside = test::errorOf([&] { estimatePayload(a, b, p); });
    QVERIFY2(outside.startsWith(QStringLiteral("payload.bound.radius:")) &&
                 outside.contains(QStringLiteral("not inside")),
             qPrintable(outside));
    p = technicianPrior();
    p.bound.box = true;
    p.bound.lower = Eigen::Vector3d(-0.1, -0.1, 0.0);
    p.bound.upper = Eigen::Vector3d(0.1, 0.1, 0.04);
    QVERIFY(test::errorOf([&] {
                estimatePayload(a, b, p);
            }).startsWith(QStringLiteral("payload.bound.box:")));
    p.bound.upper.z() = -0.1;
    QVERIFY(test::errorOf([&] { estimatePayload(a, b, p); }).contains(QStringLiteral("above")));
    p = technicianPrior();
    p.inertiaAtCom = Eigen::Vector3d(0.01, 0.01, 0.05).asDiagonal(); // 0.01 + 0.01 < 0.05
    QVERIFY(test::errorOf([&] {
                estimatePayload(a, b, p);
            }).startsWith(QStringLiteral("payload.prior.inertia:")));
    QVERIFY(test::errorOf([&] {
                estimatePayload(a, Eigen::VectorXd::Zero(3), technicianPrior());
            }).contains(QStringLiteral("do not match")));
}

QTEST_GUILESS_MAIN(TestPayloadEstimate)
#include "tst_payloadestimate.moc"
