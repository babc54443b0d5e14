#include "model/ChainModel.h"

#include "model/ChainParameterInfo.h"
#include "model/Error.h"

#include <Eigen/Cholesky>
#include <QCoreApplication>
#include <cmath>
#include <random>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ChainModel)
};

// Regressor rows at random states for the base parameters: positions within the joint limits
// (within +-pi, or +-1 m, where there are none), velocities and accelerations of order 1.
// A fixed seed: the same chain always gives the same base parameters.
Eigen::MatrixXd randomRows(const ChainModel &model)
{
    const int n = model.dof();
    const int p = model.standardCount();
    const int states = 4 * p / n + 20;
    std::mt19937_64 random(20261123);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Eigen::MatrixXd rows(Eigen::Index(states) * n, p);
    Eigen::VectorXd q(n), qd(n), qdd(n);
    for (int s = 0; s < states; ++s) {
        for (int j = 0; j < n; ++j) {
            const ChainJoint &joint = model.chain().joints[size_t(j)];
            const double reach = joint.type == JointType::Prismatic ? 1.0 : M_PI;
            const double lo = std::max(joint.lower, -reach), hi = std::min(joint.upper, reach);
            q[j] = 0.5 * (lo + hi) + 0.5 * (hi - lo) * unit(random);
            qd[j] = 2.0 * unit(random);
            qdd[j] = 5.0 * unit(random);
        }
        model.standardRegressor(q, qd, qdd, rows.middleRows(Eigen::Index(s) * n, n));
    }
    return rows;
}

} // namespace

ChainModel::ChainModel(const SerialChain &chain, const JointTerms &terms, const QString &id)
    : m_id(id)
    , m_dynamics(chain)
    , m_terms(terms)
    , m_standardCount(10 * chain.dof() + chain.dof() * terms.count())
{
    if (!(terms.coulombVelocity > 0.0)) {
        throw Error(Text::tr("the Coulomb friction's velocity scale must be positive (it is %1)")
                        .arg(terms.coulombVelocity));
    }
    m_cad = standardOf(chain);
    m_standardInfo = standardParameterInfo(chain, terms);
    m_base = BaseParameters::fromRegressor(randomRows(*this));
    // pi_I = phi - beta cad_D, and baseFromStandard(cad) = cad_I + beta cad_D.
    m_priorShift = m_base.baseFromStandard(m_cad);
    for (int i = 0; i < m_base.baseCount(); ++i)
        m_priorShift[i] -= m_cad[m_base.independent()[size_t(i)]];
    QStringList names;
    for (const ParameterInfo &info : m_standardInfo)
        names << info.name;
    for (int i = 0; i < m_base.baseCount(); ++i) {
        const ParameterInfo &lead = m_standardInfo[m_base.independent()[size_t(i)]];
        m_baseInfo.append({m_base.describe(i, names), lead.unit,
                           m_base.beta().row(i).isZero()
                               ? lead.description
                               : Text::tr("a combination led by the %1").arg(lead.description),
                           lead.group});
    }
}

Eigen::VectorXd ChainModel::standardOf(const SerialChain &chain) const
{
    const int n = dof();
    if (chain.dof() != n) {
        throw Error(Text::tr("%1 has %2 moving joints, the model %3 has %4")
                        .arg(chain.name)
                        .arg(chain.dof())
                        .arg(m_id)
                        .arg(n));
    }
    Eigen::VectorXd pi = Eigen::VectorXd::Zero(m_standardCount);
    for (int k = 0; k < n; ++k) {
        const ChainJoint &joint = chain.joints[size_t(k)];
        pi.segment<10>(10 * k) = joint.inertial;
        Eigen::Index at = 10 * n + Eigen::Index(k) * m_terms.count();
        if (m_terms.armature)
            pi[at++] = joint.armature;
        if (m_terms.viscous)
            pi[at++] = joint.damping;
        if (m_terms.coulomb)
            pi[at++] = joint.friction;
        if (m_terms.offset)
            pi[at++] = joint.offset;
    }
    return pi;
}

std::vector<int> ChainModel::nonnegativeStandard() const
{
    std::vector<int> out;
    const int n = dof();
    for (int j = 0; j < n; ++j) {
        int at = 10 * n + j * m_terms.count();
        for (const bool on : {m_terms.armature, m_terms.viscous, m_terms.coulomb}) {
            if (on)
                out.push_back(at++);
        }
    }
    return out;
}

Eigen::VectorXd ChainModel::baseFromStandard(const Eigen::VectorXd &pi) const
{
    return m_base.baseFromStandard(pi);
}

Eigen::VectorXd ChainModel::standardFromBase(const Eigen::VectorXd &phi) const
{
    return m_base.standardFromBase(phi, m_cad);
}

void ChainModel::fillStandard(const VectorRef &phi, StandardVector &pi) const
{
    pi = m_cad;
    for (int i = 0; i < m_base.baseCount(); ++i)
        pi[m_base.independent()[size_t(i)]] = phi[i] - m_priorShift[i];
}

