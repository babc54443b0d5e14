#pragma once

// Simulated logs of the KUKA LWR4+ carrying a payload, for the `identify --payload` tests: the
// torque is the fixed model's inverse dynamics with the payload merged into its link, 1 % of each
// joint's limit as white noise, the angles on 2^20-count encoders.

#include "../identify/PayloadPaths.h"
#include "model/Payload.h"

#include <QByteArray>
#include <QFile>
#include <QString>
#include <cmath>
#include <random>

namespace learnid::test {

/// A 3 kg payload 5 cm off the flange axis.
inline PayloadBody truePayload()
{
    PayloadBody b;
    b.mass = 3.0;
    b.com = Eigen::Vector3d(0.05, 0.0, 0.08);
    b.inertiaAtCom << 0.012, 0.001, 0.0, 0.001, 0.011, 0.0, 0.0, 0.0, 0.006;
    return b;
}

/// The log of the arm carrying `payload` along path, as CSV (t, q, dq, tau).
inline QByteArray payloadLog(const PayloadModel &model, const JointPath &path, unsigned seed,
                             const InertialParameters &payload = truePayload().parameters())
{
    std::mt19937 random(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    const int n = model.dof();
    const double count = 2.0 * M_PI / double(1 << 20);
    QByteArray csv = "t";
    for (const char *name : {"q", "dq", "tau"})
        for (int j = 1; j <= n; ++j)
            csv += ',' + QByteArray(name) + QByteArray::number(j);
    csv += '\n';
    for (Eigen::Index k = 0; k < path.q.cols(); ++k) {
        const Eigen::VectorXd tau =
            model.torqueAt(path.q.col(k), path.qd.col(k), path.qdd.col(k), payload);
        QByteArray row = QByteArray::number(double(k) * path.period, 'g', 17);
        for (int j = 0; j < n; ++j)
            row += ',' + QByteArray::number(std::round(path.q(j, k) / count) * count, 'g', 17);
        for (int j = 0; j < n; ++j)
            row += ',' + QByteArray::number(path.qd(j, k), 'g', 17);
        for (int j = 0; j < n; ++j) {
            const double limit = model.arm().chain().joints[size_t(j)].effortLimit;
            row += ',' + QByteArray::number(tau[j] + 0.01 * limit * normal(random), 'g', 17);
        }
        csv += row + '\n';
    }
    return csv;
}

inline bool writeFile(const QString &path, const QByteArray &data)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(data) == data.size();
}

} // namespace learnid::test
