#pragma once

// Test support: a robot controller's log made from a known robot, as a real logger writes it.
// The built-in Franka Panda (7 joints) with every inertial parameter changed by up to 30 %
// (ChainPerturbation) and friction and offsets of its own follows a smooth multi-sine motion
// (0.16 to 1.3 Hz); the torque is its inverse dynamics Y(q, qd, qdd) pi plus white noise, the
// velocity the true one plus noise. The stamps are 1 kHz ticks with jitter. A logger's faults
// are applied to that clean recording, so that a faulty log and the clean one share every sample
// they both hold: gaps (rows lost, every `gapEvery` seconds) and stale rows (a row whose values
// are those of the row before, under its own new stamp).

#include "model/ChainModel.h"
#include "model/ChainPerturbation.h"
#include "model/UrdfChain.h"

#include <Eigen/Core>
#include <QByteArray>
#include <QString>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace learnid::test {

/// The Panda as `learnid-cli identify --robot panda` models it (viscous, Coulomb, offset).
inline ChainModel pandaLogModel()
{
    return ChainModel(readUrdfChain(QStringLiteral(":/robots/panda.urdf")),
                      JointTerms{false, true, true, true}, QStringLiteral("panda"));
}

/// The robot that made the logs: the CAD inertia changed by up to 30 % and per joint viscous
/// friction 0.2 to 0.6 N m s/rad, Coulomb friction 0.3 to 0.9 N m, an offset of -0.2 to 0.2 N m.
inline Eigen::VectorXd pandaLogTruth(const ChainModel &model, quint64 seed = 3)
{
    Eigen::VectorXd truth = perturbedStandard(model, 0.3, seed);
    std::mt19937 random(unsigned(seed) + 100);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = model.dof(), terms = model.jointTerms().count();
    for (int j = 0; j < n; ++j) {
        const Eigen::Index at = 10 * n + j * terms;
        truth[at] = 0.2 + 0.4 * u(random);
        truth[at + 1] = 0.3 + 0.6 * u(random);
        truth[at + 2] = -0.2 + 0.4 * u(random);
    }
    return truth;
}

struct SyntheticLogOptions
{
    double seconds = 21.0;       ///< [s] length
    double period = 0.001;       ///< [s] the logger's tick
    double jitter = 0.05e-3;     ///< [s] stamps uniform within +-jitter of the tick
    double gapEvery = 5.0;       ///< [s] where the gaps are (t = 5, 10, ... s); 0: none
    double gapLength = 8.5e-3;   ///< [s] from the stamp before a gap to the one after
    double torqueNoise = 0.05;   ///< [N m] RMS of the white noise on every torque
    double velocityNoise = 2e-3; ///< [rad/s] RMS of the white noise on every velocity
    unsigned seed = 1;           ///< the motion, jitter and noise
};

/// A clean recording and where its logger's faults would fall.
struct SyntheticLog
{
    Eigen::VectorXd t;          ///< N stamps [s]
    Eigen::MatrixXd q, dq, tau; ///< n x N
    std::vector<bool> inGap;    ///< N: rows a logger with gaps loses
    int gaps = 0;               ///< how many gaps

    Eigen::Index samples() const { return t.size(); }
};

