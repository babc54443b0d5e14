// The exports of an identification from logs (LogIdentification.h): the parameter file with its
// DCF fragment and the identified URDF, as `learnid-cli identify` and the window write them.
#include "service/LogIdentification.h"

#include "can/ManufacturerObjects.h"
#include "io/UrdfExport.h"
#include "model/Error.h"
#include "service/SessionExport.h"
#include "service/StandardExport.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace learnid {

ParameterFileContent logParameterFile(const LogIdentificationResult &result,
                                      const std::optional<ControllerSettings> &controller)
{
    QStringList logs;
    for (const QString &log : result.trainingLogs)
        logs << QFileInfo(log).fileName();
    const LogFit &fit = result.fit;
    const ChainModel &model = result.model();
    ParameterFileContent c = logFileHeader(
        model, result.robot.modelId,
        QCoreApplication::translate("LogIdentification", "%1 (%2), identified from the logs %3")
            .arg(result.robot.chain.name, result.robot.source, logs.join(QStringLiteral(", "))),
        controller);
    c.values = fit.base;
    c.residualRms = fit.trainingRms;
    c.condition = fit.condition;
    c.rank = fit.rank;
    c.canWrites = objects::parameterWriteSequence(c.nodes(), fit.base);
    setStandardParameters(c, model, fit.standard, fit.standardDetermined);
    return c;
}

QByteArray logIdentifiedUrdf(const LogIdentificationResult &result, const QString &comment)
{
    return urdfWithStandard(result.model(), result.robot.urdf, result.robot.source,
                            result.fit.standard, comment, result.fit.standardDetermined);
}

QList<QPair<QString, QByteArray>> logExportFiles(const LogIdentificationResult &result,
                                                 const LogExportRequest &request)
{
    QList<QPair<QString, QByteArray>> files;
    if (!request.parameterPath.isEmpty()) {
        if (request.controller && request.controller->dof() != result.model().dof()) {
            throw Error(QCoreApplication::translate("LogIdentification",
                                                    "the controller gains the parameter file "
                                                    "records are for %1 joints, the robot has %2")
                            .arg(request.controller->dof())
                            .arg(result.model().dof()));
        }
        const ParameterFileContent content = logParameterFile(result, request.controller);
        appendParameterFiles(files, request.parameterPath, content);
    }
    if (!request.urdfPath.isEmpty())
        files.append({request.urdfPath, logIdentifiedUrdf(result, request.urdfComment)});
    return files;
}

QStringList writeLogExport(const LogIdentificationResult &result, const LogExportRequest &request)
{
    const QList<QPair<QString, QByteArray>> files = logExportFiles(result, request);
    return writeExportFiles(files);
}

} // namespace learnid
