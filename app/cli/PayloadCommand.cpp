#include "cli/PayloadCommand.h"

#include "cli/IdentifyCommand.h"

#include "cli/IdentifyReportPdf.h"
#include "cli/IdentifyTable.h"
#include "cli/TorquePlotPng.h"
#include "io/AtomicFile.h"
#include "model/Error.h"
#include "service/LogIdentificationSummary.h"
#include "service/PayloadExport.h"
#include "service/PayloadIdentification.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <cmath>

namespace learnid::cli {

namespace {

QString number(double v, int precision, int width)
{
    if (std::abs(v) < 1e-12) // rounding of a zero, not a value
        v = 0.0;
    return (std::isfinite(v) ? QString::number(v, 'g', precision) : QStringLiteral("-"))
        .rightJustified(width);
}

} // namespace

QString payloadTable(const PayloadEstimate &e, const QString &dataName)
{
    const PayloadBody prior = payloadBody(e.prior);
    const double priorValues[10] = {prior.mass,
                                    prior.com.x(),
                                    prior.com.y(),
                                    prior.com.z(),
                                    prior.inertiaAtCom(0, 0),
                                    prior.inertiaAtCom(0, 1),
                                    prior.inertiaAtCom(1, 1),
                                    prior.inertiaAtCom(0, 2),
                                    prior.inertiaAtCom(1, 2),
                                    prior.inertiaAtCom(2, 2)};
    const QStringList names = PayloadEstimate::bodyNames();
    QString t = QCoreApplication::translate("learnid-cli", "value").leftJustified(16) +
                QCoreApplication::translate("learnid-cli", "estimate").rightJustified(12) +
                QCoreApplication::translate("learnid-cli", "std. error").rightJustified(12) +
                QCoreApplication::translate("learnid-cli", "prior").rightJustified(12) +
                QStringLiteral("  ") + QCoreApplication::translate("learnid-cli", "from") +
                QLatin1Char('\n');
    for (int i = 0; i < 10; ++i) {
        const QString unit = i == 0 ? QStringLiteral("kg")
                                    : (i < 4 ? QStringLiteral("m") : QStringLiteral("kg m^2"));
        const bool seen = e.bodyIdentified[size_t(i)];
        t += (names[i] + QStringLiteral(" [") + unit + QLatin1Char(']')).leftJustified(16) +
             number(e.bodyValue[size_t(i)], 5, 12) +
             (seen ? number(e.bodyStandardError[size_t(i)], 2, 12)
                   : QStringLiteral("-").rightJustified(12)) +
             number(priorValues[i], 5, 12) + QStringLiteral("  ") +
             (seen ? dataName
                   : QCoreApplication::translate("learnid-cli", "the prior (not identified)")) +
             QLatin1Char('\n');
    }
    return t;
}

namespace {

QString payloadText(const PayloadIdentificationResult &r, const QString &bound)
{
    const PayloadEstimate &e = r.fit.estimate;
    const PayloadObservability &o = e.observability;
    const LogRobot &robot = r.arm.robot;
    const QString armSource = r.arm.parameterFile.isEmpty()
                                  ? robot.source
                                  : QCoreApplication::translate("learnid-cli", "%1 on %2")
                                        .arg(r.arm.parameterFile, robot.source);
    QString t = QCoreApplication::translate(
                    "learnid-cli", "Payload on %1 of %2; the arm's model (%3) held fixed.\n")
                    .arg(r.model->link(), logRobotName(robot), armSource);
    if (!r.arm.identified)
        t += wrapText(QCoreApplication::translate(
                          "learnid-cli",
                          "Warning: the arm's model is %1 as given (its CAD values), not one "
                          "identified earlier: its errors go into the payload's estimate. "
                          "Identify the arm first (identify --export or --urdf-out, without the "
                          "payload) and give that file as --robot.")
                          .arg(robot.source));
    for (const QString &note : r.arm.notes)
        t += wrapText(QCoreApplication::translate("learnid-cli", "Note: %1").arg(note));
    t += QCoreApplication::translate("learnid-cli",
                                     "Fitted to %n log(s), %1 samples: %2 of 10 "
                                     "directions determined (condition %3).\n",
                                     nullptr, int(r.trainingLogs.size()))
             .arg(r.fit.samples)
             .arg(o.rank)
             .arg(o.condition, 0, 'f', 1);
    for (const BaselineAlignment &a : r.baselines)
        t += QCoreApplication::translate("learnid-cli",
                                         "Baseline %1 taken out of %2: shifted by %3 s, joint "
                                         "angles %4 deg RMS apart.\n")
                 .arg(a.baseline, a.log)
                 .arg(a.shiftSeconds, 0, 'f', 3)
                 .arg(a.angleRmsDeg, 0, 'f', 3);
    t += QLatin1Char('\n') +
         payloadTable(r.fit.estimate, QCoreApplication::translate("learnid-cli", "the logs")) +
         QLatin1Char('\n');
    if (!e.converged)
        t += QCoreApplication::translate("learnid-cli",
                                         "Warning: the plausible estimate did not converge (%1).\n")
                 .arg(e.solverReport);
    t += e.comInsideBound
             ? QCoreApplication::translate("learnid-cli",
                                           "A real body whose mass lies in the bound (%1).\n")
                   .arg(bound)
             : QCoreApplication::translate(
                   "learnid-cli", "Warning: the centre of mass lies outside the bound (%1).\n")
                   .arg(bound);
    const QStringList advice = o.advice(r.model->link());
    if (!advice.isEmpty()) {
        t += QCoreApplication::translate("learnid-cli",
                                         "What the logs did not show (kept from the prior):\n");
        for (const QString &line : advice)
            t += QStringLiteral("  - ") + line + QLatin1Char('\n');
    }
    t += QCoreApplication::translate("learnid-cli", "Torque residual per joint on the logs [N m]:");
    for (Eigen::Index j = 0; j < r.fit.trainingRms.size(); ++j)
        t += QLatin1Char(' ') + QString::number(r.fit.trainingRms[j], 'f', 3);
    t += QLatin1Char('\n');
    return t;
}

LogIdentificationRequest logRequest(const IdentifyOptions &o)
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

} // namespace

ExitCode payloadIdentifyCommand(const IdentifyOptions &o, QTextStream &out, QTextStream &err)
{
    QList<QPair<QString, QByteArray>> files;
    try {
        PayloadIdentificationRequest request;
        request.logs = logRequest(o);
        request.link = o.payload->link;
        request.armUrdf = o.payload->armUrdf;
        request.armUrdfName = QStringLiteral("--arm-urdf");
        request.prior = o.payload->prior;
        request.baselineLogs = o.payload->baselineLogs;
        request.fit.estimate.priorShare = o.fit.priorShare;
        if (!o.quiet)
            err << QCoreApplication::translate("learnid-cli",
                                               "learnid-cli: fitting the payload to %1")
                       .arg(o.logs.join(QStringLiteral(", ")))
                << Qt::endl;
        const PayloadIdentificationResult r =
            identifyPayloadFromLogs(request, payloadOptionNames());
        QString text = payloadText(r, o.payload->prior.bound.describe());
        if (!r.validation.empty())
            text += QLatin1Char('\n') +
                    QCoreApplication::translate(
                        "learnid-cli",
                        "On the --validate logs: \"URDF as given\" is the arm without the payload, "
                        "\"identified\" the arm with it.\n");
        for (const LogValidation &v : r.validation)
            text += QLatin1Char('\n') + validationTable(*r.arm.robot.model, v.source,
                                                        static_cast<long long>(v.samples()),
                                                        v.given, v.identified);
        out << text;
        out.flush();
        QStringList names;
        for (const ChainJoint &j : r.arm.robot.chain.joints)
            names << j.name;
        QList<QByteArray> pngs;
        for (const LogValidation &v : r.validation) {
            if (o.plotsDir.isEmpty() && o.reportPath.isEmpty())
                break;
            const QFileInfo log(v.source);
            const QByteArray png = torquePlotPng(
                {QCoreApplication::translate("learnid-cli",
                                             "%1: torque of the arm alone and with the payload")
                     .arg(log.fileName()),
                 names, v.time, v.measured, v.predictedGiven, v.predictedIdentified});
            pngs << png;
            if (!o.plotsDir.isEmpty())
                files.append(
                    {QDir(o.plotsDir)
                         .filePath(log.completeBaseName() + QStringLiteral("-payload-torque.png")),
                     png});
        }
        if (!o.reportPath.isEmpty())
            files.append(
                {o.reportPath,
                 identifyReportPdf(QCoreApplication::translate(
                                       "learnid-cli", "learnid: payload on %1 identified from logs")
                                       .arg(r.model->link()),
                                   text, pngs)});
        files += payloadExportFiles(r, identifyExportRequest(o, r.arm.robot.model->dof()));
    } catch (const Error &e) {
        out.flush();
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(e.message())
            << Qt::endl;
        return ExitBadInput;
    }
    return writeIdentifyFiles(o, files, err);
}

} // namespace learnid::cli
