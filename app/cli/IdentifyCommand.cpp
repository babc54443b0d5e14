#include "cli/IdentifyCommand.h"

#include "can/ManufacturerObjects.h"
#include "cli/IdentifyTable.h"
#include "io/AtomicFile.h"
#include "io/ParameterFile.h"
#include "io/ScenarioFile.h"
#include "io/UrdfExport.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "model/UrdfChain.h"
#include "service/SessionExport.h"
#include "session/EstimateConsistency.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <algorithm>

namespace learnid::cli {

namespace {

constexpr double consistencyTolerance = 1e-12; ///< relative to a link's largest eigenvalue

/// The robot as --robot names it: its URDF text (kept for --urdf-out) and the chain read from it.
struct Robot
{
    QString model;  ///< the parameter file's robot.model: the built-in id, or "urdf"
    QString source; ///< the URDF in messages
    QByteArray urdf;
    SerialChain chain;
};

Robot loadRobot(const IdentifyOptions &o)
{
    QStringList builtIns;
    for (const QString &id : knownRobotModels())
        if (isUrdfModel(id) && id != QLatin1String("urdf"))
            builtIns << id;
    Robot r;
    const bool builtIn = builtIns.contains(o.robot);
    if (!builtIn && !QFileInfo(o.robot).isFile()) {
        throw Error(
            QCoreApplication::translate(
                "learnid-cli", "--robot: '%1' is neither a URDF file nor a built-in robot (%2)")
                .arg(o.robot, builtIns.join(QStringLiteral(", "))));
    }
    r.model = builtIn ? o.robot : QStringLiteral("urdf");
    const QString path = builtIn ? urdfFileOf(o.robot, {}) : o.robot;
    r.source = builtIn ? QCoreApplication::translate("learnid-cli", "built-in %1").arg(o.robot)
                       : QDir::toNativeSeparators(path);
    r.urdf = readFile(path);
    r.chain = parseUrdfChain(r.urdf, r.source, o.baseLink, o.tipLink);
    return r;
}

// The parameter file records the gains the data were recorded with; logs do not say, so they
// come from --scenario, else the scenario's defaults (for two joints only).
ControllerSettings exportController(const IdentifyOptions &o, int joints)
{
    if (!o.scenarioPath.isEmpty()) {
        const Scenario scenario = readScenarioFile(o.scenarioPath);
        validateControllerSettings(
            scenario.controller, joints,
            QStringLiteral("%1: controller").arg(QDir::toNativeSeparators(o.scenarioPath)));
        return scenario.controller;
    }
    const ControllerSettings defaults;
    if (defaults.dof() != joints) {
        throw Error(QCoreApplication::translate(
                        "learnid-cli",
                        "--export: a parameter file records the controller's gains, and the "
                        "default gains are for %1 joints, the robot has %2: give them with "
                        "--scenario FILE (its controller section)")
                        .arg(defaults.dof())
                        .arg(joints));
    }
    return defaults;
}

FilteredLog loadLog(const QString &path, const ChainModel &model, const IdentifyOptions &o,
                    QTextStream &err)
{
    if (!o.quiet)
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: reading %1")
                   .arg(QDir::toNativeSeparators(path))
            << Qt::endl;
    QList<bool> angular; // revolute joints: a log in degrees is refused
    for (const ChainJoint &j : model.chain().joints)
        angular << (j.type == JointType::Revolute);
    return filterLog(
        resampleUniform(readRobotLogFile(path, model.dof(), o.columns, angular), o.resample),
        o.filter);
}

// The verdict on the identified standard parameters themselves (not on base parameters with
// the CAD model filling the rest, as checkEstimateConsistency() judges an estimate).
QStringList consistencyLines(const ChainModel &model, const Eigen::VectorXd &standard)
{
    EstimateConsistency c;
    c.applicable = true;
    c.links = checkConsistency(standard, model.dof(), consistencyTolerance);
    c.negativeTerms = negativeJointTerms(standard, model.nonnegativeStandard());
    c.consistent = c.negativeTerms.empty() &&
                   std::all_of(c.links.begin(), c.links.end(),
                               [](const LinkConsistency &l) { return l.consistent; });
    return c.describe(model);
}

ParameterFileContent parameterFile(const Robot &robot, const ChainModel &model, const LogFit &fit,
                                   const IdentifyOptions &o, const ControllerSettings &controller)
{
    QStringList logs;
    for (const QString &log : o.logs)
        logs << QFileInfo(log).fileName();
    ParameterFileContent c;
    c.robotModel = robot.model;
    c.robotDescription =
        QCoreApplication::translate("learnid-cli", "%1 (%2), identified from the logs %3")
            .arg(robot.chain.name, robot.source, logs.join(QStringLiteral(", ")));
    c.controller = controller;
    c.created = QDateTime::currentDateTimeUtc();
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.law = QStringLiteral("improved"); // its zero-phase filter F(s) prepares the logs
    c.parameters = model.parameters();
    c.values = fit.base;
    c.residualRms = fit.trainingRms;
    c.condition = fit.condition;
    c.rank = fit.rank;
    c.canWrites = objects::parameterWriteSequence(c.nodes(), fit.base);
    return c;
}

// The URDF with the identified bodies and friction; a term the model does not have is 0.
QByteArray urdfFile(const Robot &robot, const ChainModel &model, const LogFit &fit)
{
    const int n = model.dof();
    const JointTerms &t = model.jointTerms();
    std::vector<InertialParameters> bodies(size_t(n), InertialParameters::Zero());
    std::vector<IdentifiedJoint> friction(static_cast<size_t>(n));
    for (int j = 0; j < n; ++j) {
        bodies[size_t(j)] = fit.standard.segment<10>(10 * j);
        Eigen::Index at = 10 * n + Eigen::Index(j) * t.count() + (t.armature ? 1 : 0);
        if (t.viscous)
            friction[size_t(j)].viscous = fit.standard[at++];
        if (t.coulomb)
            friction[size_t(j)].coulomb = fit.standard[at];
    }
    const QString comment =
        QCoreApplication::translate("learnid-cli", "identified by learnid-cli %1 identify on %2")
            .arg(QStringLiteral(LEARNID_VERSION),
                 QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
    return identifiedUrdf(robot.urdf, robot.source, robot.chain, bodies, friction, comment);
}

} // namespace

ExitCode identifyCommand(const IdentifyOptions &o, QTextStream &out, QTextStream &err)
{
    const auto progress = [&](const QString &line) {
        if (!o.quiet)
            err << QCoreApplication::translate("learnid-cli", "learnid-cli: %1").arg(line)
                << Qt::endl;
    };
    QList<QPair<QString, QByteArray>> files;
    try {
        const Robot robot = loadRobot(o);
        const ChainModel model(robot.chain, o.terms, robot.model);
        const ControllerSettings controller =
            o.exportPath.isEmpty() ? ControllerSettings{} : exportController(o, model.dof());
        progress(QCoreApplication::translate("learnid-cli", "robot %1 (%2): %3 moving joints")
                     .arg(robot.chain.name, robot.source)
                     .arg(model.dof()));

        std::vector<FilteredLog> training;
        for (const QString &path : o.logs)
            training.push_back(loadLog(path, model, o, err));
        std::vector<FilteredLog> validation;
        for (const QString &path : o.validationLogs)
            validation.push_back(loadLog(path, model, o, err));
        progress(
            QCoreApplication::translate("learnid-cli", "fitting %1 standard parameters to %2 logs")
                .arg(model.standardCount())
                .arg(training.size()));
        const LogFit fit = fitLogs(model, training, o.fit);

        QStringList undetermined;
        for (const int i : fit.undetermined())
            undetermined << model.parameters().at(i).name;
        if (!undetermined.isEmpty())
            progress(QCoreApplication::translate("learnid-cli",
                                                 "base parameters the logs leave undetermined "
                                                 "(kept near the URDF's values): %1")
                         .arg(undetermined.join(QStringLiteral(", "))));

        out << identifySummary(model, fit, int(training.size()),
                               consistencyLines(model, fit.standard))
            << QLatin1Char('\n') << trainingTable(model, fit);
        for (const FilteredLog &log : validation) {
            out << QLatin1Char('\n')
                << validationTable(model, log.source, static_cast<long long>(log.keptSamples()),
                                   torqueFigures(model, model.cadStandard(), log),
                                   torqueFigures(model, fit.standard, log));
        }
        out.flush();

        if (!o.exportPath.isEmpty()) {
            const ParameterFileContent content = parameterFile(robot, model, fit, o, controller);
            files.append({o.exportPath, parameterFileToJson(content)});
            files.append({dcfPathFor(o.exportPath), parameterDcfFragment(content)});
        }
        if (!o.urdfPath.isEmpty())
            files.append({o.urdfPath, urdfFile(robot, model, fit)});
    } catch (const Error &e) {
        out.flush();
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(e.message())
            << Qt::endl;
        return ExitBadInput;
    }
    try {
        writeFilesAtomically(files);
    } catch (const Error &e) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(e.message())
            << Qt::endl;
        return ExitWriteFailed;
    }
    for (const auto &file : files)
        progress(QCoreApplication::translate("learnid-cli", "wrote %1")
                     .arg(QDir::toNativeSeparators(file.first)));
    return ExitOk;
}

} // namespace learnid::cli
