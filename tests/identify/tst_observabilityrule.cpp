// The rule observableUpdate decides observability by (docs/method.md §2.3): a parameter scale
// that does not vanish with the estimate, and the two experimental options (rows scaled per
// joint by its torque level; directions too loosely determined left alone).
#include "../support/NumericAssert.h"
#include "identify/ObservableUpdate.h"

#include <Eigen/Dense>
#include <QTest>
#include <cmath>
#include <limits>
#include <random>

using namespace learnid;

namespace {

constexpr int joints = 2;
constexpr int samples = 200;
constexpr double tolerance = 1e-3; // the scenario's default

// Sample-major rows of two joints: joint 0 carries parameter 0 (a shoulder: 100 N m), joint 1
// parameter 1 scaled by `wrist`.
Eigen::MatrixXd shoulderAndWrist(double wrist)
{
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(samples * joints, 2);
    for (int k = 0; k < samples; ++k) {
        const double t = 0.01 * k;
        a(k * joints, 0) = 100.0 * std::sin(3.0 * t) + 120.0;
        a(k * joints + 1, 1) = wrist * std::cos(5.0 * t);
    }
    return a;
}

Eigen::VectorXd whiteNoise(std::mt19937 &rng, Eigen::Index rows, double sigma)
{
    std::normal_distribution<double> normal(0.0, sigma);
    Eigen::VectorXd v(rows);
    for (Eigen::Index i = 0; i < rows; ++i)
        v[i] = normal(rng);
    return v;
}

} // namespace

class TestObservabilityRule : public QObject
{
    Q_OBJECT

private slots:
    void weakJoint_isObservedAtItsOwnTorqueLevel();
    void parameterNearZero_staysObservableThroughTheAnchor();
    void directionsAboveTheStdLimit_keepTheirValue();
};

void TestObservabilityRule::weakJoint_isObservedAtItsOwnTorqueLevel()
{
    // The wrist's parameter explains 5e-5 of the shoulder's RMS torque: below the tolerance
    // against the strongest direction of all rows (the default rule keeps it), but all of the
    // wrist's own torque (whose level counts from 1e-3 of the shoulder's up). With joint levels,
    // noise free, least squares recovers both exactly.
    const Eigen::MatrixXd a = shoulderAndWrist(1e-2);
    const Eigen::Vector2d phiTrue(2.0, 0.5);
    const Eigen::Vector2d phiPrev(1.0, 1.0);
    const ParameterUpdate plain = observableUpdate(a, a * phiTrue, joints, phiPrev, tolerance);
    QCOMPARE(plain.rank, 1);
    QCOMPARE(plain.phi[1], phiPrev[1]);
    constexpr double noLimit = std::numeric_limits<double>::infinity();
    const ParameterUpdate u =
        observableUpdate(a, a * phiTrue, joints, phiPrev, tolerance, {}, {}, {}, noLimit, true);
    QCOMPARE(u.rank, 2);
    QCOMPARE(u.observable, (std::vector<bool>{true, true}));
    LEARNID_COMPARE_NEAR(u.phi[0], phiTrue[0], 1e-10);
    LEARNID_COMPARE_NEAR(u.phi[1], phiTrue[1], 1e-10);
}

void TestObservabilityRule::parameterNearZero_staysObservableThroughTheAnchor()
{
    // Both joints equally strong; parameter 1's estimate has passed near 0. Scaled by its own
    // value its column vanishes and it would freeze at 1e-12; anchored at the prior's 1 it is
    // learned.
    const Eigen::MatrixXd a = shoulderAndWrist(100.0);
    const Eigen::Vector2d phiTrue(2.0, 0.5);
    const Eigen::Vector2d phiPrev(1.0, 1e-12);
    const ParameterUpdate frozen = observableUpdate(a, a * phiTrue, joints, phiPrev, tolerance);
    QCOMPARE(frozen.rank, 1);
    QCOMPARE(frozen.phi[1], phiPrev[1]);
    const ParameterUpdate anchored = observableUpdate(a, a * phiTrue, joints, phiPrev, tolerance,
                                                      {}, {}, Eigen::Vector2d(1.0, 1.0));
    QCOMPARE(anchored.rank, 2);
    LEARNID_COMPARE_NEAR(anchored.phi[1], phiTrue[1], 1e-10);
}

void TestObservabilityRule::directionsAboveTheStdLimit_keepTheirValue()
{
    // Three parameters on two joints with noise: parameters 0 and 1 well excited, parameter 2
    // (on joint 1 with parameter 1) barely, so that its standard deviation is a large share of
    // its value. Without a limit it moves (by noise); with the limit it keeps phiPrev
    // (its share of the step) and is reported as not determined, while the others are learned
    // as before.
    std::mt19937 rng(2311);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(samples * joints, 3);
    a.leftCols(2) = shoulderAndWrist(10.0);
    for (int k = 0; k < samples; ++k)
        a(k * joints + 1, 2) = 0.02 * std::sin(7.0 * 0.01 * k);
    const Eigen::Vector3d phiTrue(2.0, 0.5, 1.0);
    const Eigen::Vector3d phiPrev(1.5, 0.8, 1.2);
    const Eigen::VectorXd b = a * phiTrue + whiteNoise(rng, a.rows(), 0.1);

    // Joint levels on, as the experiment runs it: parameter 2 is then above the tolerance.
    constexpr double noLimit = std::numeric_limits<double>::infinity();
    const ParameterUpdate free =
        observableUpdate(a, b, joints, phiPrev, tolerance, {}, {}, {}, noLimit, true);
    QCOMPARE(free.rank, 3);
    // The independent expectation: the reported standard deviations, relative to each
    // parameter's scale |phiPrev|, put parameter 2 above 0.3 and the others far below.
    const Eigen::Vector3d relativeStd = free.phiStd.cwiseQuotient(phiPrev.cwiseAbs());
    QVERIFY2(relativeStd[2] > 0.3, qPrintable(QString::number(relativeStd[2])));
    QVERIFY(relativeStd[0] < 0.01 && relativeStd[1] < 0.01);
    QVERIFY(free.phi[2] != phiPrev[2]);

    const ParameterUpdate limited =
        observableUpdate(a, b, joints, phiPrev, tolerance, {}, {}, {}, 0.3, true);
    QCOMPARE(limited.rank, 2);
    QCOMPARE(limited.observable, (std::vector<bool>{true, true, false}));
    // The loose direction is almost parameter 2 alone: its value stays within a small share of
    // the step the free fit took.
    QVERIFY2(std::abs(limited.phi[2] - phiPrev[2]) < 0.05 * std::abs(free.phi[2] - phiPrev[2]),
             qPrintable(QStringLiteral("%1 against %2").arg(limited.phi[2]).arg(free.phi[2])));
    QCOMPARE(limited.phiStd[2], std::numeric_limits<double>::infinity());
    // Parameters 0 and 1 do not share a row with parameter 2's weak column on joint 0; on joint
    // 1 they are nearly orthogonal to it, so they land where the free fit put them.
    LEARNID_COMPARE_NEAR(limited.phi[0], free.phi[0], 5.0 * free.phiStd[0]);
    LEARNID_COMPARE_NEAR(limited.phi[1], free.phi[1], 5.0 * free.phiStd[1]);
    LEARNID_COMPARE_NEAR(limited.phi[0], phiTrue[0], 5.0 * free.phiStd[0]);
}

QTEST_GUILESS_MAIN(TestObservabilityRule)
#include "tst_observabilityrule.moc"
