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

/// The link a payload is fixed to: a moving link of the chain, or a link fixed to one and merged
/// into its body (a flange or tool frame, ChainJoint::fixedLinks). The payload's parameters are
/// given in this link's frame.
struct PayloadLink
{
    int joint = 0; ///< the moving joint whose body carries it
    QString name;  ///< the link's name
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity(); ///< its frame in that body's frame
};

/// The payload link `link` of chain (an empty link means the tip's body, the last joint's).
/// Throws Error naming the link and listing the chain's links when it is not one of them.
PayloadLink payloadLinkOf(const SerialChain &chain, const QString &link);
/// payloadLinkOf(chain, link).joint.
int payloadJointOf(const SerialChain &chain, const QString &link);
/// A payload's 10 parameters in `link`'s frame, expressed about its body's frame origin.
InertialParameters payloadInBody(const PayloadLink &link, const InertialParameters &payload);

/// The arm with a payload fixed to one of its links. A body fixed to link k adds its 10
/// standard parameters to link k's (both about link k's frame origin, in its axes), so with
/// the arm's standard parameters pi_arm held fixed
///   tau = Y(q, qd, qdd) (pi_arm + E_k pi_L) = tau_arm + Y_k pi_L,
/// Y_k the 10 columns of link k in ChainModel::standardRegressor (the payload's regressor) and
/// tau_arm the fixed arm's torque (friction and offsets included), which the fit subtracts.
/// For a link fixed to body k, pi_L is in that link's frame and Y_k is taken times the linear
/// map of payloadInBody(), so every estimate, prior and bound stays in the named link's frame.
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
    int joint() const { return m_link.joint; }   ///< k: the payload's link is on joint k's body
    QString link() const { return m_link.name; } ///< the payload link's name
    const PayloadLink &payloadLink() const { return m_link; }

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
    PayloadLink m_link;
    Eigen::Matrix<double, 10, 10> m_toBody; ///< payloadInBody() as a matrix
};

/// The base parameters a payload on `link` (as payloadLinkOf()) adds to arm's
/// (ChainModel::baseFromStandard of its 10 parameters on its body, zero elsewhere): the base
/// parameters are linear in the standard ones, so phi_arm + this is the arm carrying it.
Eigen::VectorXd payloadBaseShift(const ChainModel &arm, const QString &link,
                                 const InertialParameters &payload);

} // namespace learnid
