// `learnid-cli plan` with a payload section (FileLoop.h, docs/cli.md): the history's trials
// replayed through a PayloadSession, then its next trial planned and checked.
#include "model/Error.h"
#include "service/FileLoopParts.h"
#include "service/FileLoopPayload.h"

#include <QCoreApplication>

namespace learnid::loop {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(FileLoop)
};

// In words: what the next trial's feedforward is built with, and for a baseline trial that the
// payload must not be mounted. path: the history's newest estimate file.
QString estimateSource(const PayloadSession &session, int k, const QString &path)
{
    if (session.nextTrialIsBaseline())
        return Text::tr("the arm's model held fixed (robot.initialParameters) alone: trial %1 is "
                        "a baseline trial (payload.baselineTrials), run it WITHOUT the payload "
                        "mounted")
            .arg(k);
    if (const PayloadTrial *t = lastLearned(session, k))
        return Text::tr("the arm's model held fixed (robot.initialParameters) and the payload "
                        "learned from the trials up to trial %1 (estimate %2 of %3)")
            .arg(t->index)
            .arg(k)
            .arg(native(path));
    return Text::tr("the arm's model held fixed (robot.initialParameters) and the payload's "
                    "prior (payload section)");
}

} // namespace

PlannedTrial planPayloadTrial(const LoopScenario &s, const PlanRequest &request)
{
    if (!request.estimatePath.isEmpty())
        throw Error(Text::tr("--estimate: a scenario with a payload section plans with the arm's "
                             "model it holds fixed (robot.initialParameters) and the payload its "
                             "history has learned, the prior (payload section) first: leave out "
                             "--estimate"));
    const std::optional<LoopHistory> read = readLoopHistory(request.historyDir);
    if (read)
        checkHistoryFits(*read, request.historyDir, s);
    const QDir dir(request.historyDir);
    const int learned = read ? int(read->trials.size()) : 0;
    // A history that has learned keeps its link, arm and prior; one that has not takes the
    // scenario's anew (estimate 0 rewritten, its plans so far leave it).
    PayloadReplay replay = payloadReplay(s, learned > 0 ? &*read : nullptr, request.historyDir,
                                         read ? historyRuns(*read, dir, angularJoints(*s.model))
                                              : QList<RecordedTrialRobot::Run>());
    // Estimate 0: the scenario's link, arm and prior.
    bool newInitial = !read;
    if (read) {
        const QString differs = payloadEstimateDiffers(dir.filePath(read->estimates.constFirst()),
                                                       s, *replay.session, 0);
        if (!differs.isEmpty() && learned > 0)
            throw Error(Text::tr("%1 (give another --history to start anew)").arg(differs));
        newInitial = !differs.isEmpty();
    }
    replayHistoryTrials(replay, learned, request.historyDir);
    for (int k = 1; k <= learned; ++k) {
        const QString differs =
            payloadEstimateDiffers(dir.filePath(read->estimates.at(k)), s, *replay.session, k);
        if (!differs.isEmpty())
            throw Error(differs);
    }

    const PayloadSession &session = *replay.session;
    PlannedTrial planned;
    planned.check = session.checkNextTrial();
    planned.trialIndex = learned;
    planned.estimateSource = estimateSource(
        session, learned, read ? dir.filePath(read->estimates.constLast()) : QString());
    const QStringList identifiability =
        planned.check.passed() ? payloadIdentifiability(session, planned.check) : QStringList();
    planned.checkText = preTrialCheckText(planned.check, planned.trialIndex, planned.estimateSource,
                                          identifiability);
    if (!planned.passed())
        return planned;

    LoopHistory history = read ? *read : newLoopHistory(s);
    history.payloadLink = session.payloadModel().link();
    const QByteArray initial = newInitial ? payloadEstimateFile(s, session, 0) : QByteArray();
    addPlanFiles(planned, s, request, history, newInitial ? &initial : nullptr);
    return planned;
}

} // namespace learnid::loop
