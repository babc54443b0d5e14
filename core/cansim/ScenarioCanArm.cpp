#include "cansim/ScenarioCanArm.h"

#include "session/TrialPlanner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace learnid {

CanArmSettings canArmSettings(const Scenario &scenario, std::shared_ptr<const RobotModel> model,
                              const QList<int> &nodes)
{
    CanArmSettings s;
    // The path's first sample is the inverse kinematics of its start point (planLine()).
    const TrialPlanner planner(scenario, model);
    s.initialPose = planner.kinematics().inverse(scenario.line.start, Eigen::VectorXd());
    s.model = std::move(model);
    s.trueParameters = scenario.simulation.trueParameters;
    s.measurement.encoderCounts = scenario.simulation.encoderCounts;
    s.measurement.torqueNoise = scenario.simulation.torqueNoise;
    s.measurement.seed = scenario.simulation.seed;
    s.measurement.substeps = scenario.simulation.substeps;
    s.controller = scenario.controller;
    s.torqueLimits = scenario.torqueLimits;
    s.nodes = nodes;
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
        nodes.insert(QString::number(node->node()),
                     QJsonObject{{QStringLiteral("storedParameters"), values}});
    }
    return QJsonDocument(QJsonObject{{QStringLiteral("nodes"), nodes}})
        .toJson(QJsonDocument::Indented);
}

} // namespace learnid
