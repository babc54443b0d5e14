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

} // namespace learnid
