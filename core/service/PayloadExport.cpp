// The exports of a payload identification (PayloadExport.h): the arm's model held fixed plus the
// payload, as a parameter file and as a URDF.
#include "service/PayloadExport.h"

#include "can/ManufacturerObjects.h"
#include "can/PayloadObjects.h"
#include "io/UrdfPayload.h"
#include "model/Error.h"
#include "service/SessionExport.h"
#include "service/StandardExport.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <cmath>
#include <limits>

namespace learnid {

void addPayloadWrites(ParameterFileContent &content, const PayloadLink &link,
                      const InertialParameters &payload)
{
    QList<SdoWrite> &writes = content.canWrites;
    qsizetype firstStore = 0;
    while (firstStore < writes.size() && writes[firstStore].index != objects::storeParameters)
        ++firstStore;
    const QList<SdoWrite> added =
        objects::payloadWrites(content.nodes(), link.joint + 1, payloadInBody(link, payload));
    writes = writes.mid(0, firstStore) + added + writes.mid(firstStore);
}

ParameterFilePayload payloadSection(const PayloadEstimate &e, const QString &link)
{
    ParameterFilePayload p;
    p.link = link;
    p.mass = e.body.mass;
    p.com = e.body.com;
    const Eigen::Matrix3d &i = e.body.inertiaAtCom;
    p.inertiaAtCom = {i(0, 0), i(0, 1), i(1, 1), i(0, 2), i(1, 2), i(2, 2)};
    for (size_t k = 0; k < 10; ++k) {
        p.identified[k] = e.bodyIdentified[k];
        const double error = e.bodyStandardError[k];
        p.standardUncertainty[k] = p.identified[k] && std::isfinite(error)
                                       ? error
                                       : std::numeric_limits<double>::quiet_NaN();
    }
    return p;
}

void setPayloadFit(ParameterFileContent &content, const PayloadFit &fit, const QString &link)
{
    content.residualRms = fit.trainingRms;
    const PayloadObservability &o = fit.estimate.observability;
    content.condition = o.rank > 0 ? o.condition : std::numeric_limits<double>::infinity();
    content.rank = o.rank;
    content.payload = payloadSection(fit.estimate, link);
}

QStringList payloadValuesKept(const PayloadEstimate &estimate)
{
    QStringList kept;
    const QStringList names = PayloadEstimate::bodyNames();
    for (int i = 0; i < 10; ++i)
        if (!estimate.bodyIdentified[size_t(i)])
            kept << names[i];
    return kept;
}

ParameterFileContent payloadParameterFile(const PayloadIdentificationResult &r,
                                          const std::optional<ControllerSettings> &controller)
{
    QStringList logs;
    for (const QString &log : r.trainingLogs)
        logs << QFileInfo(log).fileName();
    const ChainModel &model = *r.arm.robot.model;
    const QString arm = r.arm.parameterFile.isEmpty()
                            ? r.arm.robot.source
                            : QStringLiteral("%1, %2").arg(r.arm.robot.source, r.arm.parameterFile);
    ParameterFileContent c = logFileHeader(
        model, r.arm.robot.modelId,
        QCoreApplication::translate("PayloadExport",
                                    "%1 (%2) with a payload on %3 identified from the logs %4")
            .arg(r.arm.robot.chain.name, arm, r.model->link(), logs.join(QStringLiteral(", "))),
        controller);
    c.values = model.baseFromStandard(r.arm.standard);
    c.canWrites = objects::parameterWriteSequence(c.nodes(), c.values);
    setStandardParameters(c, model, r.arm.standard, r.arm.determined);
    setPayloadFit(c, r.fit, r.model->link());
    addPayloadWrites(c, r.model->payloadLink(), r.fit.estimate.parameters);
    return c;
}

QByteArray payloadIdentifiedUrdf(const PayloadIdentificationResult &r, const QString &comment)
{
    const LogRobot &robot = r.arm.robot;
    // A parameter file's values are not in the URDF yet; a URDF's own are the arm's.
    const QByteArray arm = r.arm.parameterFile.isEmpty()
                               ? robot.urdf
                               : urdfWithStandard(*robot.model, robot.urdf, robot.source,
                                                  r.arm.standard, comment, r.arm.determined);
    const PayloadEstimate &e = r.fit.estimate;
    const QStringList kept = payloadValuesKept(e);
    // English, as the file's other comments (UrdfExport.cpp).
    QString note = QStringLiteral("The payload on %1, estimated by learnid from logs with the "
                                  "arm's model held fixed")
                       .arg(r.model->link());
    if (!comment.isEmpty())
        note += QStringLiteral(" (%1)").arg(comment);
    note += kept.isEmpty() ? QStringLiteral(": all its values from the logs.")
                           : QStringLiteral(": %1 kept at the prior (not seen in the logs).")
                                 .arg(kept.join(QStringLiteral(", ")));
    return urdfWithPayload(arm, robot.source, robot.chain, r.model->link(), e.parameters, note);
}

QList<QPair<QString, QByteArray>> payloadExportFiles(const PayloadIdentificationResult &r,
                                                     const LogExportRequest &request)
{
    QList<QPair<QString, QByteArray>> files;
    const int dof = r.arm.robot.model->dof();
    if (!request.parameterPath.isEmpty()) {
        if (request.controller && request.controller->dof() != dof) {
            throw Error(QCoreApplication::translate("PayloadExport",
                                                    "the controller gains the parameter file "
                                                    "records are for %1 joints, the robot has %2")
                            .arg(request.controller->dof())
                            .arg(dof));
        }
        const ParameterFileContent content = payloadParameterFile(r, request.controller);
        appendParameterFiles(files, request.parameterPath, content);
    }
    if (!request.urdfPath.isEmpty())
        files.append({request.urdfPath, payloadIdentifiedUrdf(r, request.urdfComment)});
    return files;
}

} // namespace learnid
