#include "../support/NumericAssert.h"
#include "identify/ObservableUpdate.h"
#include "model/Error.h"

#include <Eigen/Dense>
#include <QTest>
#include <cmath>
#include <limits>
#include <random>

using namespace learnid;

namespace {

constexpr int joints = 2;
constexpr int samples = 150;
constexpr double svdTolerance = 1e-6; // the smallest the update accepts

Eigen::MatrixXd randomMatrix(std::mt19937 &rng, int rows, int cols)
{
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::MatrixXd m(rows, cols);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j)
            m(i, j) = normal(rng);
    return m;
}

Eigen::VectorXd noise(std::mt19937 &rng, int rows, double sigma)
{
    return sigma * randomMatrix(rng, rows, 1);
}

// Closed-form weighted least squares (A^T W^2 A)^-1 A^T W^2 b, W = diag(w).
Eigen::VectorXd weightedLeastSquares(const Eigen::MatrixXd &a, const Eigen::VectorXd &b,
                                     const Eigen::VectorXd &w)
{
    const Eigen::VectorXd w2 = w.cwiseAbs2();
    const Eigen::MatrixXd normal = a.transpose() * w2.asDiagonal() * a;
    return normal.ldlt().solve(a.transpose() * w2.asDiagonal() * b);
}

double relativeError(const Eigen::VectorXd &actual, const Eigen::VectorXd &expected)
{
    return (actual - expected).norm() / expected.norm();
}

} // namespace

class TestObservableUpdate : public QObject
{
    Q_OBJECT

private slots:
    void fullRankProblem_isRecoveredExactlyFromAnyPreviousEstimate();
    void unweightedUpdate_equalsClosedFormLeastSquares();
    void rowWeights_giveClosedFormWeightedLeastSquares();
    void zeroColumn_keepsItsParameterAndRecoversTheOthers();
    void tinyColumn_keepsItsParameterAndRecoversTheOthers();
    void smallButResolvedColumn_isStillUpdated();
    void collinearColumns_updateOnlyTheirObservableSum();
    void standardDeviation_equalsClosedFormCovariance();
    void standardDeviation_matchesSpreadOverNoiseRealisations();
    void noiseShaping_stdMatchesSpreadOfFilteredNoise();
    void condition_ofTwoUnitColumnsAtAngle_isOnePlusCosOverOneMinusCos();
    void condition_ignoresColumnScaling();
    void residualRms_isPerJointOfSampleMajorRows();
    void sizeMismatch_throws();
    void nonFiniteInput_throws();
};

void TestObservableUpdate::fullRankProblem_isRecoveredExactlyFromAnyPreviousEstimate()
{
    std::mt19937 rng(401);
    const Eigen::MatrixXd a = randomMatrix(rng, samples * joints, 3);
    const Eigen::Vector3d phiTrue(20.0, 5.0, 8.0);
    const Eigen::VectorXd b = a * phiTrue;
    for (const Eigen::Vector3d &phiPrev :
         {Eigen::Vector3d(40.0, 20.0, 30.0), Eigen::Vector3d(0.0, 0.0, 0.0),
          Eigen::Vector3d(-1e3, 1e-3, 0.0), Eigen::Vector3d(20.0, 5.0, 8.0)}) {
        const ParameterUpdate u = observableUpdate(a, b, joints, phiPrev, svdTolerance);
        QVERIFY2(relativeError(u.phi, phiTrue) < 1e-10,
                 qPrintable(QStringLiteral("from [%1, %2, %3]: error %4")
                                .arg(phiPrev[0])
                                .arg(phiPrev[1])
                                .arg(phiPrev[2])
                                .arg(relativeError(u.phi, phiTrue))));
        QCOMPARE(u.rank, 3);
        QCOMPARE(u.observable, std::vector<bool>(3, true));
        QVERIFY(u.phiStd.allFinite());
        QVERIFY(std::isfinite(u.condition) && u.condition >= 1.0);
        QCOMPARE(u.residualRms.size(), Eigen::Index(joints));
        QVERIFY(u.residualRms.maxCoeff() < 1e-10 * b.cwiseAbs().maxCoeff());
    }
}

