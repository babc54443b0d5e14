#include "identify/PayloadObservability.h"

#include "model/Error.h"
#include "model/Payload.h"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <QCoreApplication>
#include <algorithm>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadObservability)
};

} // namespace

bool PayloadObservability::comIdentified() const
{
    return identified(1) && identified(2) && identified(3);
}

bool PayloadObservability::inertiaIdentified() const
{
    for (int i = 4; i < 10; ++i)
        if (!identified(i))
            return false;
    return true;
}

QStringList PayloadObservability::parameterNames()
{
    return {QStringLiteral("m"),    QStringLiteral("m·cx"), QStringLiteral("m·cy"),
            QStringLiteral("m·cz"), QStringLiteral("Ixx"),  QStringLiteral("Ixy"),
            QStringLiteral("Iyy"),  QStringLiteral("Ixz"),  QStringLiteral("Iyz"),
            QStringLiteral("Izz")};
}

QStringList PayloadObservability::advice(const QString &link) const
{
    QStringList lines;
    if (!massIdentified()) {
        lines << Text::tr("the mass is not seen: the path must hold the payload against gravity "
                          "in several orientations of %1, or accelerate it")
                     .arg(link);
    }
    QStringList axes;
    const char *names[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        if (!identified(1 + a))
            axes << QLatin1String(names[a]);
    if (axes.size() == 1) {
        lines << Text::tr("the centre of mass along the %1 axis of %2 is not seen: the mass and "
                          "the centre of mass need changes of the wrist's orientation; tilt the "
                          "wrist so that this axis turns away from the vertical")
                     .arg(axes.front(), link);
    } else if (!axes.isEmpty()) {
        lines << Text::tr("the centre of mass along the %1 axes of %2 is not seen: the mass and "
                          "the centre of mass need changes of the wrist's orientation; tilt the "
                          "wrist so that these axes turn away from the vertical")
                     .arg(axes.join(QStringLiteral(", ")), link);
    }
    QStringList inertia;
    for (int i = 4; i < 10; ++i)
        if (!identified(i))
            inertia << parameterNames()[i];
    if (!inertia.isEmpty()) {
        lines << Text::tr("the inertia %1 is not seen: the full inertia needs rotations of the "
                          "wrist about several axes, with accelerations")
                     .arg(inertia.join(QStringLiteral(", ")));
    }
    return lines;
}

PayloadObservability payloadObservability(const Eigen::MatrixXd &rows, double share)
{
    if (rows.cols() != 10)
        throw Error(Text::tr("the payload's regressor has 10 columns, not %1").arg(rows.cols()));
    if (!(share > 0.0 && share < 1.0))
        throw Error(Text::tr("the share of the strongest direction must lie between 0 and 1"));
    if (!rows.allFinite())
        throw Error(Text::tr("the payload's regressor is not finite"));
    // R of the rows (10 x 10) holds all they say: ||A x|| = ||R x||.
    Eigen::Matrix<double, 10, 10> r = Eigen::Matrix<double, 10, 10>::Zero();
    if (rows.rows() > 0) {
        const Eigen::HouseholderQR<Eigen::MatrixXd> qr(rows);
        const Eigen::Index k = std::min<Eigen::Index>(10, rows.rows());
        r.topRows(k) = qr.matrixQR().topRows(k).triangularView<Eigen::Upper>();
    }
    Eigen::Matrix<double, 10, 1> d = r.colwise().norm().transpose();
    const double floor = 1e-3 * d.maxCoeff() + 1e-300;
    d = d.cwiseMax(floor);
    const Eigen::Matrix<double, 10, 10> scaled = r * d.cwiseInverse().asDiagonal();
    const Eigen::JacobiSVD<Eigen::Matrix<double, 10, 10>> svd(scaled, Eigen::ComputeFullV);
    const Eigen::VectorXd s = svd.singularValues();
    PayloadObservability o;
    o.singularValues = s;
    while (o.rank < 10 && s[o.rank] > share * s[0] && s[o.rank] > 0.0)
        ++o.rank;
    o.condition = o.rank > 0 ? s[0] / s[o.rank - 1] : 0.0;
    const Eigen::MatrixXd v = svd.matrixV();
    for (int i = 0; i < 10; ++i)
        o.determined[size_t(i)] = std::min(1.0, v.row(i).head(o.rank).norm());
    o.unseen = d.cwiseInverse().asDiagonal() * v.rightCols(10 - o.rank);
    const Eigen::MatrixXd vr = v.leftCols(o.rank);
    const Eigen::VectorXd inv = s.head(o.rank).cwiseInverse().cwiseAbs2();
    o.truncatedInverse = d.cwiseInverse().asDiagonal() * vr * inv.asDiagonal() * vr.transpose() *
                         d.cwiseInverse().asDiagonal();
    return o;
}

PayloadObservability payloadPathObservability(const PayloadModel &model, const Eigen::MatrixXd &q,
                                              const Eigen::MatrixXd &qd, const Eigen::MatrixXd &qdd,
                                              double share)
{
    const int n = model.dof();
    if (q.rows() != n || qd.rows() != n || qdd.rows() != n || qd.cols() != q.cols() ||
        qdd.cols() != q.cols()) {
        throw Error(
            Text::tr("the path must give q, qd and qdd for the %1 joints at every sample").arg(n));
    }
    if (q.cols() == 0)
        throw Error(Text::tr("the path has no samples"));
    Eigen::MatrixXd rows(q.cols() * n, 10);
    Eigen::MatrixXd y(n, 10);
    Eigen::VectorXd tau(n);
    for (Eigen::Index k = 0; k < q.cols(); ++k) {
        model.evaluate(q.col(k), qd.col(k), qdd.col(k), y, tau);
        rows.middleRows(k * n, n) = y;
    }
    return payloadObservability(rows, share);
}

} // namespace learnid
