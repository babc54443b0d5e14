#pragma once

// The payload's file loop (FileLoop.h with a scenario's payload section): the PayloadSession
// that `plan` and `learn` replay over the history's logged trials, and the history's estimate
// files, each the arm held fixed plus a payload section. Internal to service.

#include "io/LoopHistory.h"
#include "io/ParameterFilePayload.h"
#include "service/FileLoop.h"
#include "service/RecordedTrialRobot.h"
#include "session/PayloadSession.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <memory>

namespace learnid::loop {

/// A payload session whose robot answers with logged runs, one per trial.
struct PayloadReplay
{
    std::shared_ptr<RecordedTrialRobot> robot;
    std::unique_ptr<PayloadSession> session;
};

/// The scenario's payload session over runs. Throws Error as PayloadSession's constructor (a
/// robot that is not a URDF robot's, a refused prior, an unknown link), and when the history
/// learns the payload on another link than the scenario's.
PayloadReplay payloadReplay(const LoopScenario &s, const LoopHistory *history, const QString &dir,
                            QList<RecordedTrialRobot::Run> runs);

/// Runs the first `count` trials. Throws Error when one is planned otherwise than its log ran
/// (the robot's mismatch, naming both plan-ids) or is not usable (neither learned from nor a
/// baseline kept).
void replayHistoryTrials(PayloadReplay &replay, int count, const QString &dir);

/// The last trial before trial k that was learned from; none before the first (baseline trials,
/// payload.baselineTrials, are not).
const PayloadTrial *lastLearned(const PayloadSession &session, int k);

/// Estimate k of the session as the history stores it: the arm held fixed (the scenario's
/// robot.initialParameters) plus the payload section of the payload the session had before
/// trial k: the fit of lastLearned(), or the prior (every value kept at it) before the first.
ParameterFilePayload payloadEstimateSection(const PayloadSession &session, int k);
QByteArray payloadEstimateFile(const LoopScenario &s, const PayloadSession &session, int k);

/// Why the history's estimate file at path is not estimate k of the session (another arm,
/// another payload; the payload compared as written: mass, centre of mass, inertia, which
/// values are identified); empty when it is. Throws Error for a file it cannot read.
QString payloadEstimateDiffers(const QString &path, const LoopScenario &s,
                               const PayloadSession &session, int k);

/// The lines check.txt gives on what the next trial's path lets the fit see of the payload.
QStringList payloadIdentifiability(const PayloadSession &session, const PreTrialCheck &check);

} // namespace learnid::loop
