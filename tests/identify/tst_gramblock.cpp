// GramBlock: least-squares rows reduced to Gram quantities must give what the rows give.
#include "../support/NumericAssert.h"
#include "identify/GramBlock.h"
#include "identify/ObservableUpdate.h"
#include "model/Error.h"

#include <QTest>
#include <algorithm>
#include <random>

using namespace learnid;

namespace {

constexpr int joints = 2;
constexpr double tolerance = 1e-6;

Eigen::MatrixXd randomMatrix(std::mt19937 &rng, Eigen::Index rows, Eigen::Index cols,
                             double sigma = 1.0)
{
    std::normal_distribution<double> normal(0.0, sigma);
    Eigen::MatrixXd m(rows, cols);
    for (Eigen::Index i = 0; i < rows; ++i)
        for (Eigen::Index j = 0; j < cols; ++j)
            m(i, j) = normal(rng);
    return m;
}

// Sample-major stacked rows of a trial: A (N n x m), b = A phi + noise.
struct Rows
{
    Eigen::MatrixXd a;
    Eigen::VectorXd b;
};

Rows randomRows(std::mt19937 &rng, int samples, const Eigen::VectorXd &phi, double noise)
{
    Rows r;
    r.a = randomMatrix(rng, samples * joints, phi.size());
    r.b = r.a * phi + randomMatrix(rng, samples * joints, 1, noise);
    return r;
}

void compareUpdates(const ParameterUpdate &blocks, const ParameterUpdate &rows)
{
    LEARNID_COMPARE_MATRIX(blocks.phi, rows.phi, 1e-12 * rows.phi.norm());
    QCOMPARE(blocks.rank, rows.rank);
    QCOMPARE(blocks.observable, rows.observable);
    if (std::isinf(rows.condition))
        QVERIFY(std::isinf(blocks.condition));
    else
        LEARNID_COMPARE_NEAR(blocks.condition, rows.condition, 1e-10 * rows.condition);
    LEARNID_COMPARE_MATRIX(blocks.residualRms, rows.residualRms, 1e-9 * rows.residualRms.norm());
    for (Eigen::Index i = 0; i < rows.phiStd.size(); ++i) {
        if (std::isinf(rows.phiStd[i]))
            QVERIFY(std::isinf(blocks.phiStd[i]));
        else
            LEARNID_COMPARE_NEAR(blocks.phiStd[i], rows.phiStd[i], 1e-8 * rows.phiStd[i]);
    }
}

} // namespace

class TestGramBlock : public QObject
{
    Q_OBJECT

private slots:
    void residualAtAnyEstimate_equalsTheRowsResidual();
    void residualNearTheFit_isExactWhereTheExpansionAboutZeroFails();
    void weightedBlocks_equalTheStackedWeightedRows();
    void shapedBlocks_giveTheStackedRowsStandardDeviations();
    void rankDeficientBlocks_keepWhatTheStackedRowsKeep();
    void normalEquationsOnly_solveAndMarkTheResidualUnset();
    void mismatchedBlocks_throw();
    void nonzeroColumns_giveTheFullRowsBlock();
};

// ||b_j - A_j phi||^2 from G, g, rr about the reference, against the rows, near and far from it.
void TestGramBlock::residualAtAnyEstimate_equalsTheRowsResidual()
{
    std::mt19937 rng(5);
    const Eigen::Vector3d phiTrue(20, 5, 8);
    const Rows r = randomRows(rng, 400, phiTrue, 0.1);
    const GramBlock block = stackedGramBlock(r.a, r.b, joints, Eigen::Vector3d(19, 6, 7));
    for (const Eigen::Vector3d &phi :
         {Eigen::Vector3d(20, 5, 8), Eigen::Vector3d(40, 20, 30), Eigen::Vector3d(-3, 0, 1)}) {
        const Eigen::VectorXd residual = r.b - r.a * phi;
        const Eigen::VectorXd squares = block.residualSquaresAt(phi);
        for (int j = 0; j < joints; ++j) {
            double direct = 0.0;
            for (Eigen::Index k = j; k < residual.size(); k += joints)
                direct += residual[k] * residual[k];
            LEARNID_COMPARE_NEAR(squares[j], direct, 1e-11 * direct);
        }
    }
}

