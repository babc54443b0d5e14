#include "session/ScenarioRobot.h"

#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/ChainPerturbation.h"
#include "model/Error.h"
#include "model/ModelCheck.h"
#include "model/Payload.h"
#include "model/PayloadPrior.h"
#include "model/UrdfChain.h"
#include "session/ScenarioRobotJoints.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ScenarioRobot)
};

// The real robot's URDF must have the CAD robot's joints, placed alike: only its inertia and
// friction may differ (the base parameters are those of the CAD kinematics).
Eigen::VectorXd realRobotStandard(const Scenario &s, const ChainModel &model)
{
    const SerialChain real = readUrdfChain(s.simulation.realUrdf, s.urdf.baseLink, s.urdf.tipLink);
    const SerialChain &cad = model.chain();
    if (real.dof() != cad.dof()) {
        throw Error(Text::tr("simulation.realUrdf: %1 has %2 moving joints, the robot %3")
                        .arg(s.simulation.realUrdf)
                        .arg(real.dof())
                        .arg(cad.dof()));
    }
    for (int j = 0; j < cad.dof(); ++j) {
        const ChainJoint &a = cad.joints[size_t(j)];
        const ChainJoint &b = real.joints[size_t(j)];
        if (a.type != b.type || !a.origin.isApprox(b.origin, 1e-9) ||
            !a.axis.isApprox(b.axis, 1e-9)) {
            throw Error(Text::tr("simulation.realUrdf: joint %1 (%2) is placed differently from "
                                 "the robot's URDF: the real robot may differ in inertia and "
                                 "friction only")
                            .arg(j + 1)
                            .arg(b.name));
        }
    }
    // A simulated robot must be one that could be built: the URDF's links real and plausible
    // bodies, its friction dissipative (docs/robots.md §7).
    const QStringList problems =
        modelProblems(model, real, realBodyPrior(model.cadStandard(), model.dof()));
    if (!problems.isEmpty()) {
        throw Error(Text::tr("simulation.realUrdf: %1 is not a robot that could be built: %2")
                        .arg(s.simulation.realUrdf, problems.join(QLatin1String("; "))));
    }
    return model.standardOf(real);
}

} // namespace

Scenario withRobotDefaults(const Scenario &scenario, const RobotModel &model)
{
    const auto *chain = dynamic_cast<const ChainModel *>(&model);
    if (!chain)
        return scenario;
    Scenario s = scenario;
    if (s.torqueLimits.size() == 0) {
        s.torqueLimits.resize(chain->dof());
        for (int j = 0; j < chain->dof(); ++j) {
            const ChainJoint &joint = chain->chain().joints[size_t(j)];
            if (!std::isfinite(joint.effortLimit)) {
                throw Error(Text::tr("robot.torqueLimits: joint %1 (%2) has no effort limit in "
                                     "the URDF: give the torque limits in the scenario")
                                .arg(j + 1)
                                .arg(joint.name));
            }
            s.torqueLimits[j] = joint.effortLimit;
        }
    }
    if (s.initialParameters.size() == 0)
        s.initialParameters = chain->baseFromStandard(chain->cadStandard());
    if (s.simulation.trueParameters.size() == 0) {
        const Eigen::VectorXd real =
            s.simulation.realUrdf.isEmpty()
                ? perturbedStandard(*chain, s.simulation.inertiaPerturbation, s.simulation.seed)
                : realRobotStandard(s, *chain);
        s.simulation.trueParameters = chain->baseFromStandard(real);
    }
    return s;
}

namespace {

std::shared_ptr<SimulatedRobot> simulatedRobot(const Scenario &scenario,
                                               std::shared_ptr<const RobotModel> model,
                                               quint64 firstNoiseStream)
{
    MeasurementOptions measurement;
    measurement.firstNoiseStream = firstNoiseStream;
    measurement.encoderCounts = scenario.simulation.encoderCounts;
    measurement.torqueNoise = scenario.simulation.torqueNoise;
    measurement.seed = scenario.simulation.seed;
    measurement.substeps = scenario.simulation.substeps;
    measurement.realism = simulatedJoints(scenario, *model);
    Eigen::VectorXd truePhi = simulatedTrueParameters(scenario, *model);
    return std::make_shared<SimulatedRobot>(std::move(model), std::move(truePhi), measurement);
}

} // namespace

std::shared_ptr<SimulatedRobot> makeSimulatedRobot(const Scenario &scenario,
                                                   std::shared_ptr<const RobotModel> model)
{
    return simulatedRobot(scenario, std::move(model), 0);
}

Eigen::VectorXd simulatedTrueParameters(const Scenario &scenario, const RobotModel &model)
{
    // The payload it carries adds to its link's body (docs/payload.md).
    Eigen::VectorXd truePhi = scenario.simulation.trueParameters;
    const InertialParameters payload =
        simulatedPayloadParameters(scenario.simulation.payload, scenario.payload);
    if (const auto *chain = dynamic_cast<const ChainModel *>(&model);
        chain && !payload.isZero() && truePhi.size() == chain->parameterCount()) {
        truePhi += payloadBaseShift(*chain, scenario.payload.link, payload);
    }
    return truePhi;
}

std::shared_ptr<SimulatedRobot> makeSimulatedBareRobot(const Scenario &scenario,
                                                       std::shared_ptr<const RobotModel> model)
{
    Scenario bare = scenario;
    bare.simulation.payload = SimulatedPayload();
    bare.payload.enabled = false;
    // One machine with its payload off: its own noise, not a replay of the loaded trials' (the
    // same streams would cancel the payload trials' noise against the baseline's).
    return simulatedRobot(bare, std::move(model), quint64(1) << 30);
}

} // namespace learnid
