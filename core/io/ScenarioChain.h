#pragma once

#include "io/JsonReader.h"
#include "io/JsonTree.h"
#include "types/Scenario.h"

namespace learnid {

// The scenario keys of format 2 that describe any serial arm (docs/scenario.md): robot.urdf,
// robot.jointTerms, path.kind / waypoints / file and the simulated real robot. Used by
// ScenarioFile.cpp only.

void readUrdfRobot(JsonObjectReader r, UrdfRobotSettings &urdf);
void readJointTerms(JsonObjectReader r, JointTerms &terms);
/// path.kind, path.waypoints and path.file of the path section r.
void readJointPath(JsonObjectReader &r, JointPathSettings &path);

JsonTree urdfRobotJson(const UrdfRobotSettings &urdf);
JsonTree jointTermsJson(const JointTerms &terms);
/// Adds kind (and waypoints or file) to the path section.
void insertJointPath(JsonTree &pathSection, const JointPathSettings &path);

QString pathKindName(PathKind kind);

/// For a path of kind File: reads its CSV into path.fileTimes and path.fileAngles. Throws
/// Error "path.file: <file>: line L, column C: ..." for a bad file.
void loadJointPathFile(JointPathSettings &path);

/// Makes the scenario's relative file paths (URDF, path CSV, real robot's URDF) relative to
/// directory; absolute paths and Qt resources (":/...") stay.
void resolveScenarioPaths(Scenario &scenario, const QString &directory);

} // namespace learnid
