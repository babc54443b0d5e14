#include "session/ScenarioRobot.h"

namespace learnid {

std::shared_ptr<SimulatedRobot> makeSimulatedRobot(const Scenario &scenario,
                                                   std::shared_ptr<const RobotModel> model)
{
    MeasurementOptions measurement;
    measurement.encoderCounts = scenario.encoderCounts;
    measurement.torqueNoise = scenario.torqueNoise;
    measurement.seed = scenario.seed;
    measurement.substeps = scenario.substeps;
    return std::make_shared<SimulatedRobot>(std::move(model), scenario.trueParameters, measurement);
}

} // namespace learnid
