#include "model/Payload.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Payload)
};

} // namespace

PayloadBody payloadBody(const InertialParameters &pi)
{
    if (!pi.allFinite())
        throw Error(Text::tr("the payload's inertial parameters are not finite"));
    if (!(pi[0] > 0.0))
        throw Error(Text::tr("the payload's mass must be positive (it is %1 kg)").arg(pi[0]));
    PayloadBody body;
    body.mass = pi[0];
    body.com = pi.segment<3>(1) / pi[0];
    const Eigen::Vector3d &c = body.com;
    body.inertiaAtCom =
        rotationalInertia(pi) -
        body.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    return body;
}

PayloadLink payloadLinkOf(const SerialChain &chain, const QString &link)
{
    if (chain.dof() == 0)
        throw Error(Text::tr("%1 has no moving link to carry a payload").arg(chain.name));
    if (link.isEmpty())
        return {chain.dof() - 1, chain.joints.back().link, Eigen::Isometry3d::Identity()};
    QStringList links;
    for (int k = 0; k < chain.dof(); ++k) {
        const ChainJoint &joint = chain.joints[size_t(k)];
        if (joint.link == link)
            return {k, link, Eigen::Isometry3d::Identity()};
        links << joint.link;
        for (const FixedLink &fixed : joint.fixedLinks) {
            if (fixed.name == link)
                return {k, link, fixed.pose};
            links << fixed.name;
        }
    }
    throw Error(Text::tr("payload link '%1' is not a moving link of %2 or a link fixed to one "
                         "(its links: %3)")
                    .arg(link, chain.name, links.join(QStringLiteral(", "))));
}

int payloadJointOf(const SerialChain &chain, const QString &link)
{
    return payloadLinkOf(chain, link).joint;
}

InertialParameters payloadInBody(const PayloadLink &link, const InertialParameters &payload)
{
    return transformedInertial(payload, link.pose.inverse());
}

PayloadModel::PayloadModel(std::shared_ptr<const ChainModel> arm, Eigen::VectorXd armStandard,
                           const QString &link)
    : m_arm(std::move(arm))
    , m_armStandard(std::move(armStandard))
{
    if (!m_arm)
        throw Error(Text::tr("a payload needs the arm's model"));
    if (m_armStandard.size() != m_arm->standardCount() || !m_armStandard.allFinite()) {
        throw Error(Text::tr("the arm's parameters for %1 must be %2 finite numbers")
                        .arg(m_arm->id())
                        .arg(m_arm->standardCount()));
    }
    m_link = payloadLinkOf(m_arm->chain(), link);
    // payloadInBody is linear in the parameters (the parallel axis theorem and a rotation).
    for (int i = 0; i < 10; ++i)
        m_toBody.col(i) = payloadInBody(m_link, InertialParameters::Unit(i));
}

void PayloadModel::evaluate(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                            Eigen::Ref<Eigen::MatrixXd> payloadRegressor,
                            Eigen::Ref<Eigen::VectorXd> armTorque) const
{
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, ChainDynamics::maxJoints,
                  ChainModel::maxStandard>
        y(dof(), m_arm->standardCount());
    m_arm->standardRegressor(q, qd, qdd, y);
    payloadRegressor.noalias() = y.middleCols<10>(10 * m_link.joint) * m_toBody;
    armTorque.noalias() = y * m_armStandard;
}

Eigen::MatrixXd PayloadModel::regressorAt(const VectorRef &q, const VectorRef &qd,
                                          const VectorRef &qdd) const
{
    Eigen::MatrixXd y(dof(), 10);
    Eigen::VectorXd tau(dof());
    evaluate(q, qd, qdd, y, tau);
    return y;
}

Eigen::VectorXd PayloadModel::armTorqueAt(const VectorRef &q, const VectorRef &qd,
                                          const VectorRef &qdd) const
{
    Eigen::MatrixXd y(dof(), 10);
    Eigen::VectorXd tau(dof());
    evaluate(q, qd, qdd, y, tau);
    return tau;
}

Eigen::VectorXd PayloadModel::torqueAt(const VectorRef &q, const VectorRef &qd,
                                       const VectorRef &qdd,
                                       const InertialParameters &payload) const
{
    Eigen::MatrixXd y(dof(), 10);
    Eigen::VectorXd tau(dof());
    evaluate(q, qd, qdd, y, tau);
    return tau + y * payload;
}

Eigen::VectorXd PayloadModel::standardWith(const InertialParameters &payload) const
{
    Eigen::VectorXd pi = m_armStandard;
    pi.segment<10>(10 * m_link.joint) += m_toBody * payload;
    return pi;
}

Eigen::VectorXd payloadBaseShift(const ChainModel &arm, const QString &link,
                                 const InertialParameters &payload)
{
    const PayloadLink where = payloadLinkOf(arm.chain(), link);
    Eigen::VectorXd pi = Eigen::VectorXd::Zero(arm.standardCount());
    pi.segment<10>(10 * where.joint) = payloadInBody(where, payload);
    return arm.baseFromStandard(pi);
}

} // namespace learnid