// With data that no phi fits, the update is the least-squares solution, whatever phiPrev.
void TestObservableUpdate::unweightedUpdate_equalsClosedFormLeastSquares()
{
    std::mt19937 rng(409);
    const Eigen::MatrixXd a = randomMatrix(rng, samples * joints, 3);
    const Eigen::VectorXd b =
        a * Eigen::Vector3d(20.0, 5.0, 8.0) + noise(rng, samples * joints, 0.3);
    const Eigen::VectorXd expected = a.colPivHouseholderQr().solve(b);
    for (const Eigen::Vector3d &phiPrev :
         {Eigen::Vector3d(40.0, 20.0, 30.0), Eigen::Vector3d(0.0, 1.0, 0.0)}) {
        const ParameterUpdate u = observableUpdate(a, b, joints, phiPrev, svdTolerance);
        QVERIFY2(relativeError(u.phi, expected) < 1e-10,
                 qPrintable(QString::number(relativeError(u.phi, expected))));
    }
}

void TestObservableUpdate::rowWeights_giveClosedFormWeightedLeastSquares()
{
    std::mt19937 rng(419);
    const int rows = samples * joints;
    const Eigen::MatrixXd a = randomMatrix(rng, rows, 3);
    Eigen::VectorXd w(rows);
    std::uniform_real_distribution<double> weight(0.1, 10.0);
    for (int i = 0; i < rows; ++i)
        w[i] = weight(rng);
    const Eigen::VectorXd b = a * Eigen::Vector3d(20.0, 5.0, 8.0) + noise(rng, rows, 0.5);
    const ParameterUpdate u =
        observableUpdate(a, b, joints, Eigen::Vector3d(40.0, 20.0, 30.0), svdTolerance, w);
    const Eigen::VectorXd expected = weightedLeastSquares(a, b, w);
    QVERIFY2(relativeError(u.phi, expected) < 1e-10,
             qPrintable(QString::number(relativeError(u.phi, expected))));
    // The weights matter: the unweighted solution differs.
    const Eigen::VectorXd unweighted = a.colPivHouseholderQr().solve(b);
    QVERIFY(relativeError(unweighted, expected) > 1e-4);
}

// A parameter the data do not excite keeps its previous value and is reported as such.
void TestObservableUpdate::zeroColumn_keepsItsParameterAndRecoversTheOthers()
{
    std::mt19937 rng(421);
    Eigen::MatrixXd a = randomMatrix(rng, samples * joints, 3);
    a.col(1).setZero();
    const Eigen::Vector3d phiTrue(20.0, 5.0, 8.0);
    const Eigen::Vector3d phiPrev(40.0, 20.0, 30.0);
    const ParameterUpdate u = observableUpdate(a, a * phiTrue, joints, phiPrev, svdTolerance);
    QCOMPARE(u.rank, 2);
    QCOMPARE(u.observable, (std::vector<bool>{true, false, true}));
    LEARNID_COMPARE_NEAR(u.phi[1], phiPrev[1], 1e-12 * phiPrev[1]);
    LEARNID_COMPARE_NEAR(u.phi[0], phiTrue[0], 1e-10 * phiTrue[0]);
    LEARNID_COMPARE_NEAR(u.phi[2], phiTrue[2], 1e-10 * phiTrue[2]);
    QCOMPARE(u.phiStd[1], std::numeric_limits<double>::infinity());
    QVERIFY(std::isfinite(u.phiStd[0]) && std::isfinite(u.phiStd[2]));
    QCOMPARE(u.condition, std::numeric_limits<double>::infinity());
}

