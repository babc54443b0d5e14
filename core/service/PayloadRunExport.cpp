// The exports of a payload learned in the window (PayloadRunExport.h): the arm's model held
// fixed plus the payload, as a parameter file and as a URDF, as PayloadExport.cpp writes those of
// a payload identified from logs.
#include "service/PayloadRunExport.h"

#include "can/ManufacturerObjects.h"
#include "io/AtomicFile.h"
#include "io/TrialCsv.h"
#include "io/UrdfPayload.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "service/PayloadExport.h"
#include "service/SessionExport.h"
#include "service/StandardExport.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadRunExport)
};

Eigen::VectorXd armStandard(const PayloadRunResult &r)
{
    return r.model->standardFromBase(r.scenario.initialParameters);
}

} // namespace

ParameterFileContent payloadRunParameterFile(const PayloadRunResult &r)
{
    const ChainModel &model = *r.model;
    ParameterFileContent c = logFileHeader(
        model, r.scenario.model,
        Text::tr("%1 with a payload on %2 learned in %n trial(s) with the arm's model held fixed",
                 nullptr, r.learnedTrial + 1 - r.scenario.payload.baselineTrials)
            .arg(r.robotDescription, r.link),
        r.scenario.controller);
    c.law = r.scenario.law;
    c.sourceTrial = r.learnedTrial;
    c.values = r.scenario.initialParameters;
    c.maxTrackingErrorDeg = r.maxTrackingErrorDeg;
    c.rmsTrackingErrorDeg = r.rmsTrackingErrorDeg;
    c.canWrites = objects::parameterWriteSequence(c.nodes(), c.values);
    // The arm's values as given, not determined by these trials: no shares.
    setStandardParameters(c, model, armStandard(r), {});
    setPayloadFit(c, r.fit, r.link);
    addPayloadWrites(c, payloadLinkOf(model.chain(), r.link), r.fit.estimate.parameters);
    return c;
}

QByteArray payloadRunUrdf(const PayloadRunResult &r, const QString &comment)
{
    const QString source = urdfFileOf(r.scenario.model, r.scenario.urdf);
    const QByteArray arm =
        urdfWithStandard(*r.model, readFile(source), source, armStandard(r), comment);
    const PayloadEstimate &e = r.fit.estimate;
    const QStringList kept = payloadValuesKept(e);
    // English, as the file's other comments (UrdfExport.cpp).
    QString note = QStringLiteral("The payload on %1, learned by learnid in %2 trials on %3 with "
                                  "the arm's model held fixed")
                       .arg(r.link)
                       .arg(r.learnedTrial + 1 - r.scenario.payload.baselineTrials)
                       .arg(r.robotDescription);
    if (!comment.isEmpty())
        note += QStringLiteral(" (%1)").arg(comment);
    note += kept.isEmpty() ? QStringLiteral(": all its values from the trials.")
                           : QStringLiteral(": %1 kept at the prior (not seen by the path).")
                                 .arg(kept.join(QStringLiteral(", ")));
    return urdfWithPayload(arm, source, r.model->chain(), r.link, e.parameters, note);
}

QList<QPair<QString, QByteArray>> payloadRunExportFiles(const PayloadRunResult &r,
                                                        const LogExportRequest &request)
{
    QList<QPair<QString, QByteArray>> files;
    if (!request.parameterPath.isEmpty()) {
        const ParameterFileContent content = payloadRunParameterFile(r);
        appendParameterFiles(files, request.parameterPath, content);
    }
    if (!request.urdfPath.isEmpty())
        files.append({request.urdfPath, payloadRunUrdf(r, request.urdfComment)});
    return files;
}

QList<QPair<QString, QByteArray>> payloadTrialCsvFiles(const std::vector<PayloadTrial> &history,
                                                       const QString &folder)
{
    QList<QPair<QString, QByteArray>> files;
    for (const PayloadTrial &t : history) {
        if (t.record.samples() > 0) // refused before the motion: nothing measured
            files.append({trialCsvPath(folder, t.index), trialCsv(t.plan(), t.record)});
    }
    return files;
}

QStringList writePayloadRunExport(const PayloadRunResult &r, const LogExportRequest &request)
{
    const QList<QPair<QString, QByteArray>> files = payloadRunExportFiles(r, request);
    return writeExportFiles(files);
}

QString payloadRecordTrialFolder(const QString &reportPath)
{
    const QFileInfo report(reportPath);
    return report.dir().filePath(report.completeBaseName() + QStringLiteral("-trials"));
}

QStringList writePayloadRecord(const PayloadRunRecord &r, const QString &reportPath)
{
    const QString folder = payloadRecordTrialFolder(reportPath);
    QList<QPair<QString, QByteArray>> files{{reportPath, r.report}};
    for (const auto &[name, content] : r.trialCsvs)
        files.append({QDir(folder).filePath(name), content});
    if (!QDir().mkpath(folder))
        throw Error(Text::tr("%1: the folder for the trial CSVs cannot be created").arg(folder));
    return writeExportFiles(files);
}

} // namespace learnid
