#include "session/RobotScenario.h"

#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "model/Payload.h"
#include "model/PayloadPrior.h"
#include "session/SafetyCheck.h"
#include "session/ScenarioRobot.h"
#include "session/TrialPlanner.h"

#include <Eigen/LU>
#include <QCoreApplication>
#include <QFileInfo>
#include <algorithm>
#include <cmath>
#include <limits>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(RobotScenario)
};

constexpr double kBandwidth = 25.0; ///< closed-loop bandwidth the default gains aim at [rad/s]
/// Share of a joint's torque limit its Coulomb friction may reach on the real robot, whatever
/// the CAD model says: geared joints lose a few per cent of their rated torque to friction (the
/// KUKA LWR4+'s recorded logs: 0.3 to 1.2 N m on limits of 38 to 176 N m, where its CAD model
/// says 0.2 N m everywhere).
constexpr double kFrictionShareOfLimit = 0.01;
/// What the gains must hold of a payload on top of friction: half the prior's gravity torque (the
/// technician's mass may well be off by half) plus its weight at a centre of mass moved by
/// payloadPriorShare of the bound's size (10 cm in the default sphere) in any direction.
constexpr double kPayloadPriorError = 0.5;

// The Coulomb friction the gains must hold: the CAD's, or kFrictionShareOfLimit of the joint's
// torque limit when that is more.
double designFriction(const ChainJoint &joint)
{
    const double limit = joint.effortLimit;
    const double share = std::isfinite(limit) && limit > 0.0 ? kFrictionShareOfLimit * limit : 0.0;
    return std::max(joint.friction, share);
}
/// Damping ratio: critical damping leaves the 7-axis arms' coupled loops a slow mode at the
/// edge of stability when they move (Coriolis terms); 1.5 keeps every built-in robot stable.
constexpr double kDamping = 1.5;

// The middle of a joint's range and how far the default path moves it: a fifth of the range,
// at most 0.5 rad (0.05 m); a joint without limits moves about 0.
void jointSpan(const ChainJoint &joint, double &middle, double &amplitude)
{
    const bool prismatic = joint.type == JointType::Prismatic;
    const double cap = prismatic ? 0.05 : 0.5;
    if (!std::isfinite(joint.lower) || !std::isfinite(joint.upper) || joint.upper <= joint.lower) {
        middle = 0.0;
        amplitude = cap;
        return;
    }
    middle = 0.5 * (joint.lower + joint.upper);
    amplitude = std::min(cap, 0.2 * (joint.upper - joint.lower));
}

// The controller of scenario `s` for its clock. The bandwidth rule assumes about 2 ms; a slower
// clock lags the fast loops by half a sample more (the zero-order hold), and a derivative gain
// large for a light joint (kd Ts over its lightest inertia near 1) then makes the discrete loop
// unstable: on the Panda with 3 kg at 4 ms, its joints 1 and 3 (their kd, not their kp, moves
// the pole). While the pre-trial check of `s` (its first trial, gentle or not, and a full-speed
// one, planned with the arm `phi`, the CAD arm carrying the payload's prior) finds the closed
// loop unstable at its sample period, kd is lowered by 0.8 at the joints whose kd Ts / inertia
// is within 90 % of the largest. A design already stable is left as it is, and so is one whose
// trial cannot be planned (the pre-trial check says why). Throws Error when 20 steps do not make
// it stable.
ControllerSettings softenedForClock(const Scenario &s,
                                    const std::shared_ptr<const RobotModel> &model,
                                    const Eigen::VectorXd &phi, const Eigen::VectorXd &inertia)
{
    ControllerSettings c = s.controller;
    std::vector<TrialPlan> plans; // the gentle first trial's and a full-speed one's
    try {
        const TrialPlanner planner(withRobotDefaults(s, *model), model);
        plans = {planner.plan(phi, nullptr, s.gentleTrials > 0), planner.plan(phi)};
    } catch (const Error &) {
        return c;
    }
    for (int step = 0;; ++step) {
        SafetyVerdict v;
        for (TrialPlan &plan : plans) {
            plan.controller = c;
            if (const SafetyVerdict w = checkTrial(*model, phi, plan);
                !w.physical || w.worstSpectralRadius > v.worstSpectralRadius)
                v = w;
        }
        if (v.stable || !v.physical)
            return c;
        if (step == 20)
            throw Error(Text::tr("controller.samplePeriod: the starter's gains do not hold the arm "
                                 "in discrete time at %1 ms, even with the derivative gains "
                                 "lowered (a pole at |z| = %2)")
                            .arg(1000.0 * c.samplePeriod)
                            .arg(v.worstSpectralRadius, 0, 'f', 4));
        const Eigen::VectorXd speed = c.kd.cwiseQuotient(inertia);
        const double fastest = speed.maxCoeff();
        for (int j = 0; j < c.dof(); ++j) {
            if (speed[j] >= 0.9 * fastest)
                c.kd[j] *= 0.8;
        }
    }
}

