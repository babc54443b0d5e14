#include "service/SessionReport.h"

#include "can/JointIdentity.h"
#include "can/ManufacturerObjects.h"
#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "service/StandardExport.h"
#include "session/TrialSeries.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cmath>

namespace learnid {

QJsonValue reportNumber(double v)
{
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue(QJsonValue::Null);
}

QJsonArray reportNumbers(const Eigen::VectorXd &v)
{
    QJsonArray a;
    for (Eigen::Index i = 0; i < v.size(); ++i)
        a.append(reportNumber(v[i]));
    return a;
}

namespace {

// The final estimate's standard parameters (completed by the CAD model made real bodies) with
// what the path determined (EstimateConsistency::standardDetermined; null when not known).
QJsonArray standardReport(const CommissioningSession &session, const ChainModel &chain)
{
    const int k = int(session.estimates().size()) - 1;
    const std::vector<double> determined = session.consistency(k).standardDetermined;
    const Eigen::VectorXd pi = chain.base().standardFromBase(
        session.currentEstimate(), realBodyPrior(chain.cadStandard(), chain.dof()));
    const QList<ParameterInfo> info = chain.standardParameters();
    QJsonArray list;
    for (int i = 0; i < int(info.size()); ++i) {
        const ParameterOrigin origin = parameterOrigin(determined, i);
        QJsonObject o;
        o.insert(QStringLiteral("name"), info.at(i).name);
        o.insert(QStringLiteral("unit"), info.at(i).unit);
        o.insert(QStringLiteral("value"), reportNumber(pi[i]));
        o.insert(QStringLiteral("determined"), origin == ParameterOrigin::Unknown
                                                   ? QJsonValue(QJsonValue::Null)
                                                   : QJsonValue(determined[size_t(i)]));
        o.insert(QStringLiteral("source"), origin == ParameterOrigin::Data ? QStringLiteral("data")
                                           : origin == ParameterOrigin::Prior
                                               ? QStringLiteral("prior")
                                               : QStringLiteral("unknown"));
        list.append(o);
    }
    return list;
}

} // namespace

QByteArray sessionReportJson(const CommissioningSession &session, const QString &endedEarly)
{
    QJsonObject root;
    root.insert(QStringLiteral("schema"), QStringLiteral("learnid-report/1"));
    root.insert(QStringLiteral("robot"), session.robot().description());
    root.insert(QStringLiteral("model"), session.model().id());
    root.insert(QStringLiteral("estimator"), session.law().id());
    QJsonArray names;
    for (const ParameterInfo &p : session.model().parameters())
        names.append(p.name);
    root.insert(QStringLiteral("parameters"), names);
    if (const auto truth = session.robot().trueParameters())
        root.insert(QStringLiteral("truth"), reportNumbers(*truth));

    QJsonArray trials;
    const QVector<Eigen::VectorXd> &estimates = session.estimates();
    for (int k = 0; k < estimates.size(); ++k) {
        const TrialResult *t = session.trialRunWith(k);
        if (!t)
            break; // the final estimate has not been run; it is in "final"
        QJsonObject o;
        o.insert(QStringLiteral("index"), k);
        o.insert(QStringLiteral("phi"), reportNumbers(estimates.at(k)));
        o.insert(QStringLiteral("status"), trialStatusName(t->status()));
        o.insert(QStringLiteral("maxTrackingErrorDeg"), reportNumbers(t->maxTrackingErrorDeg));
        o.insert(QStringLiteral("rmsTrackingErrorDeg"), reportNumbers(t->rmsTrackingErrorDeg));
        o.insert(QStringLiteral("durationS"), reportNumber(t->check.rule.duration));
        o.insert(QStringLiteral("samples"), t->record.samples());
        if (t->record.lateSetpoints > 0)
            o.insert(QStringLiteral("lateSetpoints"), t->record.lateSetpoints);
        if (t->update) {
            o.insert(QStringLiteral("condition"), reportNumber(t->update->condition));
            o.insert(QStringLiteral("rank"), t->update->rank);
            o.insert(QStringLiteral("residualRms"), reportNumbers(t->update->residualRms));
            o.insert(QStringLiteral("phiStd"), reportNumbers(t->update->phiStd));
        }
        if (!t->message.isEmpty())
            o.insert(QStringLiteral("message"), t->message);
        if (t->learnedFromPartial()) {
            o.insert(QStringLiteral("learnedFromPartialTrial"), true);
            o.insert(QStringLiteral("learnedSeconds"), t->partialSamples * t->record.samplePeriod);
        }
        if (!t->worseTracking.isEmpty())
            o.insert(QStringLiteral("worseTracking"), t->worseTracking);
        if (!t->seriesStop.isEmpty())
            o.insert(QStringLiteral("seriesStop"), t->seriesStop);
        trials.append(o);
    }
    root.insert(QStringLiteral("trials"), trials);
    root.insert(QStringLiteral("proposedEstimate"),
                proposedEstimate(session.history(), int(estimates.size())));
    if (!endedEarly.isEmpty())
        root.insert(QStringLiteral("endedEarly"), endedEarly);
    QJsonObject finalEstimate;
    finalEstimate.insert(QStringLiteral("phi"), reportNumbers(session.currentEstimate()));
    finalEstimate.insert(QStringLiteral("learningSteps"), int(estimates.size()) - 1);
    if (const auto *chain = dynamic_cast<const ChainModel *>(&session.model()))
        finalEstimate.insert(QStringLiteral("standardParameters"), standardReport(session, *chain));
    root.insert(QStringLiteral("final"), finalEstimate);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

ParameterFileContent parameterFileContent(const CommissioningSession &session, int estimateIndex,
                                          const QList<SdoWrite> &canWrites)
{
    const QVector<Eigen::VectorXd> &estimates = session.estimates();
    if (estimateIndex < 1 || estimateIndex >= estimates.size()) {
        throw Error(QCoreApplication::translate("SessionReport",
                                                "estimate %1 does not exist in this session")
                        .arg(estimateIndex));
    }
    // Estimate k was learned from the (k-1)-th learned trial; the figures of the trial run with
    // it (if any) tell how well it tracks.
    const TrialResult *source = session.trialRunWith(estimateIndex - 1);
    const TrialResult *verified = session.trialRunWith(estimateIndex);

    ParameterFileContent c;
    c.robotModel = session.model().id();
    c.robotDescription = session.robot().description();
    c.controller = session.scenario().controller;
    c.created = QDateTime::currentDateTimeUtc();
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.law = session.law().id();
    c.sourceTrial = source ? source->index : -1;
    c.parameters = session.model().parameters();
    c.values = estimates.at(estimateIndex);
    if (source && source->update) {
        c.standardDeviations = source->update->phiStd;
        c.residualRms = source->update->residualRms;
        c.condition = source->update->condition;
        c.rank = source->update->rank;
    }
    const TrialResult *tracking = verified ? verified : source;
    if (tracking) {
        c.maxTrackingErrorDeg = tracking->maxTrackingErrorDeg;
        c.rmsTrackingErrorDeg = tracking->rmsTrackingErrorDeg;
    }
    c.canWrites = canWrites;
    c.drives = session.robot().driveIdentities();
    return c;
}

ParameterFileContent parameterFileContent(const CommissioningSession &session, int estimateIndex)
{
    QList<int> nodes;
    for (int j = 1; j <= session.model().dof(); ++j)
        nodes << j;
    const QVector<Eigen::VectorXd> &estimates = session.estimates();
    const Eigen::VectorXd phi = estimateIndex >= 0 && estimateIndex < estimates.size()
                                    ? estimates.at(estimateIndex)
                                    : Eigen::VectorXd();
    // A robot on CAN (its drives known) gets the joint identity with the parameters.
    const quint32 identity = session.robot().driveIdentities().isEmpty()
                                 ? 0
                                 : objects::robotIdentityOf(session.model().id());
    return parameterFileContent(
        session, estimateIndex,
        phi.size() > 0 ? objects::parameterWriteSequence(nodes, phi, identity) : QList<SdoWrite>());
}

} // namespace learnid