// Torque 1e4 times its residual: b^T b - 2 phi^T A^T b + phi^T A^T A phi loses ~8 of 16 digits
// to cancellation, while the expansion about the block's own fit keeps the residual exact.
void TestGramBlock::residualNearTheFit_isExactWhereTheExpansionAboutZeroFails()
{
    std::mt19937 rng(7);
    const Eigen::Vector3d phiTrue(20, 5, 8);
    const Rows r = randomRows(rng, 2000, phiTrue, 1e-3);
    const Eigen::VectorXd fit = observableUpdate(r.a, r.b, joints, phiTrue, tolerance).phi;
    const GramBlock aboutFit = stackedGramBlock(r.a, r.b, joints, fit);
    const GramBlock aboutZero = stackedGramBlock(r.a, r.b, joints, Eigen::Vector3d::Zero());
    const Eigen::Vector3d phi = fit + Eigen::Vector3d(1e-6, -2e-6, 1e-6);
    const Eigen::VectorXd residual = r.b - r.a * phi;
    double direct = 0.0;
    for (Eigen::Index k = 0; k < residual.size(); k += joints)
        direct += residual[k] * residual[k];
    LEARNID_COMPARE_NEAR(aboutFit.residualSquaresAt(phi)[0], direct, 1e-12 * direct);
    // The same identity about phi = 0 (the textbook form): visibly off.
    QVERIFY(std::abs(aboutZero.residualSquaresAt(phi)[0] - direct) > 1e-10 * direct);
}

// Two trials' blocks, each about its own reference and with its own per-joint weights, against
// observableUpdate() of the stacked rows with those weights per row.
void TestGramBlock::weightedBlocks_equalTheStackedWeightedRows()
{
    std::mt19937 rng(11);
    const Eigen::Vector3d phiTrue(20, 5, 8), phiPrev(40, 20, 30);
    const Rows r1 = randomRows(rng, 300, phiTrue, 0.05);
    const Rows r2 = randomRows(rng, 500, phiTrue, 0.2);
    const Eigen::Vector2d w1(3.0, 0.5), w2(1.5, 7.0);
    GramBlock b1 = stackedGramBlock(r1.a, r1.b, joints, Eigen::Vector3d(21, 4, 8));
    GramBlock b2 = stackedGramBlock(r2.a, r2.b, joints, phiPrev);
    for (int j = 0; j < joints; ++j) {
        b1.setJointWeight(j, w1[j]);
        b2.setJointWeight(j, w2[j]);
    }
    Eigen::MatrixXd a(r1.a.rows() + r2.a.rows(), 3);
    a << r1.a, r2.a;
    Eigen::VectorXd b(a.rows()), weight(a.rows());
    b << r1.b, r2.b;
    weight << w1.replicate(300, 1), w2.replicate(500, 1);
    compareUpdates(observableUpdate({&b1, &b2}, phiPrev, tolerance),
                   observableUpdate(a, b, joints, phiPrev, tolerance, weight));
}

void TestGramBlock::shapedBlocks_giveTheStackedRowsStandardDeviations()
{
    std::mt19937 rng(13);
    const Eigen::Vector3d phiTrue(20, 5, 8);
    const Rows r = randomRows(rng, 600, phiTrue, 0.1);
    // Any H^T A will do for the algebra: a smoothed copy of A.
    Eigen::MatrixXd shaped = r.a;
    for (Eigen::Index k = joints; k < shaped.rows(); ++k)
        shaped.row(k) = 0.5 * shaped.row(k) + 0.5 * shaped.row(k - joints);
    NoiseShaping noise;
    noise.varianceGain = 0.3;
    noise.transposedApplied = shaped;
    const GramBlock block = stackedGramBlock(r.a, r.b, joints, phiTrue, shaped);
    QVERIFY(block.shaped());
    compareUpdates(observableUpdate({&block}, phiTrue, tolerance, 0.3),
                   observableUpdate(r.a, r.b, joints, phiTrue, tolerance, {}, noise));
}