QString valueText(double v, bool prismatic)
{
    return prismatic ? Text::tr("%1 m").arg(v, 0, 'f', 4)
                     : Text::tr("%1 deg").arg(v * 180.0 / M_PI, 0, 'f', 2);
}

} // namespace

Scenario scenarioForRobot(const QString &modelId, const UrdfRobotSettings &urdf,
                          const PayloadSettings &payload, double samplePeriod)
{
    Scenario s;
    if (!isUrdfModel(modelId)) {
        if (!knownRobotModels().contains(modelId))
            throw Error(Text::tr("robot.model: unknown model \"%1\"").arg(modelId));
        if (payload.enabled)
            throw Error(Text::tr("payload: only a URDF robot carries a payload"));
        if (std::abs(samplePeriod - s.controller.samplePeriod) > 1e-12)
            throw Error(Text::tr("controller.samplePeriod: the paper scenario is the paper's, at "
                                 "%1 ms; pick a URDF robot for another clock")
                            .arg(1000.0 * s.controller.samplePeriod));
        return s; // the paper scenario
    }
    s.model = modelId;
    s.urdf = urdf;
    // A geared joint's rotor inertia, as the joint sees it, is of the order of its link's own
    // inertia about the axis, and no URDF holds it: the model learns it (docs/benchmarks.md,
    // "Realistic robots": robot (c) with it unmodelled levels off higher).
    s.urdf.jointTerms.armature = true;
    const auto model = makeRobotModel(modelId, s.urdf); // the scenario's model designs the gains
    const auto *chain = dynamic_cast<const ChainModel *>(model.get());
    const int n = model->dof();
    Eigen::VectorXd middle(n), amplitude(n);
    for (int j = 0; j < n; ++j)
        jointSpan(chain->chain().joints[size_t(j)], middle[j], amplitude[j]);
    Eigen::VectorXd sign(n);
    for (int j = 0; j < n; ++j)
        sign[j] = j % 2 == 0 ? 1.0 : -1.0;
    s.path.kind = PathKind::Waypoints;
    s.path.waypoints = {middle, middle + amplitude.cwiseProduct(sign),
                        middle - amplitude.cwiseProduct(sign)};

    // The smallest inertia each joint's controller sees along the path (at the waypoints and
    // halfway), with the CAD parameters: 1 / (M^-1)_jj, the joint's inertia when the others
    // give way (the other controllers are as soft as its own). Gains sized for it keep the
    // loop within its bandwidth where the joint is lightest.
    const Eigen::VectorXd bare = chain->baseFromStandard(chain->cadStandard());
    // With a payload, the arm carrying the technician's prior body.
    Eigen::VectorXd cad = bare;
    // The gravity torque a prior centre of mass moved by `offset` in any direction adds at each
    // joint: m offset |dg_j/d(m c)| (the payload regressor's first-moment columns at rest).
    Eigen::VectorXd payloadOffsetTorque = Eigen::VectorXd::Zero(n);
    std::unique_ptr<PayloadModel> payloadModel;
    double offsetMass = 0.0;
    if (payload.enabled) {
        const PayloadPrior prior = payloadPriorOf(payload);
        validatePayloadPrior(prior);
        try {
            cad += payloadBaseShift(*chain, payload.link, prior.parameters());
        } catch (const Error &e) { // the link is not the arm's
            throw Error(QStringLiteral("payload.link: %1").arg(e.message()));
        }
        const double size = prior.bound.box
                                ? 0.5 * (prior.bound.upper - prior.bound.lower).minCoeff()
                                : prior.bound.radius;
        offsetMass = prior.mass * payloadPriorShare * size;
        payloadModel = std::make_unique<PayloadModel>(
            std::dynamic_pointer_cast<const ChainModel>(model), chain->cadStandard(), payload.link);
        s.payload = payload;
    }
    Eigen::VectorXd inertia = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
    Eigen::VectorXd heaviest = Eigen::VectorXd::Zero(n); ///< max M_jj along the path
    Eigen::VectorXd gravityShare = Eigen::VectorXd::Zero(n), gravity(n), shifted(n);
    Eigen::VectorXd gravityStiffness = Eigen::VectorXd::Zero(n); ///< max |dg_j/dq_j| [N m/rad]
    Eigen::VectorXd payloadGravity = Eigen::VectorXd::Zero(n);   ///< max |g_j - g_j(bare)| [N m]
    Eigen::VectorXd bareGravity(n);
    Eigen::MatrixXd mass(n, n);
    for (size_t w = 0; w < s.path.waypoints.size(); ++w) {
        const Eigen::VectorXd &a = s.path.waypoints[w];
        const Eigen::VectorXd &b = s.path.waypoints[(w + 1) % s.path.waypoints.size()];
        for (const Eigen::VectorXd &q : {a, Eigen::VectorXd(0.5 * (a + b))}) {
            model->massMatrix(q, cad, mass);
            inertia = inertia.cwiseMin(mass.inverse().diagonal().cwiseInverse());
            heaviest = heaviest.cwiseMax(mass.diagonal());
            model->biasTorque(q, Eigen::VectorXd::Zero(n), cad, gravity);
            model->biasTorque(q, Eigen::VectorXd::Zero(n), bare, bareGravity);
            payloadGravity = payloadGravity.cwiseMax((gravity - bareGravity).cwiseAbs());
            if (payloadModel) {
                const Eigen::MatrixXd y = payloadModel->regressorAt(q, Eigen::VectorXd::Zero(n),
                                                                    Eigen::VectorXd::Zero(n));
                payloadOffsetTorque =
                    payloadOffsetTorque.cwiseMax(offsetMass * y.middleCols(1, 3).rowwise().norm());
            }
            for (int j = 0; j < n; ++j) {
                Eigen::VectorXd qj = q;
                qj[j] += 1e-6;
                model->biasTorque(qj, Eigen::VectorXd::Zero(n), cad, shifted);
                gravityStiffness[j] =
                    std::max(gravityStiffness[j], std::abs(shifted[j] - gravity[j]) / 1e-6);
                const double limit = chain->chain().joints[size_t(j)].effortLimit;
                if (std::isfinite(limit) && limit > 0.0)
                    gravityShare[j] = std::max(gravityShare[j], std::abs(gravity[j]) / limit);
            }
        }
    }
    // Each joint as m s^2 + (fv + kd) s + kp: the bandwidth's m w^2 on top of what gravity
    // takes away where the link hangs above its joint (dg_j/dq_j), or stiff enough that the
    // CAD's Coulomb friction (and what a payload's prior may be off by) would move it by at most
    // 0.05 rad; then damped (kDamping) by the joint's own viscous friction and kd together. With
    // a payload the joint's inertia varies more along the path: the damping is sized for the
    // geometric mean of its lightest and its heaviest (M_jj), not the lightest alone (a Panda
    // with 1.5 kg, damped for the lightest, had a slow unstable pole at full speed).
    s.controller.kp.resize(n);
    s.controller.kd.resize(n);
    for (int j = 0; j < n; ++j) {
        const ChainJoint &joint = chain->chain().joints[size_t(j)];
        const double kp = std::max(inertia[j] * kBandwidth * kBandwidth + gravityStiffness[j],
                                   (designFriction(joint) + kPayloadPriorError * payloadGravity[j] +
                                    payloadOffsetTorque[j]) /
                                       0.05);
        const double damping =
            kDamping * 2.0 *
            std::sqrt(kp * (payload.enabled ? std::sqrt(heaviest[j] * inertia[j]) : inertia[j]));
        s.controller.kp[j] = kp;
        s.controller.kd[j] = std::max(damping - joint.damping, 0.1 * damping);
    }
    s.controller.ki = s.controller.kp * 0.1;
    s.controller.lambda = 1000.0;
    s.controller.samplePeriod = samplePeriod;
    // The paper's arm keeps its feedforward at the sample instant (the paper's figures); a new
    // robot gets the one without the hold's half-sample lag.
    s.controller.feedforwardTime = FeedforwardTime::MidSample;
    // The torque rule needs room above gravity: plan at 1.5 times the largest gravity share,
    // at least 30 % and at most 80 % of the limits.
    s.planningFraction = std::clamp(1.5 * gravityShare.maxCoeff(), 0.3, 0.8);
    // The CAD model of a robot new to the tool may be far from the real one (friction above
    // all): its first trial runs at half speed, a quarter of the inertial torque.
    s.gentleTrials = 1;
    s.gentleSpeed = 0.5;
    // A many-axis arm's wrist explains a hundredth of the shoulder's torque: at the paper's
    // tolerance 1e-3 its parameters stay at the CAD values. 1e-4 learns them; after a trial
    // stopped early, only the directions its short record determines to 30 % are learned
    // (docs/benchmarks.md, "Experiments on the observability rule").
    s.estimator.rankTolerance = 1e-4;
    s.estimator.partialMaxRelativeStd = 0.3;
    s.torqueLimits.resize(0);
    s.initialParameters.resize(0);
    s.simulation.trueParameters.resize(0);
    s.controller = softenedForClock(s, model, cad, inertia);
    if (payload.enabled) {
        // Baseline trials run the bare arm: with the bare arm's gains, since those that hold the
        // payload can leave a light wrist unstable without it (the PUMA 560's with 2 kg).
        const Scenario bareArm = scenarioForRobot(modelId, urdf, PayloadSettings(), samplePeriod);
        s.payload.baselineKp = bareArm.controller.kp;
        s.payload.baselineKi = bareArm.controller.ki;
        s.payload.baselineKd = bareArm.controller.kd;
    }
    s.simulation.inertiaPerturbation = 0.3;
    s.simulation.encoderCounts = 1 << 20;
    s.simulation.torqueNoise = 0.01;
    s.maxTrackingErrorDeg = 5.0;
    return s;
}

