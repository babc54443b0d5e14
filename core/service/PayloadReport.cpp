#include "service/PayloadReport.h"

#include "io/JsonTree.h"
#include "io/ParameterFilePayload.h"
#include "service/PayloadExport.h"
#include "service/PayloadRun.h"
#include "service/SessionReport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace learnid {

namespace {

QJsonObject trialEntry(const PayloadTrial &t)
{
    const PayloadTrialRow row = payloadTrialRow(t);
    QJsonObject o{{QStringLiteral("index"), t.index},
                  {QStringLiteral("kind"),
                   t.baseline ? QStringLiteral("baseline") : QStringLiteral("payload")},
                  {QStringLiteral("status"), trialStatusName(t.record.status)},
                  {QStringLiteral("samples"), t.record.samples()},
                  {QStringLiteral("learned"), t.learned()},
                  {QStringLiteral("learnedFromPartialTrial"), t.partial},
                  {QStringLiteral("maxTrackingErrorDeg"), reportNumbers(t.maxTrackingErrorDeg)},
                  {QStringLiteral("rmsTrackingErrorDeg"), reportNumbers(t.rmsTrackingErrorDeg)}};
    if (t.learned()) {
        QJsonArray identified;
        for (const bool v : row.identified)
            identified.append(v);
        o.insert(QStringLiteral("mass"), row.mass);
        o.insert(QStringLiteral("com"), reportNumbers(row.com));
        o.insert(QStringLiteral("identified"), identified);
        o.insert(QStringLiteral("updateCpuMs"), row.updateMs);
    }
    if (t.record.lateSetpoints > 0)
        o.insert(QStringLiteral("lateSetpoints"), t.record.lateSetpoints);
    if (!t.message.isEmpty())
        o.insert(QStringLiteral("message"), t.message);
    return o;
}

} // namespace

QByteArray payloadReportJson(const PayloadSession &session, const QString &endedEarly)
{
    const PayloadPrior &prior = session.prior();
    const QString link = session.payloadModel().link();
    QJsonArray trials;
    const PayloadTrial *learned = nullptr;
    for (const PayloadTrial &t : session.history()) {
        trials.append(trialEntry(t));
        if (t.learned())
            learned = &t;
    }
    QJsonObject result;
    if (learned) {
        result.insert(QStringLiteral("learnedTrial"), learned->index);
        result.insert(
            QStringLiteral("payload"),
            payloadSectionTree(payloadSection(learned->fit->estimate, link)).toJsonValue());
    }
    const Scenario &s = session.scenario();
    QJsonObject report{
        {QStringLiteral("schema"), QStringLiteral("learnid-payload-report/1")},
        {QStringLiteral("robot"), session.robot().description()},
        {QStringLiteral("model"), s.model},
        {QStringLiteral("link"), link},
        {QStringLiteral("prior"), QJsonObject{{QStringLiteral("mass"), prior.mass},
                                              {QStringLiteral("com"), reportNumbers(prior.com)}}},
        {QStringLiteral("bound"), prior.bound.describe()},
        {QStringLiteral("baselineTrials"), s.payload.baselineTrials},
        {QStringLiteral("payloadTrials"), s.iterations},
        {QStringLiteral("trials"), trials},
        {QStringLiteral("result"), learned ? QJsonValue(result) : QJsonValue(QJsonValue::Null)}};
    if (!endedEarly.isEmpty())
        report.insert(QStringLiteral("endedEarly"), endedEarly);
    return QJsonDocument(report).toJson(QJsonDocument::Indented);
}

} // namespace learnid
