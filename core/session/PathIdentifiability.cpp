#include "session/PathIdentifiability.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <QCoreApplication>
#include <algorithm>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PathIdentifiability)
};

constexpr int maxSamples = 4000;

} // namespace

std::vector<int> PathIdentifiability::unseen() const
{
    std::vector<int> out;
    for (size_t i = 0; i < observedShare.size(); ++i)
        if (observedShare[i] < 0.5)
            out.push_back(int(i));
    return out;
}

QStringList PathIdentifiability::describe(const RobotModel &model) const
{
    QStringList lines{Text::tr("the path observes %1 of %2 parameter directions (condition %3)")
                          .arg(rank)
                          .arg(parameters)
                          .arg(condition, 0, 'g', 3)};
    const std::vector<int> hidden = unseen();
    if (!hidden.empty()) {
        QStringList names;
        const QList<ParameterInfo> info = model.parameters();
        for (const int i : hidden)
            names << info.value(i).name;
        lines << Text::tr("it cannot see, and the trials keep: %1")
                     .arg(names.join(QLatin1String(", ")));
    }
    return lines;
}

Eigen::MatrixXd pathRegressorFactor(const RobotModel &model, const JointTrajectory &path,
                                    int maxSamples)
{
    const int n = model.dof();
    const int m = model.parameterCount();
    const int step = std::max(1, path.samples() / maxSamples);
    const int used = (path.samples() + step - 1) / step;
    Eigen::MatrixXd rows(Eigen::Index(used) * n, m);
    for (int k = 0, i = 0; k < path.samples(); k += step, ++i)
        model.regressor(path.q.col(k), path.qd.col(k), path.qdd.col(k),
                        rows.middleRows(Eigen::Index(i) * n, n));
    if (rows.rows() <= m)
        return rows;
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(rows);
    return qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
}

PathIdentifiability pathIdentifiability(const RobotModel &model, const JointTrajectory &path,
                                        const Eigen::VectorXd &phi, double rankTolerance)
{
    PathIdentifiability out;
    const int m = model.parameterCount();
    out.parameters = m;
    out.observedShare.assign(size_t(m), 0.0);
    if (path.samples() == 0 || phi.size() != m)
        return out;
    // The laws' scaling, by the estimate or to unit norm where it is 0, applied to the factor:
    // (W D)^T (W D) = D R^T R D, so R D has W D's singular values and right vectors.
    Eigen::MatrixXd r = pathRegressorFactor(model, path, maxSamples);
    const Eigen::VectorXd norms = r.colwise().norm();
    for (int i = 0; i < m; ++i) {
        const double s = phi[i] != 0.0 ? std::abs(phi[i]) : (norms[i] > 0.0 ? 1.0 / norms[i] : 1.0);
        r.col(i) *= s;
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(r, Eigen::ComputeThinV);
    const Eigen::VectorXd &sigma = svd.singularValues();
    if (sigma.size() == 0 || !(sigma[0] > 0.0))
        return out;
    while (out.rank < sigma.size() && sigma[out.rank] > rankTolerance * sigma[0])
        ++out.rank;
    out.condition = sigma[0] / sigma[out.rank - 1];
    const Eigen::MatrixXd observed = svd.matrixV().leftCols(out.rank);
    for (int i = 0; i < m; ++i)
        out.observedShare[size_t(i)] = observed.row(i).squaredNorm();
    return out;
}

} // namespace learnid
