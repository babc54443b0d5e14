#pragma once

#include "types/JointTrajectory.h"

#include <Eigen/Core>
#include <QList>
#include <QString>

namespace learnid {

/// Name, unit and meaning of one dynamic parameter phi_i.
struct ParameterInfo
{
    QString name;
    QString unit;
    QString description;
    QString group; ///< what it belongs to, e.g. "link 3 (lwr_arm_3_link)"; empty for a model
                   ///< without links
};

/// Rigid-body dynamics linear in a parameter vector phi (paper eq. 1-2):
///   tau = M(q, phi) qdd + h(q, qd, phi) = W(q, qd, qdd) phi
/// q: joint angles [rad] (n), qd [rad/s] (n), qdd [rad/s^2] (n), tau [N m] (n), phi (m).
/// A model does not change after construction; callers own all working memory. Outputs are
/// written into caller-sized storage so the simulator's inner loop does not allocate.
class RobotModel
{
public:
    using VectorRef = Eigen::Ref<const Eigen::VectorXd>;

    virtual ~RobotModel() = default;

    /// Identifier used in scenario files, e.g. "paper-2link".
    virtual QString id() const = 0;
    virtual int dof() const = 0;
    virtual int parameterCount() const = 0;
    virtual QList<ParameterInfo> parameters() const = 0;

    /// W(q, qd, qdd) into out (dof x parameterCount).
    virtual void regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                           Eigen::Ref<Eigen::MatrixXd> out) const = 0;
    /// W at every sample of a trajectory: column k of out (dof * parameterCount x N) holds
    /// W(q_k, qd_k, qdd_k) column-major (entry (j, i) at row i * dof + j); q, qd, qdd are
    /// dof x N. The default calls regressor() per sample; models override it where a batch
    /// saves the per-sample call (the learning laws evaluate it at every recorded sample).
    virtual void regressorSeries(const Eigen::Ref<const Eigen::MatrixXd> &q,
                                 const Eigen::Ref<const Eigen::MatrixXd> &qd,
                                 const Eigen::Ref<const Eigen::MatrixXd> &qdd,
                                 Eigen::Ref<Eigen::MatrixXd> out) const;
    /// M(q, phi) into out (dof x dof).
    virtual void massMatrix(const VectorRef &q, const VectorRef &phi,
                            Eigen::Ref<Eigen::MatrixXd> out) const = 0;
    /// h(q, qd, phi): Coriolis, centripetal and gravity torques [N m] into out (dof).
    virtual void biasTorque(const VectorRef &q, const VectorRef &qd, const VectorRef &phi,
                            Eigen::Ref<Eigen::VectorXd> out) const = 0;

    /// tau = M qdd + h into out (dof).
    virtual void inverseDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                                 const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const;
    /// qdd = M^-1 (tau - h) into out (dof). The default factorises M; models override it with a
    /// closed form where the simulator's speed matters.
    virtual void forwardDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &tau,
                                 const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const;

    /// One classical Runge-Kutta (RK4) step of length h of q'' = forwardDynamics(q, q', tau)
    /// with tau held, updating q and qd in place. The default evaluates forwardDynamics four
    /// times; models override it where they can share work between the stages.
    virtual void rk4Step(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                         const VectorRef &tau, const VectorRef &phi, double h) const;

    /// True when phi gives a positive definite mass matrix at q (a physically possible robot).
    bool massMatrixPositiveDefinite(const VectorRef &q, const VectorRef &phi) const;

    /// Allocating conveniences for tests and planning code outside hot loops.
    Eigen::MatrixXd regressorAt(const VectorRef &q, const VectorRef &qd,
                                const VectorRef &qdd) const;
    Eigen::VectorXd torqueAt(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                             const VectorRef &phi) const;
};

/// tau_f = W(q_d, qd_d, qdd_d) phi for every sample of a desired trajectory (paper eq. 8)
/// [N m] (n x N).
Eigen::MatrixXd feedforwardTorque(const RobotModel &model, const JointTrajectory &desired,
                                  const Eigen::VectorXd &phi);

} // namespace learnid
