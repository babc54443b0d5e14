#include "identify/JointRows.h"

#include "identify/GramBlock.h"
#include "identify/TaskThreads.h"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <numeric>

namespace learnid {

namespace {

// Samples of the regressor each thread evaluates at once: n m (B + 1) doubles, 400 kB for 7 axes
// and 57 parameters, stay in the cache while they are spread over the joints' rows. A multiple
// of 8, and chunks start at multiples of it: TwoLinkArm::regressorSeries() carries sin and cos
// from sample to sample between anchors every 8 samples of its call, so its values are those of
// the whole series, to the bit.
constexpr Eigen::Index chunkSamples = 128;

// Joint rows with the parameters `added` (ascending, new) as further columns, keeping the columns
// in ascending order. The rows written so far move along; the new columns are 0 there, as the
// regressor entries were until now.
void addColumns(JointRows &rows, const std::vector<int> &added, Eigen::Index written)
{
    std::vector<int> columns;
    std::merge(rows.columns.begin(), rows.columns.end(), added.begin(), added.end(),
               std::back_inserter(columns));
    Eigen::MatrixXd a(rows.a.rows(), Eigen::Index(columns.size()));
    size_t old = 0;
    for (size_t s = 0; s < columns.size(); ++s) {
        auto head = a.col(Eigen::Index(s)).head(written);
        if (old < rows.columns.size() && rows.columns[old] == columns[s])
            head = rows.a.col(Eigen::Index(old++)).head(written);
        else
            head.setZero();
    }
    rows.a.swap(a);
    rows.columns = std::move(columns);
}

// One chunk of the regressor: column 0 of w is the sample before it (unless s0 = 0), columns
// 1 .. count its samples s0 .. s0 + count - 1; entry r = i n + j is W(j, i), as
// regressorSeries() writes it.
struct Chunk
{
    Eigen::Index s0 = 0;
    Eigen::Index count = 0;
    Eigen::MatrixXd w;
    std::vector<unsigned char> nonzero; ///< per entry: not 0 at some sample (NaN counts)
};

// The chunk of samples from s0 (none past the last), and which of its entries are nonzero.
void evaluate(const RobotModel &model, const Eigen::MatrixXd &q, const Eigen::MatrixXd &qd,
              const Eigen::MatrixXd &qdd, Eigen::Index s0, Chunk &chunk)
{
    chunk.s0 = s0;
    chunk.count = std::clamp<Eigen::Index>(q.cols() - s0, 0, chunkSamples);
    if (chunk.count == 0)
        return;
    model.regressorSeries(q.middleCols(s0, chunk.count), qd.middleCols(s0, chunk.count),
                          qdd.middleCols(s0, chunk.count), chunk.w.middleCols(1, chunk.count));
    std::fill(chunk.nonzero.begin(), chunk.nonzero.end(), 0);
    for (Eigen::Index c = 1; c <= chunk.count; ++c) {
        const double *x = chunk.w.col(c).data();
        for (size_t r = 0; r < chunk.nonzero.size(); ++r)
            chunk.nonzero[r] |= (x[r] != 0.0);
    }
}

// Joint j's rows of the chunk: row k pairs samples k and k + 1, columns c and c + 1 of w for
// k = s0 + c - 1.
void spread(const Chunk &chunk, int j, int n, JointRows &joint)
{
    const Eigen::Index entries = chunk.w.rows();
    const Eigen::Index first = std::max<Eigen::Index>(chunk.s0 - 1, 0);
    const Eigen::Index end = chunk.s0 + chunk.count - 1; // one past the chunk's last row
    const Eigen::Index c0 = chunk.s0 > 0 ? 0 : 1;
    for (size_t s = 0; s < joint.columns.size(); ++s) {
        const double *x = chunk.w.data() + Eigen::Index(joint.columns[s]) * n + j;
        double *to = joint.a.col(Eigen::Index(s)).data();
        for (Eigen::Index k = first, c = c0; k < end; ++k, ++c)
            to[k] = 0.5 * (x[c * entries] + x[(c + 1) * entries]);
    }
}

} // namespace

std::vector<int> jointsLargestFirst(const std::vector<JointRows> &rows)
{
    std::vector<int> order(rows.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
        return rows[size_t(i)].columns.size() > rows[size_t(j)].columns.size();
    });
    return order;
}