void TestObservableUpdate::tinyColumn_keepsItsParameterAndRecoversTheOthers()
{
    std::mt19937 rng(431);
    Eigen::MatrixXd a = randomMatrix(rng, samples * joints, 3);
    a.col(2) *= 1e-13; // explains 1e-13 of the torque: below the 1e-6 tolerance
    const Eigen::Vector3d phiTrue(20.0, 5.0, 8.0);
    const Eigen::Vector3d phiPrev(40.0, 20.0, 30.0);
    const ParameterUpdate u = observableUpdate(a, a * phiTrue, joints, phiPrev, svdTolerance);
    QCOMPARE(u.rank, 2);
    QCOMPARE(u.observable, (std::vector<bool>{true, true, false}));
    LEARNID_COMPARE_NEAR(u.phi[2], phiPrev[2], 1e-10 * phiPrev[2]);
    LEARNID_COMPARE_NEAR(u.phi[0], phiTrue[0], 1e-10 * phiTrue[0]);
    LEARNID_COMPARE_NEAR(u.phi[1], phiTrue[1], 1e-10 * phiTrue[1]);
    QCOMPARE(u.phiStd[2], std::numeric_limits<double>::infinity());
}

// Above the tolerance a weak column is still identified, to the precision its conditioning
// allows: the update solves normal equations, whose rounding error grows like cond^2 eps
// (cond ~ 1e4 here, so ~1e-8 relative; tolerance 1e-6).
void TestObservableUpdate::smallButResolvedColumn_isStillUpdated()
{
    std::mt19937 rng(433);
    Eigen::MatrixXd a = randomMatrix(rng, samples * joints, 3);
    a.col(2) *= 1e-4;
    const Eigen::Vector3d phiTrue(20.0, 5.0, 8.0);
    const ParameterUpdate u =
        observableUpdate(a, a * phiTrue, joints, Eigen::Vector3d(40.0, 20.0, 30.0), svdTolerance);
    QCOMPARE(u.rank, 3);
    QCOMPARE(u.observable, std::vector<bool>(3, true));
    LEARNID_COMPARE_NEAR(u.phi[2], phiTrue[2], 1e-6 * phiTrue[2]);
    LEARNID_COMPARE_NEAR(u.phi[0], phiTrue[0], 1e-10 * phiTrue[0]);
}

// Identical columns 0 and 1: only phi0 + phi1 is observable. The update fits that sum, leaves
// phi2 exact, and (minimum change in the scaled coordinates, equal |phiPrev| here) splits the
// correction equally.
void TestObservableUpdate::collinearColumns_updateOnlyTheirObservableSum()
{
    std::mt19937 rng(439);
    Eigen::MatrixXd a = randomMatrix(rng, samples * joints, 3);
    a.col(1) = a.col(0);
    const Eigen::Vector3d phiTrue(20.0, 5.0, 8.0);
    const Eigen::Vector3d phiPrev(10.0, 10.0, 30.0);
    const ParameterUpdate u = observableUpdate(a, a * phiTrue, joints, phiPrev, svdTolerance);
    QCOMPARE(u.rank, 2);
    QCOMPARE(u.observable, (std::vector<bool>{false, false, true}));
    LEARNID_COMPARE_NEAR(u.phi[0] + u.phi[1], phiTrue[0] + phiTrue[1], 1e-10 * 25.0);
    LEARNID_COMPARE_NEAR(u.phi[2], phiTrue[2], 1e-10 * phiTrue[2]);
    LEARNID_COMPARE_NEAR(u.phi[0] - phiPrev[0], u.phi[1] - phiPrev[1], 1e-10 * 25.0);
    QCOMPARE(u.phiStd[0], std::numeric_limits<double>::infinity());
    QCOMPARE(u.phiStd[1], std::numeric_limits<double>::infinity());
    QVERIFY(std::isfinite(u.phiStd[2]));
}

