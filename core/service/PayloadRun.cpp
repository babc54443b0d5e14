#include "service/PayloadRun.h"

#include "service/PayloadReport.h"
#include "service/PayloadRunExport.h"

#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "service/RobotFactory.h"
#include "session/ScenarioRobot.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadRun)
};

} // namespace

namespace {

// The scenario checked and completed, and its robot's model.
std::pair<Scenario, std::shared_ptr<const RobotModel>> payloadScenario(const Scenario &given)
{
    if (!given.payload.enabled)
        throw Error(Text::tr("payload: the scenario has no payload section"));
    validateScenario(given); // every key, the payload's on its robot's model, named
    const auto model = makeRobotModel(given.model, given.urdf);
    if (!model)
        throw Error(Text::tr("robot.model: unknown robot model \"%1\"").arg(given.model));
    return {withRobotDefaults(given, *model), model};
}

} // namespace

PayloadRunSession makeSimulatedPayloadSession(const Scenario &given)
{
    const auto [scenario, model] = payloadScenario(given);
    PayloadRunSession run;
    run.model = std::dynamic_pointer_cast<const ChainModel>(model);
    run.session =
        std::make_unique<PayloadSession>(scenario, model, makeSimulatedRobot(scenario, model),
                                         makeSimulatedBareRobot(scenario, model));
    return run;
}

PayloadRunSession makeCanPayloadSession(const Scenario &given, const RobotRequest &request)
{
    const auto [scenario, model] = payloadScenario(given);
    PayloadRunSession run;
    run.model = std::dynamic_pointer_cast<const ChainModel>(model);
    RobotConnection connection = makeRobot(request, scenario, model);
    if (!connection.robot) {
        run.connectError = connection.connectError;
        return run;
    }
    run.session = std::make_unique<PayloadSession>(scenario, model, std::move(connection.robot));
    return run;
}

PayloadMounting payloadMountingBefore(int trial, int baselineTrials)
{
    if (baselineTrials <= 0)
        return PayloadMounting::Unchanged;
    if (trial == 0)
        return PayloadMounting::TakeOff;
    return trial == baselineTrials ? PayloadMounting::Mount : PayloadMounting::Unchanged;
}

PayloadPreview payloadPreview(PayloadSession &session)
{
    PayloadPreview p;
    p.robotDescription = session.robot().description();
    p.link = session.payloadModel().link();
    p.bound = session.prior().bound.describe();
    p.baselineTrials = session.scenario().payload.baselineTrials;
    p.trials = session.scenario().iterations;
    p.observability = session.observability();
    p.advice = p.observability.advice(p.link);
    if (const PayloadPathChange change = session.pathChange(); change.valid())
        p.advice << change.describe(session.payloadModel().arm());
    const PreTrialCheck check = session.checkNextTrial();
    if (!check.passed())
        p.checkReason = check.reason();
    p.jointNames = jointNames(session.payloadModel().arm());
    return p;
}

PayloadTrialRow payloadTrialRow(const PayloadTrial &t)
{
    PayloadTrialRow row;
    row.index = t.index;
    row.baseline = t.baseline;
    row.usable = t.usable();
    row.learned = t.learned();
    row.partial = t.partial;
    if (t.maxTrackingErrorDeg.size() > 0) {
        row.maxTrackingErrorDeg = t.maxTrackingErrorDeg.maxCoeff();
        row.rmsTrackingErrorDeg = t.rmsTrackingErrorDeg.maxCoeff();
    }
    if (t.fit) {
        const PayloadEstimate &e = t.fit->estimate;
        row.mass = e.body.mass;
        row.com = e.body.com;
        row.identified = e.bodyIdentified;
        row.updateMs = 1000.0 * t.updateCpuSeconds;
    }
    row.message = t.message;
    if (t.record.samples() > 0)
        row.curves = trackingErrorCurves(t.index, t.plan(), t.record);
    return row;
}

PayloadRunRecord payloadRunRecord(const PayloadSession &s, const QString &endedEarly)
{
    PayloadRunRecord r{payloadReportJson(s, endedEarly), {}, endedEarly};
    for (auto &[path, content] : payloadTrialCsvFiles(s.history(), QString()))
        r.trialCsvs.append({QFileInfo(path).fileName(), std::move(content)});
    return r;
}

PayloadRunResult payloadRunResult(const PayloadRunSession &run)
{
    const PayloadSession &s = *run.session;
    PayloadRunResult r;
    r.scenario = s.scenario();
    r.model = run.model;
    r.robotDescription = run.session->robot().description();
    r.link = s.payloadModel().link();
    r.prior = s.prior();
    const PayloadTrial *learned = nullptr;
    for (const PayloadTrial &t : s.history()) {
        r.trials.push_back(payloadTrialRow(t));
        if (t.learned())
            learned = &t;
    }
    if (!learned)
        throw Error(Text::tr("no trial was learned from: the payload is not estimated"));
    r.learnedTrial = learned->index;
    r.record = payloadRunRecord(s);
    r.fit = *learned->fit;
    r.maxTrackingErrorDeg = learned->maxTrackingErrorDeg;
    r.rmsTrackingErrorDeg = learned->rmsTrackingErrorDeg;
    return r;
}

QString applyRunPayload(const PayloadRunSession &run, const PayloadRunResult &result)
{
    const PayloadLink &link = run.session->payloadModel().payloadLink();
    return run.session->robot().applyPayload(link.joint + 1,
                                             payloadInBody(link, result.fit.estimate.parameters));
}

} // namespace learnid
