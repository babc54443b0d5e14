#include "identify/LearningLaw.h"
#include "io/JsonReader.h"
#include "io/ParameterFile.h"
#include "io/ScenarioFile.h"
#include "io/ValueChecks.h"
#include "model/ModelFactory.h"

#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ParameterFile)
};

QString key(const char *path)
{
    return QString::fromLatin1(path);
}

// A vector that is either empty (not available) or has expected entries.
void checkOptionalVector(const QString &path, const Eigen::VectorXd &values, Eigen::Index expected,
                         const QString &what)
{
    if (values.size() > 0)
        checkVector(path, values, expected, what, EntryRule::NonNegativeOrInfinite);
}

// The standard parameters: names, finite values, determined shares in [0, 1] or unknown.
void validateStandard(const ParameterFileContent &c)
{
    const int p = int(c.standardParameters.size());
    const QString perStandard = Text::tr("one per standard parameter");
    checkLength(key("standardParameters"), c.standardValues.size(), p,
                Text::tr("values, %1").arg(perStandard));
    if (!c.standardDetermined.empty()) {
        checkLength(key("standardParameters"), Eigen::Index(c.standardDetermined.size()), p,
                    Text::tr("determined shares, %1").arg(perStandard));
    }
    for (int i = 0; i < p; ++i) {
        const QString path = jsonIndexPath(key("standardParameters"), i);
        if (c.standardParameters.at(i).name.isEmpty())
            throwAtKey(jsonKeyPath(path, key("name")), Text::tr("must not be empty"));
        checkFinite(jsonKeyPath(path, key("value")), c.standardValues[i]);
        const double share = c.standardDetermined.empty() ? 0.0 : c.standardDetermined[size_t(i)];
        if (!std::isnan(share) && !(share >= 0.0 && share <= 1.0)) {
            throwAtKey(jsonKeyPath(path, key("determined")),
                       Text::tr("must be a share from 0 to 1 or null, got %1").arg(share));
        }
    }
}

} // namespace

QList<int> ParameterFileContent::nodes() const
{
    if (!jointNodes.isEmpty())
        return jointNodes;
    QList<int> n;
    for (int j = 0; j < controller.dof(); ++j)
        n.append(j + 1);
    return n;
}

int ParameterFileContent::dof() const
{
    return hasController ? controller.dof() : int(jointNodes.size());
}