// Var(phi) = s^2 (A^T W^2 A)^-1 with s^2 = |W r|^2 / (rows - m), the textbook WLS covariance.
void TestObservableUpdate::standardDeviation_equalsClosedFormCovariance()
{
    std::mt19937 rng(443);
    const int rows = samples * joints;
    const Eigen::MatrixXd a = randomMatrix(rng, rows, 3);
    const Eigen::VectorXd b = a * Eigen::Vector3d(20.0, 5.0, 8.0) + noise(rng, rows, 0.2);
    Eigen::VectorXd w(rows);
    for (int i = 0; i < rows; ++i)
        w[i] = (i % joints == 0) ? 1.0 : 4.0;
    for (const Eigen::VectorXd &weights : {Eigen::VectorXd(Eigen::VectorXd::Ones(rows)), w}) {
        const ParameterUpdate u = observableUpdate(a, b, joints, Eigen::Vector3d(40.0, 20.0, 30.0),
                                                   svdTolerance, weights);
        const Eigen::VectorXd phi = weightedLeastSquares(a, b, weights);
        const Eigen::VectorXd r = weights.cwiseProduct(b - a * phi);
        const double s2 = r.squaredNorm() / double(rows - 3);
        const Eigen::MatrixXd normal = a.transpose() * weights.cwiseAbs2().asDiagonal() * a;
        const Eigen::VectorXd expected = (s2 * normal.inverse().diagonal()).cwiseSqrt();
        QVERIFY2(relativeError(u.phiStd, expected) < 1e-9,
                 qPrintable(QString::number(relativeError(u.phiStd, expected))));
    }
}

// The reported std is the real spread: over 400 noise realisations the sample standard
// deviation of each estimate agrees with the mean reported std (a std estimated from 400
// draws has a relative spread of 1/sqrt(800) = 3.5 %; tolerance 12 %).
void TestObservableUpdate::standardDeviation_matchesSpreadOverNoiseRealisations()
{
    std::mt19937 rng(449);
    const int rows = 40 * joints;
    const Eigen::MatrixXd a = randomMatrix(rng, rows, 3);
    const Eigen::Vector3d phiTrue(20.0, 5.0, 8.0);
    const int runs = 400;
    Eigen::MatrixXd estimates(3, runs);
    Eigen::Vector3d reported = Eigen::Vector3d::Zero();
    for (int k = 0; k < runs; ++k) {
        const Eigen::VectorXd b = a * phiTrue + noise(rng, rows, 0.5);
        const ParameterUpdate u = observableUpdate(a, b, joints, phiTrue, svdTolerance);
        estimates.col(k) = u.phi;
        reported += u.phiStd / runs;
    }
    const Eigen::Vector3d mean = estimates.rowwise().mean();
    const Eigen::Vector3d spread =
        ((estimates.colwise() - mean).rowwise().squaredNorm() / (runs - 1)).cwiseSqrt();
    for (int i = 0; i < 3; ++i)
        LEARNID_COMPARE_NEAR(spread[i] / reported[i], 1.0, 0.12);
}