void ChainModel::standardRegressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                                   Eigen::Ref<Eigen::MatrixXd> out) const
{
    const int n = dof();
    m_dynamics.regressor(q, qd, qdd, out.leftCols(10 * n));
    out.rightCols(m_standardCount - 10 * n).setZero();
    const int t = m_terms.count();
    for (int j = 0; j < n; ++j) {
        Eigen::Index at = 10 * n + Eigen::Index(j) * t;
        if (m_terms.armature)
            out(j, at++) = qdd[j];
        if (m_terms.viscous)
            out(j, at++) = qd[j];
        if (m_terms.coulomb)
            out(j, at++) = std::tanh(qd[j] / m_terms.coulombVelocity);
        if (m_terms.offset)
            out(j, at++) = 1.0;
    }
}

void ChainModel::regressor(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                           Eigen::Ref<Eigen::MatrixXd> out) const
{
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, ChainDynamics::maxJoints, maxStandard>
        full(dof(), m_standardCount);
    standardRegressor(q, qd, qdd, full);
    for (int i = 0; i < m_base.baseCount(); ++i)
        out.col(i) = full.col(m_base.independent()[size_t(i)]);
}

void ChainModel::addJointTerms(const VectorRef &qd, const double *qdd, const StandardVector &pi,
                               Eigen::Ref<Eigen::VectorXd> out) const
{
    const int n = dof();
    const int t = m_terms.count();
    for (int j = 0; j < n; ++j) {
        Eigen::Index at = 10 * n + Eigen::Index(j) * t;
        if (m_terms.armature) {
            if (qdd)
                out[j] += pi[at] * qdd[j];
            ++at;
        }
        if (m_terms.viscous)
            out[j] += pi[at++] * qd[j];
        if (m_terms.coulomb)
            out[j] += pi[at++] * std::tanh(qd[j] / m_terms.coulombVelocity);
        if (m_terms.offset)
            out[j] += pi[at++];
    }
}

void ChainModel::massMatrix(const VectorRef &q, const VectorRef &phi,
                            Eigen::Ref<Eigen::MatrixXd> out) const
{
    StandardVector pi;
    fillStandard(phi, pi);
    m_dynamics.massMatrix(q, pi.head(10 * dof()), out);
    if (m_terms.armature) {
        for (int j = 0; j < dof(); ++j)
            out(j, j) += pi[10 * dof() + j * m_terms.count()];
    }
}

void ChainModel::biasTorque(const VectorRef &q, const VectorRef &qd, const VectorRef &phi,
                            Eigen::Ref<Eigen::VectorXd> out) const
{
    StandardVector pi;
    fillStandard(phi, pi);
    const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, ChainDynamics::maxJoints, 1> zero =
        Eigen::VectorXd::Zero(dof());
    m_dynamics.inverseDynamics(q, qd, zero, pi.head(10 * dof()), out);
    addJointTerms(qd, nullptr, pi, out);
}

void ChainModel::inverseDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &qdd,
                                 const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const
{
    StandardVector pi;
    fillStandard(phi, pi);
    m_dynamics.inverseDynamics(q, qd, qdd, pi.head(10 * dof()), out);
    addJointTerms(qd, qdd.data(), pi, out);
}

void ChainModel::forwardDynamics(const VectorRef &q, const VectorRef &qd, const VectorRef &tau,
                                 const VectorRef &phi, Eigen::Ref<Eigen::VectorXd> out) const
{
    constexpr int maxN = ChainDynamics::maxJoints;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, maxN, maxN> m(dof(), dof());
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, maxN, 1> h(dof());
    StandardVector pi;
    fillStandard(phi, pi);
    m_dynamics.massMatrixAndBias(q, qd, pi.head(10 * dof()), m, h);
    if (m_terms.armature) {
        for (int j = 0; j < dof(); ++j)
            m(j, j) += pi[10 * dof() + j * m_terms.count()];
    }
    addJointTerms(qd, nullptr, pi, h);
    out = tau - h;
    const Eigen::LLT<decltype(m)> llt(m);
    llt.solveInPlace(out);
}

void ChainModel::rk4Step(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> qd,
                         const VectorRef &tau, const VectorRef &phi, double h) const
{
    using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, ChainDynamics::maxJoints, 1>;
    const int n = dof();
    Vec a1(n), a2(n), a3(n), a4(n), v2(n), v3(n), v4(n), qs(n);
    forwardDynamics(q, qd, tau, phi, a1);
    v2 = qd + 0.5 * h * a1;
    qs = q + 0.5 * h * qd;
    forwardDynamics(qs, v2, tau, phi, a2);
    v3 = qd + 0.5 * h * a2;
    qs = q + 0.5 * h * v2;
    forwardDynamics(qs, v3, tau, phi, a3);
    v4 = qd + h * a3;
    qs = q + h * v3;
    forwardDynamics(qs, v4, tau, phi, a4);
    q += (h / 6.0) * (qd + 2.0 * v2 + 2.0 * v3 + v4);
    qd += (h / 6.0) * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
}

QStringList jointNames(const RobotModel &model)
{
    QStringList names;
    if (const auto *chain = dynamic_cast<const ChainModel *>(&model))
        for (const ChainJoint &joint : chain->chain().joints)
            names << joint.name;
    return names;
}

} // namespace learnid
