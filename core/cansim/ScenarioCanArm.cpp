#include "cansim/ScenarioCanArm.h"

#include "can/CanTimeouts.h"
#include "can/JointIdentity.h"
#include "session/ScenarioRobot.h"
#include "session/ScenarioRobotJoints.h"
#include "session/TrialPlanner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace learnid {

CanArmSettings canArmSettings(const Scenario &given, std::shared_ptr<const RobotModel> model,
                              const QList<int> &nodes)
{
    CanArmSettings s;
    // What a URDF robot leaves out of the scenario (torque limits, the simulated robot's true
    // parameters), as the session fills it in: the same seed gives the same robot.
    const Scenario scenario = withRobotDefaults(given, *model);
    // The arm rests at the path's first sample: the inverse kinematics of the line's start
    // point (planLine()), or the joint path at u = 0.
    const TrialPlanner planner(scenario, model);
    if (const JointPath *path = planner.jointPath()) {
        const int n = model->dof();
        Eigen::VectorXd dq(n), ddq(n);
        s.initialPose.resize(n);
        path->stateInto(0.0, s.initialPose, dq, ddq);
    } else {
        s.initialPose = planner.kinematics().inverse(scenario.line.start, Eigen::VectorXd());
    }
    // The drives come commissioned for this robot, joint j's drive as joint j (--uncommissioned
    // of learnid-robot-sim clears it).
    s.robotIdentity = objects::robotIdentityOf(model->id());
    // The arm carries the payload of a scenario's payload section from the start (there is no
    // one to take it off between trials).
    s.trueParameters = simulatedTrueParameters(scenario, *model);
    if (scenario.payload.enabled)
        s.bareParameters = scenario.simulation.trueParameters; // for the baseline trials
    s.model = std::move(model);
    s.measurement.encoderCounts = scenario.simulation.encoderCounts;
    s.measurement.torqueNoise = scenario.simulation.torqueNoise;
    s.measurement.seed = scenario.simulation.seed;
    s.measurement.substeps = scenario.simulation.substeps;
    s.measurement.realism = simulatedJoints(scenario, *s.model);
    s.controller = scenario.controller;
    s.torqueLimits = scenario.torqueLimits;
    s.nodes = nodes;
    s.setPointTimeoutSyncs = cantimeouts::setpointTimeoutSyncs(scenario.controller.samplePeriod);
    return s;
}

QByteArray simulatorStateJson(const CanArmSimulator &simulator)
{
    QJsonObject nodes;
    for (int j = 0; j < simulator.dof(); ++j) {
        const DriveNode *node = simulator.node(j);
        const Eigen::VectorXd phi = node->storedParameters();
        QJsonArray values;
        for (Eigen::Index i = 0; i < phi.size(); ++i)
            values.append(phi[i]);
        QJsonObject state{{QStringLiteral("storedParameters"), values}};
        // The stored payload: none before a payload session's apply.
        if (const int joint = node->storedSet().payloadJoint(); joint > 0) {
            QJsonArray body;
            for (const double v : node->storedSet().payloadParameters())
                body.append(v);
            state.insert(QStringLiteral("storedPayload"),
                         QJsonObject{{QStringLiteral("joint"), joint},
                                     {QStringLiteral("parameters"), body}});
        }
        nodes.insert(QString::number(node->node()), state);
    }
    return QJsonDocument(QJsonObject{{QStringLiteral("nodes"), nodes}})
        .toJson(QJsonDocument::Indented);
}

} // namespace learnid