// Targets with coloured noise b = A phi + H w, H a per-joint FIR filter (h = 0.5, 0.3, 0.2) and
// smooth regressor columns, which is where correlated residuals matter most (A^T H H^T A is
// ~ (sum h)^2 A^T A, not sum h^2 A^T A). With NoiseShaping the reported std is the real spread
// over 400 realisations (12 %, as above); without it, it is ~ sqrt(0.38) = 0.62 of it.
void TestObservableUpdate::noiseShaping_stdMatchesSpreadOfFilteredNoise()
{
    std::mt19937 rng(487);
    const int n = joints;
    const int count = 100;
    const int rows = count * n;
    Eigen::MatrixXd a(rows, 3);
    for (int k = 0; k < count; ++k)
        for (int j = 0; j < n; ++j)
            for (int c = 0; c < 3; ++c)
                a(k * n + j, c) = std::sin(0.05 * k * (c + 1) + 0.7 * j + c) +
                                  0.3 * std::cos(0.013 * k * (c + 2) - j);
    const double h[] = {0.5, 0.3, 0.2};
    Eigen::MatrixXd filter = Eigen::MatrixXd::Zero(rows, rows);
    for (int k = 0; k < count; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < 3 && i <= k; ++i)
                filter(k * n + j, (k - i) * n + j) = h[i];
    NoiseShaping shaping;
    shaping.varianceGain = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
    shaping.transposedApplied = filter.transpose() * a;

    const Eigen::Vector3d phiTrue(20.0, 5.0, 8.0);
    const int runs = 400;
    Eigen::MatrixXd estimates(3, runs);
    Eigen::Vector3d shaped = Eigen::Vector3d::Zero(), plain = Eigen::Vector3d::Zero();
    for (int r = 0; r < runs; ++r) {
        const Eigen::VectorXd b = a * phiTrue + filter * noise(rng, rows, 0.5);
        const ParameterUpdate u = observableUpdate(a, b, n, phiTrue, svdTolerance, {}, shaping);
        estimates.col(r) = u.phi;
        shaped += u.phiStd / runs;
        plain += observableUpdate(a, b, n, phiTrue, svdTolerance).phiStd / runs;
    }
    const Eigen::Vector3d mean = estimates.rowwise().mean();
    const Eigen::Vector3d spread =
        ((estimates.colwise() - mean).rowwise().squaredNorm() / (runs - 1)).cwiseSqrt();
    for (int i = 0; i < 3; ++i) {
        LEARNID_COMPARE_NEAR(spread[i] / shaped[i], 1.0, 0.12);
        QVERIFY2(
            spread[i] / plain[i] > 1.3,
            qPrintable(QStringLiteral("parameter %1: ratio %2").arg(i).arg(spread[i] / plain[i])));
    }
}

// Gram matrix of unit columns at angle theta: [1 c; c 1], eigenvalues 1 +- c.
void TestObservableUpdate::condition_ofTwoUnitColumnsAtAngle_isOnePlusCosOverOneMinusCos()
{
    std::mt19937 rng(457);
    // An orthonormal 10 x 2 frame, so the columns live in a larger row space.
    const Eigen::MatrixXd frame =
        Eigen::HouseholderQR<Eigen::MatrixXd>(randomMatrix(rng, 10, 2)).householderQ() *
        Eigen::MatrixXd::Identity(10, 2);
    for (double theta : {0.2, 0.5, M_PI / 3, M_PI / 2, 2.0, 2.8}) {
        Eigen::Matrix2d planar;
        planar << 1.0, std::cos(theta), 0.0, std::sin(theta);
        const Eigen::MatrixXd a = frame * planar;
        const ParameterUpdate u = observableUpdate(a, a * Eigen::Vector2d(1.0, 2.0), 1,
                                                   Eigen::Vector2d(1.0, 1.0), svdTolerance);
        const double expected = (1.0 + std::cos(theta)) / (1.0 - std::cos(theta));
        const double symmetric = std::max(expected, 1.0 / expected);
        LEARNID_COMPARE_NEAR(u.condition, symmetric, 1e-9 * symmetric);
    }
}

void TestObservableUpdate::condition_ignoresColumnScaling()
{
    std::mt19937 rng(461);
    const Eigen::MatrixXd a = randomMatrix(rng, samples * joints, 3);
    const Eigen::VectorXd b = a * Eigen::Vector3d(20.0, 5.0, 8.0);
    const Eigen::Vector3d phiPrev(40.0, 20.0, 30.0);
    const double plain = observableUpdate(a, b, joints, phiPrev, svdTolerance).condition;
    const Eigen::MatrixXd scaled = a * Eigen::Vector3d(1e3, 1.0, 1e-3).asDiagonal();
    const double rescaled = observableUpdate(scaled, b, joints, phiPrev, svdTolerance).condition;
    LEARNID_COMPARE_NEAR(rescaled, plain, 1e-9 * plain);
}

