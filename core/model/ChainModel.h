#pragma once

#include "model/BaseParameters.h"
#include "model/ChainDynamics.h"
#include "model/RobotModel.h"
#include "types/ChainSettings.h"

#include <QStringList>

namespace learnid {

/// Any serial chain as a RobotModel whose parameters phi are its base parameters
/// (BaseParameters.h): the regressor is the base regressor, the learning laws estimate phi.
/// The standard parameters pi (p = 10 n + n terms.count()) are the links' inertia (10 per
/// link) then each joint's terms in JointTerms' order. The CAD vector (from the chain: its
/// inertia, the URDF's damping as viscous and friction as Coulomb friction, armature and offset
/// from learnid's URDF extension, 0 without it) is the prior that fills what the base parameters do
/// not fix: dynamics from phi are evaluated with standardFromBase(phi), which gives the same
/// torques as any pi with those base parameters.
class ChainModel final : public RobotModel
{
public:
    /// Throws Error as ChainDynamics, or when terms.coulombVelocity is not positive.
    ChainModel(const SerialChain &chain, const JointTerms &terms, const QString &id);

    const ChainDynamics &dynamics() const { return m_dynamics; }
    const SerialChain &chain() const { return m_dynamics.chain(); }
    const JointTerms &jointTerms() const { return m_terms; }
    const BaseParameters &base() const { return m_base; }

    int standardCount() const { return m_standardCount; }
    QList<ParameterInfo> standardParameters() const { return m_standardInfo; }
    const Eigen::VectorXd &cadStandard() const { return m_cad; }
    /// The standard vector of a chain with this model's joints (the CAD one, or a real robot's
    /// URDF): its links' inertia, its URDF damping and friction as viscous and Coulomb terms,
    /// armature and offset from learnid's URDF extension.
    /// Throws Error when the joint count differs.
    Eigen::VectorXd standardOf(const SerialChain &chain) const;
    /// Indices of the standard parameters that must not be negative (armature, friction).
    std::vector<int> nonnegativeStandard() const;
    Eigen::VectorXd baseFromStandard(const Eigen::VectorXd &pi) const;
    Eigen::VectorXd standardFromBase(const Eigen::VectorXd &phi) const;
    /// Y(q, qd, qdd) in the standard parameters into out (n x p).
    void standardRegressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                           Eigen::Ref<Eigen::MatrixXd> out) const;

    QString id() const override { return m_id; }
    int dof() const override { return m_dynamics.dof(); }
    int parameterCount() const override { return m_base.baseCount(); }
    QList<ParameterInfo> parameters() const override { return m_baseInfo; }

    void regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                   Eigen::Ref<Eigen::MatrixXd> out) const override;
    void massMatrix(const VectorRef &q, const VectorRef &phi,
                    Eigen::Ref<Eigen::MatrixXd> out) const override;
    void biasTorque(const VectorRef &q, const VectorRef &qd, const VectorRef &phi,
                    Eigen::Ref<Eigen::VectorXd> out) const override;
    void inverseDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                         const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const override;
    /// M qdd = tau - h by Cholesky, on the stack.
    void forwardDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &tau,
                         const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const override;
    void rk4Step(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                 const VectorRef &tau, const VectorRef &phi, double h) const override;

    static constexpr int maxStandard = ChainDynamics::maxJoints * 14;
    using StandardVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, maxStandard, 1>;

private:
    /// standardFromBase without allocation.
    void fillStandard(const VectorRef &phi, StandardVector &pi) const;
    /// The joint terms' torques (velocity and offset terms; armature when qdd is given).
    void addJointTerms(const VectorRef &qd, const double *qdd, const StandardVector &pi,
                       Eigen::Ref<Eigen::VectorXd> out) const;

    QString m_id;
    ChainDynamics m_dynamics;
    JointTerms m_terms;
    int m_standardCount = 0;
    BaseParameters m_base;
    Eigen::VectorXd m_cad;
    Eigen::VectorXd m_priorShift; ///< beta * cad_D: pi_I = phi - this
    QList<ParameterInfo> m_standardInfo;
    QList<ParameterInfo> m_baseInfo;
};

/// The joint names of a chain model (as its URDF has them), in joint order; empty for a model
/// without a chain (the paper's arm).
QStringList jointNames(const RobotModel &model);

} // namespace learnid
