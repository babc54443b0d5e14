#pragma once

#include "types/Scenario.h"

#include <QByteArray>
#include <QString>

namespace learnid {

/// The "schema" of scenario files this version writes; it reads this and version 1 (the paper's
/// arm only, whose keys version 2 keeps).
inline constexpr char scenarioSchema[] = "learnid-scenario/2";
inline constexpr char scenarioSchemaVersion1[] = "learnid-scenario/1";

/// Limits of the scenario settings (docs/scenario.md), shared by the reader, validateScenario()
/// and editors that bound their inputs.
namespace scenarioLimits {
constexpr int maxIterations = 100;
constexpr int maxRepetitions = 20;
constexpr int maxSubsteps = 1000;
constexpr qint64 minEncoderCounts = 16; ///< besides 0 (ideal encoder)
constexpr qint64 maxEncoderCounts = qint64(1) << 31;
constexpr qint64 maxSeed = qint64(1) << 53;    ///< larger integers are not exact in JSON
constexpr double maxSamplePeriod = 0.1;        ///< [s]
constexpr double maxRest = 60.0;               ///< restBefore, restAfter [s]
constexpr double maxTorqueNoise = 1.0;         ///< standard deviation / torque limit
constexpr double maxInertiaPerturbation = 0.9; ///< simulated real robot vs CAD, a fraction
constexpr double maxJointStiffness = 1e7;      ///< [N m/rad]
constexpr double maxTorqueSensorLag = 1.0;     ///< [s]
} // namespace scenarioLimits

/// The scenario as indented JSON with every key, in the documented order (docs/scenario.md).
/// scenarioToJson(Scenario{}) is what `learnid-cli scenario --print` prints. Numbers read back
/// bit-exactly; values JSON cannot hold (NaN, inf) are written as null, which the reader
/// rejects.
QByteArray scenarioToJson(const Scenario &scenario);

/// Reads a scenario. Missing keys keep the defaults of Scenario{}; unknown keys, wrong types,
/// wrong lengths and values out of range are errors. Throws Error
/// "<sourceName>: <key path>: <problem>", e.g. "scenario.json: controller.kp[1]: must be a
/// positive number, got -5", or with line and byte offset for malformed JSON.
/// Relative file paths in it (robot.urdf.file, path.file, simulation.realUrdf) are taken
/// relative to directory (empty: the working directory).
Scenario scenarioFromJson(const QByteArray &json, const QString &sourceName,
                          const QString &directory = {});

/// readFile() then scenarioFromJson() with the path as the source name and relative paths
/// taken relative to the file's directory.
Scenario readScenarioFile(const QString &path);

/// scenarioToJson() written with writeFileAtomically().
void writeScenarioFile(const QString &path, const Scenario &scenario);

/// Checks a scenario however it was made (file, GUI, command line): vector lengths against the
/// model's joints and parameters, ranges, known model and law. Throws Error
/// "<key path>: <problem>" with the key path of the JSON form. Reachability of the path is
/// left to the planner.
void validateScenario(const Scenario &scenario);

/// The controller part of validateScenario(): samplePeriod in (0, 0.1] s, kp > 0, ki >= 0,
/// kd >= 0 with dof entries each, lambda > 0. path prefixes the key paths ("controller").
void validateControllerSettings(const ControllerSettings &controller, int dof, const QString &path);
/// The kp (> 0), ki and kd (>= 0) gains, one per joint, under `path` (path.kp, ...): the
/// controller's, or the baseline trials' (payload.baselineGains).
void validateJointGains(const Eigen::VectorXd &kp, const Eigen::VectorXd &ki,
                        const Eigen::VectorXd &kd, int dof, const QString &path);

} // namespace learnid
