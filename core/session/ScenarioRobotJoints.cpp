#include "session/ScenarioRobotJoints.h"

#include "model/ChainModel.h"
#include "model/Error.h"

#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ScenarioRobot)
};

[[noreturn]] void throwAtKey(const QString &path, const QString &what);

// The true robot's Coulomb friction per joint [N m]; zero where the model has no Coulomb term.
// With stribeck, linkPhi becomes the true parameters without them.
Eigen::VectorXd trueCoulomb(const Scenario &s, const RobotModel &model, Eigen::VectorXd &linkPhi)
{
    const int n = model.dof();
    Eigen::VectorXd fc = Eigen::VectorXd::Zero(n);
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain || !chain->jointTerms().coulomb)
        return fc;
    const JointTerms &terms = chain->jointTerms();
    Eigen::VectorXd pi = chain->standardFromBase(s.simulation.trueParameters);
    for (int j = 0; j < n; ++j) {
        const Eigen::Index at =
            10 * n + Eigen::Index(j) * terms.count() + int(terms.armature) + int(terms.viscous);
        fc[j] = pi[at];
        pi[at] = 0.0;
    }
    linkPhi = chain->baseFromStandard(pi);
    return fc;
}

// The link's own rotational inertia about its joint axis [kg m^2] (the CAD link).
Eigen::VectorXd ownAxisInertia(const Scenario &s, const RobotModel &model)
{
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain) {
        throwAtKey(QStringLiteral("simulation.armatureFactor"),
                   Text::tr("needs a URDF robot (the link's inertia about its axis); %1 has "
                            "none: give simulation.armature in kg m^2")
                       .arg(s.model));
    }
    Eigen::VectorXd own(model.dof());
    for (int j = 0; j < model.dof(); ++j) {
        const ChainJoint &joint = chain->chain().joints[size_t(j)];
        own[j] = joint.axis.dot(rotationalInertia(joint.inertial) * joint.axis);
    }
    return own;
}

[[noreturn]] void throwAtKey(const QString &path, const QString &what)
{
    throw Error(QStringLiteral("%1: %2").arg(path, what));
}

} // namespace

JointRealism simulatedJoints(const Scenario &s, const RobotModel &model)
{
    const SimulationSettings &sim = s.simulation;
    const int n = model.dof();
    JointRealism r;
    if (sim.staticFriction.size() > 0 || sim.staticFrictionRatio > 0.0) {
        r.coulomb = trueCoulomb(s, model, r.linkParameters);
        r.staticFriction = sim.staticFriction.size() > 0
                               ? sim.staticFriction
                               : Eigen::VectorXd(sim.staticFrictionRatio * r.coulomb);
        r.stribeckVelocity = sim.stribeckVelocity;
        for (int j = 0; j < n; ++j) {
            if (r.staticFriction[j] < r.coulomb[j]) {
                throwAtKey(QStringLiteral("simulation.staticFriction[%1]").arg(j),
                           Text::tr("must be at least the simulated robot's Coulomb friction "
                                    "of joint %1, %2 N m, got %3")
                               .arg(j + 1)
                               .arg(r.coulomb[j], 0, 'g', 6)
                               .arg(r.staticFriction[j], 0, 'g', 6));
            }
        }
    }
    if (sim.armature.size() > 0 || sim.armatureFactor.size() > 0) {
        r.armature = sim.armature.size() > 0 ? sim.armature : Eigen::VectorXd::Zero(n);
        if (sim.armatureFactor.size() > 0)
            r.armature += sim.armatureFactor.cwiseProduct(ownAxisInertia(s, model));
    }
    if (sim.jointStiffness.size() > 0) {
        for (int j = 0; j < n; ++j) {
            if (r.armature.size() == 0 || !(r.armature[j] > 0.0)) {
                throwAtKey(QStringLiteral("simulation.jointStiffness"),
                           Text::tr("an elastic joint needs its motor's rotor inertia: give "
                                    "simulation.armature or simulation.armatureFactor above 0 "
                                    "for joint %1")
                               .arg(j + 1));
            }
        }
        r.stiffness = sim.jointStiffness;
        r.damping = sim.jointDamping.size() > 0 ? sim.jointDamping : Eigen::VectorXd::Zero(n);
        r.linkSideEncoder = sim.linkSideEncoder;
    }
    r.sensorOffset = sim.torqueSensorOffset;
    r.sensorLag = sim.torqueSensorLag;
    return r;
}

} // namespace learnid