// Rows are sample-major (row k n + j is joint j of sample k): joint 2's noise is 30 times
// joint 1's, and the RMS per joint is computed here from the closed-form residual.
void TestObservableUpdate::residualRms_isPerJointOfSampleMajorRows()
{
    std::mt19937 rng(463);
    for (int n : {2, 3}) {
        const int rows = samples * n;
        const Eigen::MatrixXd a = randomMatrix(rng, rows, 3);
        Eigen::VectorXd b = a * Eigen::Vector3d(20.0, 5.0, 8.0);
        const Eigen::VectorXd e = noise(rng, rows, 1.0);
        for (int i = 0; i < rows; ++i)
            b[i] += e[i] * (i % n == 1 ? 0.3 : 0.01);
        const ParameterUpdate u =
            observableUpdate(a, b, n, Eigen::Vector3d(40.0, 20.0, 30.0), svdTolerance);
        const Eigen::VectorXd r = b - a * a.colPivHouseholderQr().solve(b);
        QCOMPARE(u.residualRms.size(), Eigen::Index(n));
        for (int j = 0; j < n; ++j) {
            double sum = 0.0;
            for (int k = 0; k < samples; ++k)
                sum += r[k * n + j] * r[k * n + j];
            const double expected = std::sqrt(sum / samples);
            LEARNID_COMPARE_NEAR(u.residualRms[j], expected, 1e-10 * expected);
        }
        // The fit spreads joint 2's noise over all rows, so the ratio is below 30, but far from
        // the ~1 a joint-major reading of the rows would give.
        QVERIFY(u.residualRms[1] > 5.0 * u.residualRms[0]);
    }
}

void TestObservableUpdate::sizeMismatch_throws()
{
    std::mt19937 rng(467);
    const Eigen::MatrixXd a = randomMatrix(rng, 10, 3);
    const Eigen::VectorXd b = a * Eigen::Vector3d(1, 2, 3);
    const Eigen::Vector3d phi(1, 1, 1);
    QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(a, b.head(9), 2, phi, svdTolerance));
    QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(a, b, 2, Eigen::Vector2d(1, 1), svdTolerance));
    QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(a, b, 3, phi, svdTolerance)); // 10 % 3
    QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(a, b, 0, phi, svdTolerance));
    QVERIFY_THROWS_EXCEPTION(
        Error, observableUpdate(a, b, 2, phi, svdTolerance, Eigen::VectorXd::Ones(9)));
    QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(a.topRows(2), b.head(2), 2, phi,
                                                     svdTolerance)); // fewer rows than parameters
    try {
        observableUpdate(a, b.head(8), 2, phi, svdTolerance);
        QFAIL("mismatched sizes accepted");
    } catch (const Error &e) {
        QVERIFY2(e.message().contains(QStringLiteral("10 x 3")), qPrintable(e.message()));
        QVERIFY2(e.message().contains(QStringLiteral("8")), qPrintable(e.message()));
    }
}

void TestObservableUpdate::nonFiniteInput_throws()
{
    std::mt19937 rng(479);
    const Eigen::MatrixXd a = randomMatrix(rng, 10, 3);
    const Eigen::VectorXd b = a * Eigen::Vector3d(1, 2, 3);
    const Eigen::Vector3d phi(1, 1, 1);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (double bad : {nan, inf}) {
        Eigen::MatrixXd badA = a;
        badA(4, 1) = bad;
        QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(badA, b, 2, phi, svdTolerance));
        Eigen::VectorXd badB = b;
        badB[7] = bad;
        QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(a, badB, 2, phi, svdTolerance));
        Eigen::Vector3d badPhi = phi;
        badPhi[2] = bad;
        QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(a, b, 2, badPhi, svdTolerance));
        // e.g. the inverse of a zero residual noise estimate
        Eigen::VectorXd badWeight = Eigen::VectorXd::Ones(10);
        badWeight[3] = bad;
        QVERIFY_THROWS_EXCEPTION(Error, observableUpdate(a, b, 2, phi, svdTolerance, badWeight));
    }
}

QTEST_GUILESS_MAIN(TestObservableUpdate)
#include "tst_observableupdate.moc"