Scenario scenarioForRobotName(const QString &robot, const PayloadSettings &payload,
                              double samplePeriod)
{
    if (robot == QLatin1String("paper"))
        return scenarioForRobot(QStringLiteral("paper-2link"), {}, payload, samplePeriod);
    if (knownRobotModels().contains(robot) && robot != QLatin1String("urdf"))
        return scenarioForRobot(robot, {}, payload, samplePeriod);
    const QFileInfo file(robot);
    if (!robot.endsWith(QLatin1String(".urdf"), Qt::CaseInsensitive) && !file.isFile()) {
        QStringList known{QStringLiteral("paper")};
        for (const QString &id : knownRobotModels())
            if (isUrdfModel(id) && id != QLatin1String("urdf"))
                known << id;
        throw Error(Text::tr("unknown robot \"%1\"; known: %2, or a URDF file (FILE.urdf)")
                        .arg(robot, known.join(QStringLiteral(", "))));
    }
    UrdfRobotSettings urdf;
    urdf.file = file.absoluteFilePath();
    return scenarioForRobot(QStringLiteral("urdf"), urdf, payload, samplePeriod);
}

QString waypointLimitError(const RobotModel &model, const std::vector<Eigen::VectorXd> &waypoints)
{
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain)
        return {};
    for (size_t i = 0; i < waypoints.size(); ++i) {
        const Eigen::VectorXd &w = waypoints[i];
        for (int j = 0; j < std::min<int>(int(w.size()), chain->dof()); ++j) {
            const ChainJoint &joint = chain->chain().joints[size_t(j)];
            const bool prismatic = joint.type == JointType::Prismatic;
            const bool below = w[j]<joint.lower, above = w[j]> joint.upper;
            if (!below && !above)
                continue;
            return Text::tr("path.waypoints[%1][%2]: %3 is %4 joint %5 (%6)'s %7 limit %8")
                .arg(i)
                .arg(j)
                .arg(valueText(w[j], prismatic), below ? Text::tr("below") : Text::tr("above"))
                .arg(j + 1)
                .arg(joint.name, below ? Text::tr("lower") : Text::tr("upper"),
                     valueText(below ? joint.lower : joint.upper, prismatic));
        }
    }
    return {};
}

} // namespace learnid
