#include "service/FileLoopPayload.h"

#include "can/ManufacturerObjects.h"
#include "identify/PayloadObservability.h"
#include "io/ParameterFile.h"
#include "model/Error.h"
#include "service/FileLoopParts.h"
#include "service/PayloadExport.h"

#include <QCoreApplication>
#include <QDir>
#include <limits>

namespace learnid::loop {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(FileLoop)
};

bool samePayload(const ParameterFilePayload &a, const ParameterFilePayload &b)
{
    return a.link == b.link && a.mass == b.mass && a.com == b.com &&
           a.inertiaAtCom == b.inertiaAtCom && a.identified == b.identified;
}

} // namespace

PayloadReplay payloadReplay(const LoopScenario &s, const LoopHistory *history, const QString &dir,
                            QList<RecordedTrialRobot::Run> runs)
{
    PayloadReplay replay;
    replay.robot = std::make_shared<RecordedTrialRobot>(std::move(runs));
    replay.session = std::make_unique<PayloadSession>(s.scenario, s.model, replay.robot);
    const QString link = replay.session->payloadModel().link();
    if (history && history->payloadLink != link)
        throw Error(Text::tr("the history %1 learns the payload on %2, the scenario's payload.link "
                             "is %3: a history keeps its link (give another --history for "
                             "another)")
                        .arg(native(dir), history->payloadLink, link));
    return replay;
}

void replayHistoryTrials(PayloadReplay &replay, int count, const QString &dir)
{
    for (int k = 0; k < count; ++k) {
        const PayloadTrial &t = replay.session->runTrial();
        if (!replay.robot->mismatch().isEmpty())
            throw Error(replay.robot->mismatch());
        if (!t.usable())
            throw Error(Text::tr("the history %1 does not replay: %2").arg(native(dir), t.message));
    }
}

const PayloadTrial *lastLearned(const PayloadSession &session, int k)
{
    const PayloadTrial *learned = nullptr;
    for (int i = 0; i < k && i < int(session.history().size()); ++i)
        if (session.history().at(size_t(i)).learned())
            learned = &session.history().at(size_t(i));
    return learned;
}

ParameterFilePayload payloadEstimateSection(const PayloadSession &session, int k)
{
    const QString link = session.payloadModel().link();
    if (const PayloadTrial *t = lastLearned(session, k))
        return payloadSection(t->fit->estimate, link);
    ParameterFilePayload p;
    p.link = link;
    const PayloadBody prior = payloadBody(session.prior().parameters());
    p.mass = prior.mass;
    p.com = prior.com;
    const Eigen::Matrix3d &i = prior.inertiaAtCom;
    p.inertiaAtCom = {i(0, 0), i(0, 1), i(1, 1), i(0, 2), i(1, 2), i(2, 2)};
    return p; // identified: none; standardUncertainty: NaN
}

QByteArray payloadEstimateFile(const LoopScenario &s, const PayloadSession &session, int k)
{
    ParameterFileContent c;
    c.robotModel = s.model->id();
    const PayloadTrial *t = lastLearned(session, k);
    c.robotDescription =
        t ? Text::tr("the arm held fixed and the payload learned from the trials up to trial %1: "
                     "estimate %2 of a payload's learning loop through files")
                .arg(t->index)
                .arg(k)
          : Text::tr("the arm held fixed and the payload's prior: estimate %1 of a payload's "
                     "learning loop through files")
                .arg(k);
    c.controller = s.scenario.controller;
    c.created = QDateTime::currentDateTimeUtc();
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.law = s.scenario.law;
    c.parameters = s.model->parameters();
    c.values = s.scenario.initialParameters;
    c.canWrites = objects::parameterWriteSequence(c.nodes(), c.values);
    c.payload = payloadEstimateSection(session, k);
    addPayloadWrites(c, session.payloadModel().payloadLink(), c.payload->parameters());
    if (t) {
        c.sourceTrial = t->index;
        c.maxTrackingErrorDeg = t->maxTrackingErrorDeg;
        c.rmsTrackingErrorDeg = t->rmsTrackingErrorDeg;
        c.residualRms = t->fit->trainingRms;
        const PayloadObservability &o = t->fit->estimate.observability;
        c.condition = o.rank > 0 ? o.condition : std::numeric_limits<double>::infinity();
        c.rank = o.rank;
    }
    return parameterFileToJson(c);
}

QString payloadEstimateDiffers(const QString &path, const LoopScenario &s,
                               const PayloadSession &session, int k)
{
    const ParameterFileContent c = readParameterFile(path);
    if (c.robotModel != s.model->id() || c.values.size() != s.scenario.initialParameters.size() ||
        c.values != s.scenario.initialParameters)
        return Text::tr("%1 holds another arm model than the scenario's robot.initialParameters: "
                        "a history keeps the arm it learns the payload on")
            .arg(native(path));
    if (!c.payload || !samePayload(*c.payload, payloadEstimateSection(session, k))) {
        if (k == 0)
            return Text::tr("%1 holds another payload prior than the scenario's payload section: "
                            "a history keeps its prior")
                .arg(native(path));
        return Text::tr("%1 is not the payload estimate %2 that the history's trials give with "
                        "this scenario: are its payload section and estimator the history's?")
            .arg(native(path))
            .arg(k);
    }
    return {};
}

QStringList payloadIdentifiability(const PayloadSession &session, const PreTrialCheck &check)
{
    if (!check.planningError.isEmpty())
        return {};
    const JointTrajectory &d = check.plan.desired;
    const PayloadObservability o =
        payloadPathObservability(session.payloadModel(), d.q, d.qd, d.qdd);
    const QString link = session.payloadModel().link();
    QStringList lines{Text::tr("the path determines %1 of the payload's 10 parameters on %2")
                          .arg(o.rank)
                          .arg(link)};
    lines += o.advice(link);
    if (const PayloadPathChange change = session.pathChange(); change.valid())
        lines << change.describe(session.payloadModel().arm());
    return lines;
}

} // namespace learnid::loop
