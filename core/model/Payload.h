#pragma once

#include "model/ChainModel.h"
#include "model/SerialChain.h"

#include <Eigen/Core>
#include <QString>
#include <QStringList>
#include <memory>

namespace learnid {

/// A payload as a technician describes it (docs/payload.md): a rigid body of mass m [kg] whose
/// centre of mass is at com [m] and whose rotational inertia about that centre is
/// inertiaAtCom [kg m^2] (3 x 3, symmetric), all in the frame of the link it is fixed to.
struct PayloadBody
{
    double mass = 0.0;
    Eigen::Vector3d com = Eigen::Vector3d::Zero();
    Eigen::Matrix3d inertiaAtCom = Eigen::Matrix3d::Zero();

    /// Its 10 standard parameters about the link frame's origin (SerialChain.h's order:
    /// m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz), by the parallel axis theorem.
    InertialParameters parameters() const { return inertialParameters(mass, com, inertiaAtCom); }
};

/// The body of 10 standard parameters: c = h / m, I_c = I - m (|c|^2 E - c c^T).
/// Throws Error when the mass is not positive or an entry is not finite.
PayloadBody payloadBody(const InertialParameters &pi);

/// The index of the moving joint whose body is `link` in chain (its ChainJoint::link); an empty
/// link means the tip (the last joint). Throws Error naming the link and listing the chain's
/// links when it is not one of them.
int payloadJointOf(const SerialChain &chain, const QString &link);

/// The arm with a payload fixed to one of its links. A body fixed to link k adds its 10
/// standard parameters to link k's (both about link k's frame origin, in its axes), so with
/// the arm's standard parameters pi_arm held fixed
///   tau = Y(q, qd, qdd) (pi_arm + E_k pi_L) = tau_arm + Y_k pi_L,
/// Y_k the 10 columns of link k in ChainModel::standardRegressor (the payload's regressor) and
/// tau_arm the fixed arm's torque (friction and offsets included), which the fit subtracts.
/// q, qd, qdd: joint positions, velocities, accelerations (n); torques [N m or N] (n).
class PayloadModel
{
public:
    using VectorRef = Eigen::Ref<const Eigen::VectorXd>;

    /// armStandard: the arm's standard parameters (arm->standardCount()); link as
    /// payloadJointOf(). Throws Error for a wrong size, a non-finite entry or an unknown link.
    PayloadModel(std::shared_ptr<const ChainModel> arm, Eigen::VectorXd armStandard,
                 const QString &link = {});

    const ChainModel &arm() const { return *m_arm; }
    const Eigen::VectorXd &armStandard() const { return m_armStandard; }
    int dof() const { return m_arm->dof(); }
    int joint() const { return m_joint; } ///< k: the payload's link is joint k's body
    QString link() const;                 ///< that link's name

    /// The payload's regressor Y_k (n x 10) and the arm's torque tau_arm (n) at one state.
    void evaluate(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                  Eigen::Ref<Eigen::MatrixXd> payloadRegressor,
                  Eigen::Ref<Eigen::VectorXd> armTorque) const;
    Eigen::MatrixXd regressorAt(const VectorRef &q, const VectorRef &qd,
                                const VectorRef &qdd) const;
    Eigen::VectorXd armTorqueAt(const VectorRef &q, const VectorRef &qd,
                                const VectorRef &qdd) const;
    /// tau_arm + Y_k payload: the torque of the arm carrying the payload.
    Eigen::VectorXd torqueAt(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                             const InertialParameters &payload) const;
    /// The arm's standard parameters with the payload merged into its link: the fixed model of
    /// arm and payload (for a simulated robot, a feedforward, a URDF export).
    Eigen::VectorXd standardWith(const InertialParameters &payload) const;

private:
    std::shared_ptr<const ChainModel> m_arm;
    Eigen::VectorXd m_armStandard;
    int m_joint = 0;
};

/// The base parameters a payload adds to arm's (ChainModel::baseFromStandard of the payload's
/// 10 parameters on joint `joint`'s link, zero elsewhere): the base parameters are linear in the
/// standard ones, so phi_arm + this is the arm carrying the payload.
Eigen::VectorXd payloadBaseShift(const ChainModel &arm, int joint,
                                 const InertialParameters &payload);

} // namespace learnid
