#include "io/ScenarioChain.h"

#include "io/PathCsv.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ScenarioFile)
};

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

const std::pair<PathKind, const char *> pathKinds[] = {
    {PathKind::Line, "line"}, {PathKind::Waypoints, "waypoints"}, {PathKind::File, "file"}};

QString resolved(const QString &path, const QDir &directory)
{
    if (path.isEmpty() || path.startsWith(QLatin1String(":/")) || QFileInfo(path).isAbsolute())
        return path;
    return QDir::cleanPath(directory.filePath(path));
}

} // namespace

QString pathKindName(PathKind kind)
{
    return enumName(kind, pathKinds);
}

void readUrdfRobot(JsonObjectReader r, UrdfRobotSettings &urdf)
{
    r.read(key("file"), urdf.file);
    r.read(key("baseLink"), urdf.baseLink);
    r.read(key("tipLink"), urdf.tipLink);
    Eigen::VectorXd gravity = urdf.gravity;
    r.read(key("gravity"), gravity);
    if (gravity.size() != 3) {
        throwAtKey(r.keyPath(key("gravity")),
                   Text::tr("must have 3 entries (x, y, z in the base link's frame), got %1")
                       .arg(gravity.size()));
    }
    urdf.gravity = gravity;
    r.rejectUnknownKeys();
}

void readJointTerms(JsonObjectReader r, JointTerms &terms)
{
    r.read(key("armature"), terms.armature);
    r.read(key("viscous"), terms.viscous);
    r.read(key("coulomb"), terms.coulomb);
    r.read(key("offset"), terms.offset);
    r.read(key("coulombVelocity"), terms.coulombVelocity);
    r.rejectUnknownKeys();
}

void readJointPath(JsonObjectReader &r, JointPathSettings &path)
{
    const QJsonValue kind = r.value(key("kind"));
    if (!kind.isUndefined())
        path.kind = jsonEnum(kind, r.keyPath(key("kind")), pathKinds);
    const QJsonValue waypoints = r.value(key("waypoints"));
    if (!waypoints.isUndefined()) {
        const QString at = r.keyPath(key("waypoints"));
        const QJsonArray list = jsonArray(waypoints, at);
        path.waypoints.clear();
        for (int i = 0; i < list.size(); ++i)
            path.waypoints.push_back(jsonNumbers(list[i], jsonIndexPath(at, i)));
    }
    r.read(key("file"), path.file);
}

JsonTree urdfRobotJson(const UrdfRobotSettings &urdf)
{
    JsonTree t = JsonTree::object();
    t.insert(key("file"), urdf.file)
        .insert(key("baseLink"), urdf.baseLink)
        .insert(key("tipLink"), urdf.tipLink)
        .insert(key("gravity"), JsonTree::numbers(urdf.gravity));
    return t;
}

JsonTree jointTermsJson(const JointTerms &terms)
{
    JsonTree t = JsonTree::object();
    t.insert(key("armature"), terms.armature)
        .insert(key("viscous"), terms.viscous)
        .insert(key("coulomb"), terms.coulomb)
        .insert(key("offset"), terms.offset)
        .insert(key("coulombVelocity"), terms.coulombVelocity);
    return t;
}

void insertJointPath(JsonTree &pathSection, const JointPathSettings &path)
{
    pathSection.insert(key("kind"), pathKindName(path.kind));
    if (path.kind == PathKind::Waypoints) {
        JsonTree list = JsonTree::array();
        for (const Eigen::VectorXd &w : path.waypoints)
            list.append(JsonTree::numbers(w));
        pathSection.insert(key("waypoints"), list);
    } else if (path.kind == PathKind::File) {
        pathSection.insert(key("file"), path.file);
    }
}

void loadJointPathFile(JointPathSettings &path)
{
    if (path.kind != PathKind::File || path.file.isEmpty())
        return;
    try {
        const PathSamples samples = readPathCsvFile(path.file);
        path.fileTimes = samples.t;
        path.fileAngles = samples.q;
    } catch (const Error &e) {
        throwAtKey(key("path.file"), e.message());
    }
}

void resolveScenarioPaths(Scenario &s, const QString &directory)
{
    const QDir dir(directory);
    s.urdf.file = resolved(s.urdf.file, dir);
    s.path.file = resolved(s.path.file, dir);
    s.simulation.realUrdf = resolved(s.simulation.realUrdf, dir);
}

} // namespace learnid