std::vector<JointRows> midSampleJointRows(const RobotModel &model, const Eigen::MatrixXd &q,
                                          const Eigen::MatrixXd &qd, const Eigen::MatrixXd &qdd,
                                          TaskThreads &threads)
{
    const int n = model.dof();
    const int m = model.parameterCount();
    const Eigen::Index samples = q.cols();
    if (q.rows() != n || qd.rows() != n || qdd.rows() != n || qd.cols() != samples ||
        qdd.cols() != samples)
        throw sizeError(q.rows() * samples, m, qdd.rows() * qdd.cols(), n, m);
    const Eigen::Index rows = std::max<Eigen::Index>(samples - 1, 0);
    std::vector<JointRows> out(static_cast<size_t>(n));
    for (JointRows &joint : out)
        joint.a.resize(rows, 0);

    // A round is one chunk per thread. While the threads spread a round over the joints' rows
    // (each joint on one thread: its pages are first written there, in parallel), they evaluate
    // the next round; in between, this thread alone gives the rows their new columns.
    const Eigen::Index entries = Eigen::Index(n) * m;
    const int workers = threads.count();
    std::vector<Chunk> rounds[2];
    for (std::vector<Chunk> &round : rounds) {
        round.resize(size_t(workers));
        for (Chunk &chunk : round) {
            chunk.w.resize(entries, chunkSamples + 1);
            chunk.nonzero.resize(size_t(entries));
        }
    }
    threads.run(
        [&](int t) { evaluate(model, q, qd, qdd, t * chunkSamples, rounds[0][size_t(t)]); });
    Eigen::VectorXd previous(entries); // the last sample before the chunk
    std::vector<unsigned char> known(static_cast<size_t>(entries), 0);
    std::vector<std::vector<int>> added(static_cast<size_t>(n));
    for (int r = 0; rounds[r % 2][0].count > 0; ++r) {
        std::vector<Chunk> &now = rounds[r % 2];
        std::vector<Chunk> &later = rounds[(r + 1) % 2];
        // Entries seen nonzero for the first time get their columns; the rows written so far (up
        // to the round's first) were all exactly 0 there.
        for (Chunk &chunk : now) {
            if (chunk.count == 0)
                break;
            if (chunk.s0 > 0)
                chunk.w.col(0) = previous;
            previous = chunk.w.col(chunk.count);
            for (Eigen::Index e = 0; e < entries; ++e) {
                if (chunk.nonzero[size_t(e)] && !known[size_t(e)]) {
                    known[size_t(e)] = 1;
                    added[size_t(e % n)].push_back(int(e / n));
                }
            }
        }
        for (int j = 0; j < n; ++j) {
            std::sort(added[size_t(j)].begin(), added[size_t(j)].end());
            if (!added[size_t(j)].empty())
                addColumns(out[size_t(j)], added[size_t(j)],
                           std::max<Eigen::Index>(now[0].s0 - 1, 0));
            added[size_t(j)].clear();
        }

        const std::vector<int> order = jointsLargestFirst(out);
        std::atomic<int> nextJoint{0};
        const Eigen::Index s1 = now[0].s0 + workers * chunkSamples;
        threads.run([&](int t) {
            for (int i = nextJoint++; i < n; i = nextJoint++) {
                const int j = order[size_t(i)];
                for (const Chunk &chunk : now)
                    if (chunk.count > 0)
                        spread(chunk, j, n, out[size_t(j)]);
            }
            evaluate(model, q, qd, qdd, s1 + t * chunkSamples, later[size_t(t)]);
        });
    }
    return out;
}

} // namespace learnid
