#include "model/TwoLinkArm.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

QList<ParameterInfo> TwoLinkArm::parameters() const
{
    const QString unit = QStringLiteral("kg m^2");
    return {
        {QStringLiteral("a"), unit,
         QCoreApplication::translate("TwoLinkArm", "inertia of the base axis")},
        {QStringLiteral("b"), unit,
         QCoreApplication::translate("TwoLinkArm", "coupling inertia of the two links")},
        {QStringLiteral("c"), unit,
         QCoreApplication::translate("TwoLinkArm", "inertia of the second link")},
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

} // namespace learnid