void TestGramBlock::rankDeficientBlocks_keepWhatTheStackedRowsKeep()
{
    std::mt19937 rng(17);
    const Eigen::Vector3d phiTrue(20, 5, 8), phiPrev(40, 20, 30);
    Rows r = randomRows(rng, 200, phiTrue, 0.01);
    r.a.col(2).setZero(); // the trajectory does not excite c
    r.b = r.a * phiTrue + randomMatrix(rng, r.a.rows(), 1, 1e-3);
    const GramBlock prior = stackedGramBlock(r.a, r.b, joints, phiPrev);
    const ParameterUpdate u = observableUpdate({&prior}, phiPrev, tolerance);
    QCOMPARE(u.rank, 2);
    QCOMPARE(u.phi[2], phiPrev[2]);
    // Taken about the fit (as the laws do) the block's residual is the rows' own.
    const GramBlock block = stackedGramBlock(r.a, r.b, joints, u.phi);
    compareUpdates(observableUpdate({&block}, phiPrev, tolerance),
                   observableUpdate(r.a, r.b, joints, phiPrev, tolerance));
}

void TestGramBlock::normalEquationsOnly_solveAndMarkTheResidualUnset()
{
    std::mt19937 rng(19);
    const Eigen::Vector3d phiTrue(20, 5, 8), phiPrev(40, 20, 30);
    const Rows r = randomRows(rng, 300, phiTrue, 0.1);
    GramBlock block(joints, 3, 300, phiPrev);
    std::vector<Eigen::MatrixXd> a(joints, Eigen::MatrixXd(300, 3));
    std::vector<Eigen::VectorXd> b(joints, Eigen::VectorXd(300));
    for (int j = 0; j < joints; ++j) {
        for (int k = 0; k < 300; ++k) {
            a[size_t(j)].row(k) = r.a.row(k * joints + j);
            b[size_t(j)][k] = r.b[k * joints + j];
        }
        block.setJointNormalEquations(j, a[size_t(j)], b[size_t(j)]);
    }
    QVERIFY(std::isnan(block.residualSquares(0)));
    const ParameterUpdate rows = observableUpdate(r.a, r.b, joints, phiPrev, tolerance);
    const Eigen::VectorXd phi = observableUpdate({&block}, phiPrev, tolerance).phi;
    LEARNID_COMPARE_MATRIX(phi, rows.phi, 1e-12 * rows.phi.norm());
    block.setReference(phi);
    for (int j = 0; j < joints; ++j)
        block.setJointResidual(j, a[size_t(j)], b[size_t(j)]);
    compareUpdates(observableUpdate({&block}, phiPrev, tolerance), rows);
}

void TestGramBlock::mismatchedBlocks_throw()
{
    std::mt19937 rng(23);
    const Rows r = randomRows(rng, 50, Eigen::Vector3d(1, 2, 3), 0.1);
    const GramBlock two = stackedGramBlock(r.a, r.b, joints, Eigen::Vector3d::Zero());
    const GramBlock one = stackedGramBlock(r.a, r.b, 1, Eigen::Vector3d::Zero());
    QVERIFY_THROWS_EXCEPTION(Error,
                             observableUpdate({&two, &one}, Eigen::Vector3d::Zero(), tolerance));
    QVERIFY_THROWS_EXCEPTION(Error, observableUpdate({}, Eigen::Vector3d::Zero(), tolerance));
    QVERIFY_THROWS_EXCEPTION(Error,
                             stackedGramBlock(r.a, r.b.head(7), joints, Eigen::Vector3d::Zero()));
    QVERIFY_THROWS_EXCEPTION(Error, GramBlock(joints, 3, 10, Eigen::Vector2d::Zero()));
}

