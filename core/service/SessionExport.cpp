#include "service/SessionExport.h"

#include "can/ManufacturerObjects.h"
#include "io/AtomicFile.h"
#include "io/ParameterFile.h"
#include "io/TrialCsv.h"
#include "model/Error.h"
#include "service/SessionReport.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace learnid {

QList<QPair<QString, QByteArray>> trialCsvFiles(const QVector<TrialResult> &history,
                                                const QString &folder)
{
    const QDir dir(folder);
    QList<QPair<QString, QByteArray>> files;
    for (const TrialResult &t : history) {
        if (t.status() == TrialStatus::Refused)
            continue;
        const QString name = QStringLiteral("trial-%1.csv").arg(t.index, 3, 10, QLatin1Char('0'));
        files.append({dir.filePath(name), trialCsv(t.plan(), t.record)});
    }
    return files;
}

QString dcfPathFor(const QString &parameterPath)
{
    const QFileInfo info(parameterPath);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral(".dcf"));
}

QList<QPair<QString, QByteArray>> exportFiles(const CommissioningSession &session,
                                              const ExportRequest &request)
{
    QList<QPair<QString, QByteArray>> files;
    if (!request.reportPath.isEmpty())
        files.append({request.reportPath, sessionReportJson(session)});
    if (!request.parameterPath.isEmpty()) {
        const int k = request.estimateIndex >= 0 ? request.estimateIndex
                                                 : int(session.estimates().size()) - 1;
        ParameterFileContent content = parameterFileContent(session, k);
        if (request.nearestConsistent) {
            const EstimateConsistency c = session.consistency(k);
            if (!c.applicable || !c.nearestError.isEmpty()) {
                throw Error(QCoreApplication::translate("SessionExport",
                                                        "no consistent estimate near estimate "
                                                        "%1: %2")
                                .arg(k)
                                .arg(c.applicable
                                         ? c.nearestError
                                         : QCoreApplication::translate(
                                               "SessionExport", "only URDF robots have standard "
                                                                "parameters to make consistent")));
            }
            content.values = c.nearest;
            content.standardDeviations.resize(0);
            content.canWrites = objects::parameterWriteSequence(content.nodes(), c.nearest);
        }
        files.append({request.parameterPath, parameterFileToJson(content)});
        files.append({dcfPathFor(request.parameterPath), parameterDcfFragment(content)});
    }
    if (!request.trialCsvDir.isEmpty())
        files += trialCsvFiles(session.history(), request.trialCsvDir);
    return files;
}

QStringList writeExport(const CommissioningSession &session, const ExportRequest &request)
{
    const QList<QPair<QString, QByteArray>> files = exportFiles(session, request);
    if (!request.trialCsvDir.isEmpty() && !QDir().mkpath(request.trialCsvDir)) {
        throw Error(QCoreApplication::translate("SessionExport", "cannot create the folder %1")
                        .arg(QDir::toNativeSeparators(request.trialCsvDir)));
    }
    writeFilesAtomically(files);
    QStringList paths;
    for (const auto &file : files)
        paths << file.first;
    return paths;
}

} // namespace learnid
