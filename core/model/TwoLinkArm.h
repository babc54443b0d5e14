#pragma once

#include "model/RobotModel.h"

namespace learnid {

/// The paper's direct-drive planar 2-link arm (horizontal, no gravity), eq. (21)-(23).
/// theta2 is an absolute angle (measured from the base x axis, like theta1). With
/// d = theta2 - theta1:
///   M = [a, b cos d; b cos d, c],   h = [-b qd2^2 sin d; b qd1^2 sin d],
///   W = [qdd1, qdd2 cos d - qd2^2 sin d, 0; 0, qdd1 cos d + qd1^2 sin d, qdd2],
///   phi = [a, b, c] [kg m^2].
/// The paper's expressions of a, b, c in masses and lengths are not used: phi is identified as
/// three free parameters (docs/method.md §4).
class TwoLinkArm final : public RobotModel
{
public:
    QString id() const override { return QStringLiteral("paper-2link"); }
    int dof() const override { return 2; }
    int parameterCount() const override { return 3; }
    QList<ParameterInfo> parameters() const override;

    void regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                   Eigen::Ref<Eigen::MatrixXd> out) const override;
    /// One tight loop over the samples: no per-sample call, one sin/cos per 8 samples (rotated
    /// in between); equal to regressor() per sample to a few ulp.
    void regressorSeries(const Eigen::Ref<const Eigen::MatrixXd> &q,
                         const Eigen::Ref<const Eigen::MatrixXd> &qd,
                         const Eigen::Ref<const Eigen::MatrixXd> &qdd,
                         Eigen::Ref<Eigen::MatrixXd> out) const override;
    void massMatrix(const VectorRef &q, const VectorRef &phi,
                    Eigen::Ref<Eigen::MatrixXd> out) const override;
    void biasTorque(const VectorRef &q, const VectorRef &qd, const VectorRef &phi,
                    Eigen::Ref<Eigen::VectorXd> out) const override;
    void inverseDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                         const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const override;
    void forwardDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &tau,
                         const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const override;
    /// RK4 with one sin/cos of theta2 - theta1 per step: the stages rotate it by their small
    /// angle increments (the simulator's inner loop).
    void rk4Step(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                 const VectorRef &tau, const VectorRef &phi, double h) const override;
};

} // namespace learnid
