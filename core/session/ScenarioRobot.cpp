#include "session/ScenarioRobot.h"

namespace learnid {

std::shared_ptr<SimulatedRobot> makeSimulatedRobot(const Scenario &scenario,
                                                   std::shared_ptr<const RobotModel> model)
{
    MeasurementOptions measurement;
    measurement.encoderCounts = scenario.simulation.encoderCounts;
    measurement.torqueNoise = scenario.simulation.torqueNoise;
    measurement.seed = scenario.simulation.seed;
    measurement.substeps = scenario.simulation.substeps;
    return std::make_shared<SimulatedRobot>(std::move(model), scenario.simulation.trueParameters,
                                            measurement);
}

} // namespace learnid