/// The Panda truth's log along a motion of its own (seed). The rows around each gap are stamped
/// so that the gap is exactly gapLength long: the one before late, the one after early.
inline SyntheticLog syntheticPandaLog(const ChainModel &model, const Eigen::VectorXd &truth,
                                      const SyntheticLogOptions &o)
{
    std::mt19937 random(o.seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    const int n = model.dof();
    // Centred in the Panda's joint ranges (joint 4 in [-3.07, -0.07], joint 6 in [-0.02, 3.75]).
    const Eigen::VectorXd centre =
        (Eigen::VectorXd(7) << 0.0, -0.3, 0.0, -1.9, 0.0, 1.7, 0.8).finished();
    Eigen::MatrixXd w(n, 3), a(n, 3), p(n, 3);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < 3; ++i) {
            w(j, i) = (1.0 + 1.5 * i) * (1.0 + u(random)); // 1 to 8 rad/s
            a(j, i) = 0.3 * (1.0 + u(random)) / (1 + i);
            p(j, i) = 6.28 * u(random);
        }
    }
    // Ticks: gaps of `lost` ticks, the stamps beside them moved by `shift` into the gap.
    const int lost = int(std::ceil(o.gapLength / o.period - 1e-9)) - 1;
    const double shift = 0.5 * ((lost + 1) * o.period - o.gapLength);
    const auto ticks = Eigen::Index(std::lround(o.seconds / o.period)) + 1;
    SyntheticLog log;
    log.t.resize(ticks);
    log.inGap.assign(size_t(ticks), false);
    for (Eigen::Index k = 0; k < ticks; ++k)
        log.t[k] = 1.0 + double(k) * o.period + o.jitter * (2.0 * u(random) - 1.0);
    for (double at = o.gapEvery; o.gapEvery > 0.0 && at < o.seconds - 0.1; at += o.gapEvery) {
        const auto before = Eigen::Index(std::lround(at / o.period));
        log.t[before] = 1.0 + double(before) * o.period + shift;
        log.t[before + lost + 1] = 1.0 + double(before + lost + 1) * o.period - shift;
        for (int k = 1; k <= lost; ++k)
            log.inGap[size_t(before + k)] = true;
        ++log.gaps;
    }
    log.q.resize(n, ticks);
    log.dq.resize(n, ticks);
    log.tau.resize(n, ticks);
    Eigen::VectorXd qdd(n);
    Eigen::MatrixXd y(n, model.standardCount());
    for (Eigen::Index k = 0; k < ticks; ++k) {
        for (int j = 0; j < n; ++j) {
            log.q(j, k) = centre[j];
            log.dq(j, k) = qdd[j] = 0.0;
            for (int i = 0; i < 3; ++i) {
                const double phase = w(j, i) * log.t[k] + p(j, i);
                log.q(j, k) += a(j, i) * std::sin(phase);
                log.dq(j, k) += a(j, i) * w(j, i) * std::cos(phase);
                qdd[j] -= a(j, i) * w(j, i) * w(j, i) * std::sin(phase);
            }
        }
        model.standardRegressor(log.q.col(k), log.dq.col(k), qdd, y);
        log.tau.col(k) = y * truth;
        for (int j = 0; j < n; ++j) {
            log.dq(j, k) += o.velocityNoise * normal(random);
            log.tau(j, k) += o.torqueNoise * normal(random);
        }
    }
    return log;
}

/// `count` rows to make stale, in runs of 1 to 3, none of them within 5 rows of a gap or of the
/// ends (so that no gap grows past what it is): the row indices, ascending.
inline std::vector<Eigen::Index> pickStaleRows(const SyntheticLog &log, int count, unsigned seed)
{
    std::mt19937 random(seed);
    const Eigen::Index rows = log.samples();
    std::uniform_int_distribution<Eigen::Index> start(6, rows - 10);
    std::uniform_int_distribution<int> length(1, 3);
    const auto nearGap = [&](Eigen::Index k) {
        for (Eigen::Index i = std::max<Eigen::Index>(0, k - 6); i <= std::min(rows - 1, k + 6); ++i)
            if (log.inGap[size_t(i)])
                return true;
        return false;
    };
    std::set<Eigen::Index> stale;
    while (int(stale.size()) < count) {
        const Eigen::Index first = start(random);
        const int run = std::min(length(random), count - int(stale.size()));
        bool free = !stale.count(first - 1) && !nearGap(first);
        for (int r = 0; free && r <= run; ++r)
            free = !stale.count(first + r) && !nearGap(first + r);
        for (int r = 0; free && r < run; ++r)
            stale.insert(first + r);
    }
    return {stale.begin(), stale.end()};
}

/// The log as CSV (t, q1..qn, dq1..dqn, tau1..taun, 17 digits): without the rows in gaps when
/// withGaps, and with the rows `stale` (ascending indices) holding the values of the row before.
inline QByteArray syntheticLogCsv(const SyntheticLog &log, bool withGaps,
                                  const std::vector<Eigen::Index> &stale = {})
{
    const int n = int(log.q.rows());
    QByteArray csv = "t";
    for (const char *name : {"q", "dq", "tau"})
        for (int j = 1; j <= n; ++j)
            csv += ',' + QByteArray(name) + QByteArray::number(j);
    csv += '\n';
    const auto number = [](double v) {
        return QByteArray::number(v, 'g', 17);
    };
    Eigen::Index values = 0; // the row whose values the next row writes
    size_t nextStale = 0;
    for (Eigen::Index k = 0; k < log.samples(); ++k) {
        if (withGaps && log.inGap[size_t(k)])
            continue;
        const bool isStale = nextStale < stale.size() && stale[nextStale] == k;
        nextStale += isStale ? 1 : 0;
        if (!isStale)
            values = k;
        QByteArray row = number(log.t[k]);
        for (const Eigen::MatrixXd *m : {&log.q, &log.dq, &log.tau})
            for (int j = 0; j < n; ++j)
                row += ',' + number((*m)(j, values));
        csv += row + '\n';
    }
    return csv;
}

} // namespace learnid::test
