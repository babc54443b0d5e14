#include "service/SessionExport.h"

#include "can/ManufacturerObjects.h"
#include "io/AtomicFile.h"
#include "io/ParameterFile.h"
#include "io/TrialCsv.h"
#include "io/UrdfExport.h"
#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "service/SessionReport.h"
#include "service/StandardExport.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace learnid {

QList<QPair<QString, QByteArray>> trialCsvFiles(const QVector<TrialResult> &history,
                                                const QString &folder)
{
    QList<QPair<QString, QByteArray>> files;
    for (const TrialResult &t : history) {
        if (t.status() != TrialStatus::Refused)
            files.append({trialCsvPath(folder, t.index), trialCsv(t.plan(), t.record)});
    }
    return files;
}

QString trialCsvPath(const QString &folder, int index)
{
    return QDir(folder).filePath(
        QStringLiteral("trial-%1.csv").arg(index, 3, 10, QLatin1Char('0')));
}

QString dcfPathFor(const QString &parameterPath)
{
    const QFileInfo info(parameterPath);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral(".dcf"));
}

void appendParameterFiles(QList<QPair<QString, QByteArray>> &files, const QString &path,
                          const ParameterFileContent &content)
{
    files.append({path, parameterFileToJson(content)});
    files.append({dcfPathFor(path), parameterDcfFragment(content)});
}

QStringList writeExportFiles(const QList<QPair<QString, QByteArray>> &files)
{
    writeFilesAtomically(files);
    QStringList paths;
    for (const auto &file : files)
        paths << file.first;
    return paths;
}

QByteArray urdfWithStandard(const ChainModel &model, const QByteArray &xml, const QString &source,
                            const Eigen::VectorXd &pi, const QString &comment,
                            const std::vector<double> &determined)
{
    const int n = model.dof();
    std::vector<InertialParameters> bodies(size_t(n), InertialParameters::Zero());
    for (int j = 0; j < n; ++j)
        bodies[size_t(j)] = pi.segment<10>(10 * j);
    return identifiedUrdf(xml, source, model.chain(), bodies, urdfJointTerms(model, pi), comment,
                          determinedNotes(model, pi, determined));
}

namespace {

// The session's robot URDF with estimate k as real bodies.
// The verdict on estimate k with its nearest consistent estimate, or Error saying why there is
// none (the parameter file's --consistent and the URDF export alike).
EstimateConsistency consistencyWithNearest(const CommissioningSession &session, int k)
{
    const EstimateConsistency c = session.consistency(k, NearestEstimate::Always);
    if (!c.applicable || !c.nearestError.isEmpty()) {
        throw Error(QCoreApplication::translate("SessionExport",
                                                "no consistent estimate near estimate %1: %2")
                        .arg(k)
                        .arg(c.applicable ? c.nearestError
                                          : QCoreApplication::translate(
                                                "SessionExport", "only URDF robots have standard "
                                                                 "parameters to make consistent")));
    }
    return c;
}

// Estimate k's standard parameters: completed by the CAD model (made real bodies), or, when a
// consistent one is asked for, its nearest plausible estimate where there is one.
Eigen::VectorXd standardOfEstimate(const CommissioningSession &session, const ChainModel &chain,
                                   int k, const EstimateConsistency &c, bool consistent)
{
    // The nearest plausible estimate whenever there is one: a consistent estimate's CAD
    // completion can still hold point masses and needles.
    if (consistent && c.nearestStandard.size() > 0)
        return c.nearestStandard;
    return chain.base().standardFromBase(session.estimates().at(k),
                                         realBodyPrior(chain.cadStandard(), chain.dof()));
}

QByteArray sessionUrdf(const CommissioningSession &session, int k, const QString &comment)
{
    const auto *chain = dynamic_cast<const ChainModel *>(&session.model());
    if (!chain) {
        throw Error(
            QCoreApplication::translate("SessionExport", "only URDF robots have a URDF to export"));
    }
    // Without a trial there is no path to weigh by: a consistent estimate's completion then.
    const EstimateConsistency c = consistencyWithNearest(session, k);
    const Eigen::VectorXd pi = standardOfEstimate(session, *chain, k, c, true);
    const Scenario &s = session.scenario();
    const QString source = urdfFileOf(s.model, s.urdf);
    return urdfWithStandard(*chain, readFile(source), source, pi, comment, c.standardDetermined);
}

} // namespace

QList<QPair<QString, QByteArray>> exportFiles(const CommissioningSession &session,
                                              const ExportRequest &request)
{
    QList<QPair<QString, QByteArray>> files;
    if (!request.reportPath.isEmpty())
        files.append({request.reportPath, sessionReportJson(session, request.endedEarly)});
    const int k =
        request.estimateIndex >= 0 ? request.estimateIndex : int(session.estimates().size()) - 1;
    if (!request.parameterPath.isEmpty()) {
        ParameterFileContent content = parameterFileContent(session, k);
        const auto *chain = dynamic_cast<const ChainModel *>(&session.model());
        if (request.nearestConsistent) {
            const EstimateConsistency c = consistencyWithNearest(session, k);
            content.values = c.nearest;
            content.standardDeviations.resize(0);
            content.canWrites = objects::parameterWriteSequence(content.nodes(), c.nearest);
            setStandardParameters(content, *chain, standardOfEstimate(session, *chain, k, c, true),
                                  c.standardDetermined);
        } else if (chain) {
            const EstimateConsistency c = session.consistency(k);
            setStandardParameters(content, *chain, standardOfEstimate(session, *chain, k, c, false),
                                  c.standardDetermined);
        }
        appendParameterFiles(files, request.parameterPath, content);
    }
    if (!request.trialCsvDir.isEmpty())
        files += trialCsvFiles(session.history(), request.trialCsvDir);
    if (!request.urdfPath.isEmpty())
        files.append({request.urdfPath, sessionUrdf(session, k, request.urdfComment)});
    return files;
}

QStringList writeExport(const CommissioningSession &session, const ExportRequest &request)
{
    const QList<QPair<QString, QByteArray>> files = exportFiles(session, request);
    if (!request.trialCsvDir.isEmpty() && !QDir().mkpath(request.trialCsvDir)) {
        throw Error(QCoreApplication::translate("SessionExport", "cannot create the folder %1")
                        .arg(QDir::toNativeSeparators(request.trialCsvDir)));
    }
    return writeExportFiles(files);
}

} // namespace learnid
