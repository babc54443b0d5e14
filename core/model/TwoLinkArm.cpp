#include "model/TwoLinkArm.h"

#include "model/TwoLinkDynamics.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

QList<ParameterInfo> TwoLinkArm::parameters() const
{
    const QString unit = QStringLiteral("kg m^2");
    return {
        {QStringLiteral("a"), unit,
         QCoreApplication::translate("TwoLinkArm", "inertia of the base axis"), QString()},
        {QStringLiteral("b"), unit,
         QCoreApplication::translate("TwoLinkArm", "coupling inertia of the two links"), QString()},
        {QStringLiteral("c"), unit,
         QCoreApplication::translate("TwoLinkArm", "inertia of the second link"), QString()},
    };
}

void TwoLinkArm::regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                           Eigen::Ref<Eigen::MatrixXd> out) const
{
    const double d = q[1] - q[0];
    const double cd = std::cos(d);
    const double sd = std::sin(d);
    // eq. (22)
    out(0, 0) = qdd[0];
    out(0, 1) = qdd[1] * cd - qd[1] * qd[1] * sd;
    out(0, 2) = 0.0;
    out(1, 0) = 0.0;
    out(1, 1) = qdd[0] * cd + qd[0] * qd[0] * sd;
    out(1, 2) = qdd[1];
}

void TwoLinkArm::regressorSeries(const Eigen::Ref<const Eigen::MatrixXd> &q,
                                 const Eigen::Ref<const Eigen::MatrixXd> &qd,
                                 const Eigen::Ref<const Eigen::MatrixXd> &qdd,
                                 Eigen::Ref<Eigen::MatrixXd> out) const
{
    // sin and cos of d are carried from sample to sample by the exact rotation of the simulator
    // (twolink::rotate: |delta| < 0.01 by series, else directly) and evaluated afresh every
    // kAnchor samples, so rounding cannot accumulate beyond a few ulp.
    constexpr Eigen::Index kAnchor = 8;
    double dPrev = 0.0, sd = 0.0, cd = 1.0;
    for (Eigen::Index k = 0; k < q.cols(); ++k) {
        const double d = q(1, k) - q(0, k);
        if (k % kAnchor == 0) {
            sd = std::sin(d);
            cd = std::cos(d);
        } else {
            twolink::rotate(dPrev, sd, cd, d - dPrev, sd, cd);
        }
        dPrev = d;
        double *w = out.col(k).data(); // W column-major: (0,0) (1,0) (0,1) (1,1) (0,2) (1,2)
        // eq. (22), as regressor()
        w[0] = qdd(0, k);
        w[1] = 0.0;
        w[2] = qdd(1, k) * cd - qd(1, k) * qd(1, k) * sd;
        w[3] = qdd(0, k) * cd + qd(0, k) * qd(0, k) * sd;
        w[4] = 0.0;
        w[5] = qdd(1, k);
    }
}

void TwoLinkArm::massMatrix(const VectorRef &q, const VectorRef &phi,
                            Eigen::Ref<Eigen::MatrixXd> out) const
{
    const double m12 = phi[1] * std::cos(q[1] - q[0]);
    out(0, 0) = phi[0];
    out(0, 1) = m12;
    out(1, 0) = m12;
    out(1, 1) = phi[2];
}

void TwoLinkArm::biasTorque(const VectorRef &q, const VectorRef &qd, const VectorRef &phi,
                            Eigen::Ref<Eigen::VectorXd> out) const
{
    const double bs = phi[1] * std::sin(q[1] - q[0]);
    out[0] = -bs * qd[1] * qd[1];
    out[1] = bs * qd[0] * qd[0];
}

void TwoLinkArm::inverseDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                                 const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const
{
    const double d = q[1] - q[0];
    const double bc = phi[1] * std::cos(d);
    const double bs = phi[1] * std::sin(d);
    out[0] = phi[0] * qdd[0] + bc * qdd[1] - bs * qd[1] * qd[1];
    out[1] = bc * qdd[0] + phi[2] * qdd[1] + bs * qd[0] * qd[0];
}

void TwoLinkArm::forwardDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &tau,
                                 const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const
{
    const double d = q[1] - q[0];
    const double bc = phi[1] * std::cos(d);
    const double bs = phi[1] * std::sin(d);
    const double r0 = tau[0] + bs * qd[1] * qd[1];
    const double r1 = tau[1] - bs * qd[0] * qd[0];
    const double det = phi[0] * phi[2] - bc * bc; // > 0 for a physical phi (a c > b^2)
    out[0] = (phi[2] * r0 - bc * r1) / det;
    out[1] = (phi[0] * r1 - bc * r0) / det;
}

void TwoLinkArm::rk4Step(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                         const VectorRef &tau, const VectorRef &phi, double h) const
{
    const double t[2] = {tau[0], tau[1]};
    const double p[3] = {phi[0], phi[1], phi[2]};
    twolink::rk4Steps(q.data(), qd.data(), t, p, h, 1);
}

} // namespace learnid
