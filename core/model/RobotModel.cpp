#include "model/RobotModel.h"

#include <Eigen/Cholesky>

namespace learnid {

void RobotModel::inverseDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                                 const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const
{
    Eigen::MatrixXd m(dof(), dof());
    massMatrix(q, phi, m);
    biasTorque(q, qd, phi, out);
    out.noalias() += m * qdd;
}

void RobotModel::forwardDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &tau,
                                 const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const
{
    Eigen::MatrixXd m(dof(), dof());
    massMatrix(q, phi, m);
    Eigen::VectorXd h(dof());
    biasTorque(q, qd, phi, h);
    out = m.ldlt().solve(tau - h);
}

void RobotModel::rk4Step(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                         const VectorRef &tau, const VectorRef &phi, double h) const
{
    const int n = dof();
    Eigen::VectorXd a1(n), a2(n), a3(n), a4(n);
    forwardDynamics(q, qd, tau, phi, a1);
    const Eigen::VectorXd v2 = qd + 0.5 * h * a1;
    forwardDynamics(q + 0.5 * h * qd, v2, tau, phi, a2);
    const Eigen::VectorXd v3 = qd + 0.5 * h * a2;
    forwardDynamics(q + 0.5 * h * v2, v3, tau, phi, a3);
    const Eigen::VectorXd v4 = qd + h * a3;
    forwardDynamics(q + h * v3, v4, tau, phi, a4);
    q += (h / 6.0) * (qd + 2.0 * v2 + 2.0 * v3 + v4);
    qd += (h / 6.0) * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
}

void RobotModel::regressorSeries(const Eigen::Ref<const Eigen::MatrixXd> &q,
                                 const Eigen::Ref<const Eigen::MatrixXd> &qd,
                                 const Eigen::Ref<const Eigen::MatrixXd> &qdd,
                                 Eigen::Ref<Eigen::MatrixXd> out) const
{
    const int n = dof();
    const int m = parameterCount();
    for (Eigen::Index k = 0; k < q.cols(); ++k) {
        Eigen::Map<Eigen::MatrixXd> wk(out.col(k).data(), n, m);
        regressor(q.col(k), qd.col(k), qdd.col(k), wk);
    }
}

bool RobotModel::massMatrixPositiveDefinite(const VectorRef &q, const VectorRef &phi) const
{
    Eigen::MatrixXd m(dof(), dof());
    massMatrix(q, phi, m);
    const Eigen::LLT<Eigen::MatrixXd> llt(m);
    return llt.info() == Eigen::Success;
}

Eigen::MatrixXd RobotModel::regressorAt(const VectorRef &q, const VectorRef &qd,
                                        const VectorRef &qdd) const
{
    Eigen::MatrixXd w(dof(), parameterCount());
    regressor(q, qd, qdd, w);
    return w;
}

Eigen::VectorXd RobotModel::torqueAt(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                                     const VectorRef &phi) const
{
    Eigen::VectorXd tau(dof());
    inverseDynamics(q, qd, qdd, phi, tau);
    return tau;
}

Eigen::MatrixXd feedforwardTorque(const RobotModel &model, const JointTrajectory &desired,
                                  const Eigen::VectorXd &phi)
{
    Eigen::MatrixXd tau(model.dof(), desired.samples());
    for (int k = 0; k < desired.samples(); ++k)
        model.inverseDynamics(desired.q.col(k), desired.qd.col(k), desired.qdd.col(k), phi,
                              tau.col(k));
    return tau;
}

} // namespace learnid
