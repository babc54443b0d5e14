#include "cli/IdentifyCommand.h"

#include "cli/IdentifyReportPdf.h"
#include "cli/PayloadCommand.h"
#include "cli/TorquePlotPng.h"

#include "cli/IdentifyParameters.h"
#include "cli/IdentifyTable.h"
#include "io/AtomicFile.h"
#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "service/LogIdentification.h"
#include "service/LogIdentificationSummary.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>

namespace learnid::cli {

namespace {

LogIdentificationRequest identificationRequest(const IdentifyOptions &o)
{
    LogIdentificationRequest r;
    r.robot = o.robot;
    r.baseLink = o.baseLink;
    r.tipLink = o.tipLink;
    r.terms = o.terms;
    r.trainingLogs = o.logs;
    r.validationLogs = o.validationLogs;
    r.columns = o.columns;
    r.filter = o.filter;
    r.fit = o.fit;
    r.resample = o.resample;
    return r;
}

LogRobot loadRobot(const LogIdentificationRequest &request)
{
    if (!builtInUrdfRobots().contains(request.robot) && !QFileInfo(request.robot).isFile()) {
        throw Error(
            QCoreApplication::translate(
                "learnid-cli", "--robot: '%1' is neither a URDF file nor a built-in robot (%2)")
                .arg(request.robot, builtInUrdfRobots().join(QStringLiteral(", "))));
    }
    return loadLogRobot(request);
}

// --plots DIR: DIR/<log name>-torque.png per validation log; --report FILE: the text and the
// plots as PDF. Images need the QGuiApplication main() makes for them (imagesWanted()).
QList<QPair<QString, QByteArray>>
plotFiles(const IdentifyOptions &o, const LogIdentificationResult &result, const QString &text)
{
    QList<QPair<QString, QByteArray>> files;
    if (o.plotsDir.isEmpty() && o.reportPath.isEmpty())
        return files;
    QStringList names;
    for (const ChainJoint &j : result.robot.chain.joints)
        names << j.name;
    QList<QByteArray> pngs;
    for (const LogValidation &v : result.validation) {
        const QFileInfo log(v.source);
        const QByteArray png = torquePlotPng(
            {QCoreApplication::translate("learnid-cli", "%1: torque predicted and measured")
                 .arg(log.fileName()),
             names, v.time, v.measured, v.predictedGiven, v.predictedIdentified});
        pngs << png;
        if (!o.plotsDir.isEmpty())
            files.append(
                {QDir(o.plotsDir).filePath(log.completeBaseName() + QStringLiteral("-torque.png")),
                 png});
    }
    if (!o.reportPath.isEmpty()) {
        files.append(
            {o.reportPath, identifyReportPdf(QCoreApplication::translate(
                                                 "learnid-cli", "learnid: %1 identified from logs")
                                                 .arg(logRobotName(result.robot)),
                                             text, pngs)});
    }
    return files;
}

} // namespace

ExitCode identifyCommand(const IdentifyOptions &o, QTextStream &out, QTextStream &err)
{
    if (o.payload)
        return payloadIdentifyCommand(o, out, err);
    const auto progress = [&](const QString &line) {
        if (!o.quiet)
            err << QCoreApplication::translate("learnid-cli", "learnid-cli: %1").arg(line)
                << Qt::endl;
    };
    QList<QPair<QString, QByteArray>> files;
    try {
        const LogIdentificationRequest request = identificationRequest(o);
        const LogRobot robot = loadRobot(request);
        const ChainModel &model = *robot.model;
        const LogExportRequest exports = identifyExportRequest(o, model.dof());
        progress(QCoreApplication::translate("learnid-cli", "robot %1: %2, %3 moving joints")
                     .arg(logRobotName(robot), robot.source)
                     .arg(model.dof()));

        const auto stage = [&](const LogIdentificationProgress &p) {
            switch (p.stage) {
            case LogIdentificationStage::ReadTraining:
            case LogIdentificationStage::ReadValidation:
                if (!o.quiet)
                    err << QCoreApplication::translate("learnid-cli", "learnid-cli: reading %1")
                               .arg(QDir::toNativeSeparators(p.path))
                        << Qt::endl;
                break;
            case LogIdentificationStage::Fit:
                progress(QCoreApplication::translate("learnid-cli",
                                                     "fitting %1 standard parameters to %n log(s)",
                                                     nullptr, p.count)
                             .arg(model.standardCount()));
                break;
            case LogIdentificationStage::Robot:
            case LogIdentificationStage::Validate:
                break;
            }
        };
        const LogIdentificationResult result = identifyFromLogs(robot, request, stage);
        QString text = identifySummary(result) + modelWarningText(result.robot.warnings) +
                       QLatin1Char('\n') + verdictTable(result) + QLatin1Char('\n') +
                       trainingTable(model, result.fit) + QLatin1Char('\n') +
                       parameterTable(model, result.fit);
        for (const LogValidation &v : result.validation) {
            text += QLatin1Char('\n') + validationTable(model, v.source,
                                                        static_cast<long long>(v.samples()),
                                                        v.given, v.identified);
        }
        out << text;
        out.flush();
        files += plotFiles(o, result, text);

        files += logExportFiles(result, exports);
    } catch (const Error &e) {
        out.flush();
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(e.message())
            << Qt::endl;
        return ExitBadInput;
    }
    return writeIdentifyFiles(o, files, err);
}

LogExportRequest identifyExportRequest(const IdentifyOptions &o, int joints)
{
    LogExportRequest exports;
    exports.parameterPath = o.exportPath;
    exports.urdfPath = o.urdfPath;
    // The parameter file records the gains the data were recorded with when --scenario names
    // them; logs do not say, so without it the file holds the model alone.
    if (!o.exportPath.isEmpty() && !o.scenarioPath.isEmpty()) {
        const Scenario scenario = readScenarioFile(o.scenarioPath);
        validateControllerSettings(
            scenario.controller, joints,
            QStringLiteral("%1: controller").arg(QDir::toNativeSeparators(o.scenarioPath)));
        exports.controller = scenario.controller;
    }
    exports.urdfComment =
        QCoreApplication::translate("learnid-cli", "identified by learnid-cli %1 identify on %2")
            .arg(QStringLiteral(LEARNID_VERSION),
                 QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
    return exports;
}

ExitCode writeIdentifyFiles(const IdentifyOptions &o,
                            const QList<QPair<QString, QByteArray>> &files, QTextStream &err)
{
    try {
        if (!o.plotsDir.isEmpty() && !QDir().mkpath(o.plotsDir))
            throw Error(QCoreApplication::translate("learnid-cli", "--plots: cannot create %1")
                            .arg(QDir::toNativeSeparators(o.plotsDir)));
        writeFilesAtomically(files);
    } catch (const Error &e) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(e.message())
            << Qt::endl;
        return ExitWriteFailed;
    }
    for (const auto &file : files)
        if (!o.quiet)
            err << QCoreApplication::translate("learnid-cli", "learnid-cli: %1")
                       .arg(QCoreApplication::translate("learnid-cli", "wrote %1")
                                .arg(QDir::toNativeSeparators(file.first)))
                << Qt::endl;
    return ExitOk;
}

} // namespace learnid::cli
