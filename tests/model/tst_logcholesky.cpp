// The log-Cholesky parametrisation of a link's inertia (Rucker and Wensing 2022): J = U U^T,
// its round trip, its Jacobian and curvature against central differences.

#include "../support/NumericAssert.h"
#include "InertiaSamples.h"
#include "model/LogCholesky.h"
#include "model/PhysicalConsistency.h"

#include <QTest>
#include <cmath>
#include <random>

using namespace learnid;
using namespace learnid::test;

class TestLogCholesky : public QObject
{
    Q_OBJECT

private slots:
    void logCholesky_givesUUTransposeAndRoundTrips();
    void logCholeskyJacobian_matchesCentralDifferences();
    void logCholeskyCurvature_matchesCentralDifferencesOfTheJacobian();
    void logCholeskyOfInconsistentLink_throws();
};

void TestLogCholesky::logCholesky_givesUUTransposeAndRoundTrips()
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        Vector10d theta;
        for (int k = 0; k < 10; ++k)
            theta[k] = value(rng);
        const double e = std::exp(theta[0]);
        Eigen::Matrix4d u;
        u << std::exp(theta[1]), theta[4], theta[6], theta[7], 0.0, std::exp(theta[2]), theta[5],
            theta[8], 0.0, 0.0, std::exp(theta[3]), theta[9], 0.0, 0.0, 0.0, 1.0;
        u *= e;
        const Vector10d pi = inertialFromLogCholesky(theta);
        LEARNID_COMPARE_MATRIX(pseudoInertia(pi), u * u.transpose(), 1e-13);
        QVERIFY(checkConsistency(pi, 1, 1e-12)[0].consistent);
        LEARNID_COMPARE_MATRIX(logCholeskyFromInertial(pi), theta, 1e-11);
    }
    const Vector10d box = boxInertial(sampleBox());
    LEARNID_COMPARE_MATRIX(inertialFromLogCholesky(logCholeskyFromInertial(box)), box, 1e-13);
}

void TestLogCholesky::logCholeskyJacobian_matchesCentralDifferences()
{
    const Vector10d theta = logCholeskyFromInertial(boxInertial(sampleBox()));
    Matrix10d jacobian;
    const Vector10d pi = inertialFromLogCholesky(theta, jacobian);
    LEARNID_COMPARE_MATRIX(pi, inertialFromLogCholesky(theta), 0.0);
    Matrix10d differences;
    for (int k = 0; k < 10; ++k) {
        const double h = 1e-5 * std::max(1.0, std::abs(theta[k]));
        Vector10d plus = theta, minus = theta;
        plus[k] += h;
        minus[k] -= h;
        differences.col(k) =
            (inertialFromLogCholesky(plus) - inertialFromLogCholesky(minus)) / (2.0 * h);
    }
    LEARNID_COMPARE_MATRIX(jacobian, differences, 1e-6 * jacobian.cwiseAbs().maxCoeff());
}

void TestLogCholesky::logCholeskyCurvature_matchesCentralDifferencesOfTheJacobian()
{
    Vector10d theta;
    theta << 0.3, -0.2, 0.4, -1.1, 0.25, -0.15, 0.05, 0.3, -0.1, 0.2;
    Vector10d weights;
    weights << 1.0, -2.0, 0.5, 0.7, -0.3, 1.2, 0.4, -0.9, 0.6, 1.5;
    const Matrix10d curvature = logCholeskyCurvature(theta, weights);
    Matrix10d differences;
    for (int k = 0; k < 10; ++k) {
        const double h = 1e-5;
        Vector10d plus = theta, minus = theta;
        plus[k] += h;
        minus[k] -= h;
        Matrix10d jPlus, jMinus;
        inertialFromLogCholesky(plus, jPlus);
        inertialFromLogCholesky(minus, jMinus);
        differences.col(k) = (jPlus - jMinus).transpose() * weights / (2.0 * h);
    }
    LEARNID_COMPARE_MATRIX(curvature, differences, 1e-6 * curvature.cwiseAbs().maxCoeff());
    LEARNID_COMPARE_MATRIX(curvature, curvature.transpose(), 0.0);
}

void TestLogCholesky::logCholeskyOfInconsistentLink_throws()
{
    Vector10d pi = boxInertial(sampleBox());
    pi[0] = -1.0;
    QVERIFY_THROWS_EXCEPTION(Error, logCholeskyFromInertial(pi));
    const Vector10d point = inertialOf(2.0, Eigen::Matrix3d::Zero(), {0.1, 0.2, 0.3});
    QVERIFY_THROWS_EXCEPTION(Error, logCholeskyFromInertial(shiftedLeastEigenvalue(point, -1e-3)));
    QVERIFY_THROWS_EXCEPTION(Error, inertialFromLogCholesky(Eigen::VectorXd::Zero(9)));
}

QTEST_GUILESS_MAIN(TestLogCholesky)
#include "tst_logcholesky.moc"