// Rows stored by their nonzero columns (JointRows) give the Gram quantities of the full rows,
// zero columns included, to rounding; columns that are not ascending parameter indices throw.
void TestGramBlock::nonzeroColumns_giveTheFullRowsBlock()
{
    std::mt19937 rng(31);
    const int m = 12;
    const Eigen::VectorXd phiPrev = randomMatrix(rng, m, 1);
    const std::vector<std::vector<int>> kept = {{0, 1, 2, 3, 5, 6, 7, 8, 9, 10, 11}, {4, 7, 11}};
    GramBlock full(joints, m, 400, phiPrev), compact(joints, m, 400, phiPrev);
    std::vector<Eigen::MatrixXd> a(joints);
    std::vector<JointRows> rows(joints);
    std::vector<Eigen::VectorXd> b(joints);
    for (int j = 0; j < joints; ++j) {
        const std::vector<int> &columns = kept[size_t(j)];
        rows[size_t(j)].a = randomMatrix(rng, 400, Eigen::Index(columns.size()));
        rows[size_t(j)].columns = columns;
        a[size_t(j)] = Eigen::MatrixXd::Zero(400, m);
        a[size_t(j)](Eigen::all, columns) = rows[size_t(j)].a;
        b[size_t(j)] = randomMatrix(rng, 400, 1);
        full.setJointNormalEquations(j, a[size_t(j)], b[size_t(j)]);
        compact.setJointNormalEquations(j, rows[size_t(j)], b[size_t(j)]);
    }
    const Eigen::VectorXd phi = observableUpdate({&full}, phiPrev, tolerance).phi;
    full.setReference(phi);
    compact.setReference(phi);
    for (int j = 0; j < joints; ++j) {
        full.setJointResidual(j, a[size_t(j)], b[size_t(j)]);
        compact.setJointResidual(j, rows[size_t(j)], b[size_t(j)]);
        full.setJointShapedRows(j, a[size_t(j)]);
        compact.setJointShapedRows(j, rows[size_t(j)]);
    }
    QVERIFY(compact.shaped());
    for (int j = 0; j < joints; ++j) {
        const double scale = full.gram(j).norm();
        LEARNID_COMPARE_MATRIX(compact.gram(j), full.gram(j), 1e-12 * scale);
        LEARNID_COMPARE_MATRIX(compact.shapedGram(j), full.shapedGram(j), 1e-12 * scale);
        LEARNID_COMPARE_MATRIX(compact.gradient(j), full.gradient(j),
                               1e-12 * full.gradient(j).norm());
        LEARNID_COMPARE_NEAR(compact.residualSquares(j), full.residualSquares(j),
                             1e-12 * full.residualSquares(j));
        // The columns left out are exactly zero.
        for (int i = 0; i < m; ++i) {
            if (std::find(kept[size_t(j)].begin(), kept[size_t(j)].end(), i) ==
                kept[size_t(j)].end()) {
                QVERIFY(compact.gram(j).row(i).isZero(0.0));
                QVERIFY(compact.gram(j).col(i).isZero(0.0));
                QCOMPARE(compact.gradient(j)[i], 0.0);
            }
        }
    }
    JointRows unordered = rows[1];
    unordered.columns = {7, 4, 11};
    QVERIFY_THROWS_EXCEPTION(Error, compact.setJointShapedRows(1, unordered));
    unordered.columns = {4, 7, m};
    QVERIFY_THROWS_EXCEPTION(Error, compact.setJointShapedRows(1, unordered));
    unordered.columns = {4, 7};
    QVERIFY_THROWS_EXCEPTION(Error, compact.setJointShapedRows(1, unordered));
}

QTEST_GUILESS_MAIN(TestGramBlock)
#include "tst_gramblock.moc"
