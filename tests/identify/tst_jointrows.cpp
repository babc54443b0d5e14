// midSampleJointRows: the joints' mid-sample rows by their nonzero columns must be those of the
// whole regressor series, to the bit, whatever the number of threads.
#include "../support/NumericAssert.h"
#include "identify/JointRows.h"
#include "identify/TaskThreads.h"
#include "model/Error.h"
#include "model/TwoLinkArm.h"

#include <QTest>
#include <cmath>

using namespace learnid;

namespace {

// A model whose W(0, 2) is 0 until q_0 > 1 (late in the record, after several chunks), W(1, 0)
// never, and W(1, 3) NaN at one sample: the columns appear as the samples show them.
class LateEntryModel final : public RobotModel
{
public:
    QString id() const override { return QStringLiteral("late-entry"); }
    int dof() const override { return 2; }
    int parameterCount() const override { return 4; }
    QList<ParameterInfo> parameters() const override { return {}; }
    void regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                   Eigen::Ref<Eigen::MatrixXd> out) const override
    {
        out.setZero();
        out(0, 0) = qdd[0];
        out(0, 1) = std::sin(q[1]) * qd[0];
        out(0, 2) = q[0] > 1.0 ? q[0] - 1.0 : 0.0;
        out(1, 1) = qdd[1];
        out(1, 3) = q[1] == 0.5 ? std::nan("") : 0.0;
    }
    void massMatrix(const VectorRef &, const VectorRef &,
                    Eigen::Ref<Eigen::MatrixXd> out) const override
    {
        out.setIdentity();
    }
    void biasTorque(const VectorRef &, const VectorRef &, const VectorRef &,
                    Eigen::Ref<Eigen::VectorXd> out) const override
    {
        out.setZero();
    }
};

struct States
{
    Eigen::MatrixXd q, qd, qdd;
};

States states(Eigen::Index samples)
{
    States s{Eigen::MatrixXd(2, samples), Eigen::MatrixXd(2, samples), Eigen::MatrixXd(2, samples)};
    for (Eigen::Index k = 0; k < samples; ++k) {
        const double t = 0.001 * double(k);
        s.q.col(k) << 1.2 * t, 0.3 * std::sin(7.0 * t);
        s.qd.col(k) << 1.2, 2.1 * std::cos(7.0 * t);
        s.qdd.col(k) << 0.4 * std::cos(3.0 * t), -14.7 * std::sin(7.0 * t);
    }
    return s;
}

// The rows as the law formed them before: the whole series, then (W_k + W_k+1) / 2 per entry.
std::vector<Eigen::MatrixXd> fullRows(const RobotModel &model, const States &s)
{
    const int n = model.dof(), m = model.parameterCount();
    Eigen::MatrixXd w(n * m, s.q.cols());
    model.regressorSeries(s.q, s.qd, s.qdd, w);
    const Eigen::Index rows = s.q.cols() - 1;
    std::vector<Eigen::MatrixXd> a(size_t(n), Eigen::MatrixXd(rows, m));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < m; ++i)
            a[size_t(j)].col(i) =
                0.5 * (w.row(i * n + j).head(rows) + w.row(i * n + j).tail(rows)).transpose();
    return a;
}

void compareWithFull(const RobotModel &model, const States &s, const std::vector<JointRows> &rows)
{
    const std::vector<Eigen::MatrixXd> full = fullRows(model, s);
    QCOMPARE(rows.size(), full.size());
    for (size_t j = 0; j < rows.size(); ++j) {
        QVERIFY(std::is_sorted(rows[j].columns.begin(), rows[j].columns.end()));
        for (int i = 0; i < model.parameterCount(); ++i) {
            const auto at = std::find(rows[j].columns.begin(), rows[j].columns.end(), i);
            if (at == rows[j].columns.end()) {
                QVERIFY2(full[j].col(i).isZero(0.0), "a column left out is not zero");
                continue;
            }
            const Eigen::Index c = at - rows[j].columns.begin();
            // Bitwise, NaN included.
            QVERIFY(std::memcmp(rows[j].a.col(c).data(), full[j].col(i).data(),
                                sizeof(double) * size_t(full[j].rows())) == 0);
        }
    }
}

} // namespace

class TestJointRows : public QObject
{
    Q_OBJECT

private slots:
    void twoLinkRows_equalTheWholeSeriesToTheBit();
    void lateAndNonFiniteEntries_getTheirColumns();
    void shortRecordsAndBadSizes_areHandled();
};

// The paper's arm carries sin and cos between anchors every 8 samples of a call: the chunks must
// not change a bit. Lengths that end mid-chunk; one and two threads give the same rows.
void TestJointRows::twoLinkRows_equalTheWholeSeriesToTheBit()
{
    const TwoLinkArm arm;
    for (const Eigen::Index samples : {2, 129, 1000, 1537}) {
        const States s = states(samples);
        TaskThreads one(1), two(2);
        const std::vector<JointRows> rows = midSampleJointRows(arm, s.q, s.qd, s.qdd, one);
        QCOMPARE(rows[0].columns, std::vector<int>({0, 1}));
        QCOMPARE(rows[1].columns, std::vector<int>({1, 2}));
        compareWithFull(arm, s, rows);
        compareWithFull(arm, s, midSampleJointRows(arm, s.q, s.qd, s.qdd, two));
    }
}

void TestJointRows::lateAndNonFiniteEntries_getTheirColumns()
{
    const LateEntryModel model;
    States s = states(2000); // q_0 passes 1 at sample 834
    s.q(1, 1500) = 0.5;
    TaskThreads two(2);
    const std::vector<JointRows> rows = midSampleJointRows(model, s.q, s.qd, s.qdd, two);
    QCOMPARE(rows[0].columns, std::vector<int>({0, 1, 2}));
    QCOMPARE(rows[1].columns, std::vector<int>({1, 3}));
    QVERIFY(rows[0].a.col(2).head(833).isZero(0.0));
    QVERIFY(std::isnan(rows[1].a(1500, 1)) && std::isnan(rows[1].a(1499, 1)));
    compareWithFull(model, s, rows);
}

void TestJointRows::shortRecordsAndBadSizes_areHandled()
{
    const TwoLinkArm arm;
    TaskThreads two(2);
    for (const Eigen::Index samples : {0, 1}) {
        const States s = states(samples);
        for (const JointRows &joint : midSampleJointRows(arm, s.q, s.qd, s.qdd, two))
            QCOMPARE(joint.a.rows(), Eigen::Index(0));
    }
    const States s = states(10);
    QVERIFY_THROWS_EXCEPTION(Error, midSampleJointRows(arm, s.q, s.qd.leftCols(9), s.qdd, two));
    QVERIFY_THROWS_EXCEPTION(Error, midSampleJointRows(arm, s.q.topRows(1), s.qd, s.qdd, two));
}

QTEST_GUILESS_MAIN(TestJointRows)
#include "tst_jointrows.moc"
