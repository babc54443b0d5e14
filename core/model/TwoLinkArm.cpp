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

namespace {

// sin and cos of d + delta from s = sin d, c = cos d. For |delta| < 0.01 the series below are
// exact to double precision (the first omitted terms, delta^8/8! and delta^9/9!, are below
// 1e-20); larger steps evaluate sin and cos directly.
void rotate(double d, double s, double c, double delta, double &sOut, double &cOut)
{
    if (!(std::abs(delta) < 0.01)) {
        sOut = std::sin(d + delta);
        cOut = std::cos(d + delta);
        return;
    }
    const double d2 = delta * delta;
    const double sd = delta * (1.0 - d2 / 6.0 * (1.0 - d2 / 20.0 * (1.0 - d2 / 42.0)));
    const double cd = 1.0 - d2 / 2.0 * (1.0 - d2 / 12.0 * (1.0 - d2 / 30.0));
    sOut = s * cd + c * sd;
    cOut = c * cd - s * sd;
}

// qdd of eq. (21) given sin and cos of d = theta2 - theta1.
inline void accelerations(double sd, double cd, const double *qd, const double *tau,
                          const double *phi, double *qdd)
{
    const double bc = phi[1] * cd;
    const double bs = phi[1] * sd;
    const double r0 = tau[0] + bs * qd[1] * qd[1];
    const double r1 = tau[1] - bs * qd[0] * qd[0];
    const double det = phi[0] * phi[2] - bc * bc;
    qdd[0] = (phi[2] * r0 - bc * r1) / det;
    qdd[1] = (phi[0] * r1 - bc * r0) / det;
}

} // namespace

void TwoLinkArm::rk4Step(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                         const VectorRef &tau, const VectorRef &phi, double h) const
{
    const double t[2] = {tau[0], tau[1]};
    const double p[3] = {phi[0], phi[1], phi[2]};
    const double v1[2] = {qd[0], qd[1]};
    const double d = q[1] - q[0];
    const double s1 = std::sin(d);
    const double c1 = std::cos(d);
    double a1[2], a2[2], a3[2], a4[2], v2[2], v3[2], v4[2], s, c;
    accelerations(s1, c1, v1, t, p, a1);
    // Stage angles: d + h/2 (v1_2 - v1_1), d + h/2 (v2_2 - v2_1), d + h (v3_2 - v3_1).
    v2[0] = v1[0] + 0.5 * h * a1[0];
    v2[1] = v1[1] + 0.5 * h * a1[1];
    rotate(d, s1, c1, 0.5 * h * (v1[1] - v1[0]), s, c);
    accelerations(s, c, v2, t, p, a2);
    v3[0] = v1[0] + 0.5 * h * a2[0];
    v3[1] = v1[1] + 0.5 * h * a2[1];
    rotate(d, s1, c1, 0.5 * h * (v2[1] - v2[0]), s, c);
    accelerations(s, c, v3, t, p, a3);
    v4[0] = v1[0] + h * a3[0];
    v4[1] = v1[1] + h * a3[1];
    rotate(d, s1, c1, h * (v3[1] - v3[0]), s, c);
    accelerations(s, c, v4, t, p, a4);
    for (int i = 0; i < 2; ++i) {
        q[i] += (h / 6.0) * (v1[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]);
        qd[i] += (h / 6.0) * (a1[i] + 2.0 * a2[i] + 2.0 * a3[i] + a4[i]);
    }
}

} // namespace learnid