void validateParameterFileContent(const ParameterFileContent &c)
{
    if (!knownRobotModels().contains(c.robotModel)) {
        throwAtKey(key("robot.model"),
                   Text::tr("unknown model \"%1\"; known models: %2")
                       .arg(c.robotModel, knownRobotModels().join(QStringLiteral(", "))));
    }
    // A URDF robot's parameters depend on its URDF and joint terms, which the file does not
    // carry: it names its own parameters (base parameters, docs/robots.md) and is checked
    // against itself; the paper's arm against its model.
    const bool urdf = isUrdfModel(c.robotModel);
    const auto model = urdf ? nullptr : makeRobotModel(c.robotModel);
    if (!c.hasController && c.jointNodes.isEmpty()) {
        throwAtKey(key("robot.jointNodes"),
                   Text::tr("must give each joint's node when the file records no controller"));
    }
    const int n = urdf ? c.dof() : model->dof();
    const int m = urdf ? int(c.parameters.size()) : model->parameterCount();
    const QString perJoint = Text::tr("one per joint of %1").arg(c.robotModel);

    if (!c.jointNodes.isEmpty()) {
        checkLength(key("robot.jointNodes"), c.jointNodes.size(), n, perJoint);
        for (int j = 0; j < n; ++j) {
            const QString path = jsonIndexPath(key("robot.jointNodes"), j);
            checkIntegerRange(path, c.jointNodes.at(j), 1, 127);
            if (c.jointNodes.indexOf(c.jointNodes.at(j)) != j)
                throwAtKey(path,
                           Text::tr("node %1 is given to two joints").arg(c.jointNodes.at(j)));
        }
    }
    if (!c.drives.isEmpty())
        checkLength(key("robot.drives"), c.drives.size(), n, perJoint);
    if (c.hasController) {
        validateControllerSettings(c.controller, n, key("controller"));
        // The gains and the parameters go to the drives' REAL32 objects (the DCF fragment, apply).
        const auto checkGains = [](const char *name, const Eigen::VectorXd &gains) {
            for (int j = 0; j < int(gains.size()); ++j)
                checkFitsReal32(jsonIndexPath(jsonKeyPath(key("controller"), key(name)), j),
                                gains[j]);
        };
        checkGains("kp", c.controller.kp);
        checkGains("ki", c.controller.ki);
        checkGains("kd", c.controller.kd);
        checkFitsReal32(key("controller.lambda"), c.controller.lambda);
    }
    if (!c.created.isValid())
        throwAtKey(key("created"), Text::tr("must be a valid date and time"));
    if (c.toolVersion.isEmpty())
        throwAtKey(key("toolVersion"), Text::tr("must not be empty"));
    if (!knownLearningLaws().contains(c.law)) {
        throwAtKey(key("identification.law"),
                   Text::tr("unknown learning law \"%1\"; known laws: %2")
                       .arg(c.law, knownLearningLaws().join(QStringLiteral(", "))));
    }
    if (c.sourceTrial < -1) {
        throwAtKey(
            key("identification.sourceTrial"),
            Text::tr("must be a trial index or -1 (not recorded), got %1").arg(c.sourceTrial));
    }

    const QList<ParameterInfo> modelParameters = urdf ? c.parameters : model->parameters();
    const QString perParameter = Text::tr("one per parameter of %1").arg(c.robotModel);
    if (urdf && m == 0)
        throwAtKey(key("parameters"), Text::tr("must not be empty"));
    checkLength(key("parameters"), c.parameters.size(), m, perParameter);
    for (int i = 0; i < m; ++i) {
        const QString path = jsonKeyPath(jsonIndexPath(key("parameters"), i), key("name"));
        if (urdf && c.parameters.at(i).name.isEmpty())
            throwAtKey(path, Text::tr("must not be empty"));
        if (c.parameters.at(i).name != modelParameters.at(i).name) {
            throwAtKey(path, Text::tr("must be \"%1\" (parameter %2 of %3), got \"%4\"")
                                 .arg(modelParameters.at(i).name)
                                 .arg(i + 1)
                                 .arg(c.robotModel, c.parameters.at(i).name));
        }
    }
    checkLength(key("parameters"), c.values.size(), m, Text::tr("values, %1").arg(perParameter));
    for (int i = 0; i < m; ++i) {
        const QString path = jsonKeyPath(jsonIndexPath(key("parameters"), i), key("value"));
        checkFinite(path, c.values[i]);
        checkFitsReal32(path, c.values[i]);
    }
    if (c.standardDeviations.size() > 0) {
        checkLength(key("parameters"), c.standardDeviations.size(), m,
                    Text::tr("standard deviations, %1").arg(perParameter));
        for (int i = 0; i < m; ++i) {
            checkNonNegativeOrInfinite(
                jsonKeyPath(jsonIndexPath(key("parameters"), i), key("standardDeviation")),
                c.standardDeviations[i]);
        }
    }

    validateStandard(c);
    if (c.payload)
        validatePayloadSection(*c.payload, c.robotModel);

    checkOptionalVector(key("quality.maxTrackingErrorDeg"), c.maxTrackingErrorDeg, n, perJoint);
    checkOptionalVector(key("quality.rmsTrackingErrorDeg"), c.rmsTrackingErrorDeg, n, perJoint);
    checkOptionalVector(key("quality.residualRms"), c.residualRms, n, perJoint);
    checkNonNegativeOrInfinite(key("quality.condition"), c.condition);
    checkIntegerRange(key("quality.rank"), c.rank, 0, m);

    for (int i = 0; i < int(c.canWrites.size()); ++i) {
        const SdoWrite &w = c.canWrites.at(i);
        const QString path = jsonIndexPath(key("canWrites"), i);
        checkIntegerRange(jsonKeyPath(path, key("node")), w.node, 1, 127);
        if (w.dataType.isEmpty())
            throwAtKey(jsonKeyPath(path, key("type")), Text::tr("must name the CANopen data type"));
        checkFinite(jsonKeyPath(path, key("value")), w.value);
        if (w.raw.isEmpty())
            throwAtKey(jsonKeyPath(path, key("raw")), Text::tr("must hold the bytes written"));
    }
}

} // namespace learnid
