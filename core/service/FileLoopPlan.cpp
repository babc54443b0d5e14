#include "service/FileLoop.h"

#include "can/ManufacturerObjects.h"
#include "io/ParameterFile.h"
#include "model/Error.h"
#include "service/FileLoopParts.h"

#include <QCoreApplication>
#include <QDir>
#include <algorithm>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(FileLoop)
};

QString native(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

// Estimate 0 of a new history as a parameter file: no trial has produced it.
QByteArray initialEstimateFile(const LoopScenario &s, const Eigen::VectorXd &phi)
{
    ParameterFileContent c;
    c.robotModel = s.model->id();
    c.robotDescription = Text::tr("initial estimate of a learning loop through files");
    c.controller = s.scenario.controller;
    c.created = QDateTime::currentDateTimeUtc();
    c.toolVersion = QStringLiteral(LEARNID_VERSION);
    c.law = s.scenario.law;
    c.parameters = s.model->parameters();
    c.values = phi;
    c.canWrites = objects::parameterWriteSequence(c.nodes(), phi);
    return parameterFileToJson(c);
}

// The estimate the next trial runs with, and in words where it comes from. newInitial: it
// becomes estimate 0 of the history (a new history, or one that has learned nothing yet).
struct NextEstimate
{
    Eigen::VectorXd phi;
    QString source;
    bool newInitial = false;
};

NextEstimate nextEstimate(const LoopScenario &s, const PlanRequest &request,
                          const std::optional<LoopHistory> &history)
{
    NextEstimate e;
    const QDir dir(request.historyDir);
    if (!request.estimatePath.isEmpty()) {
        if (history && !history->trials.isEmpty()) {
            throw Error(Text::tr("--estimate: the history %1 has learned from %2 trials; its next "
                                 "trial runs with its newest estimate (leave out --estimate, or "
                                 "give another --history to start a new history)")
                            .arg(native(request.historyDir))
                            .arg(history->trials.size()));
        }
        e.phi = readEstimateFile(request.estimatePath, *s.model, QStringLiteral("--estimate"));
        e.source = native(request.estimatePath);
        e.newInitial = true;
    } else if (history) {
        const int k = int(history->estimates.size()) - 1;
        const QString path = dir.filePath(history->estimates.constLast());
        e.phi = readEstimateFile(path, *s.model, native(request.historyDir));
        e.source = Text::tr("estimate %1 of %2").arg(k).arg(native(path));
    } else {
        e.phi = s.scenario.initialParameters;
        e.source = Text::tr("the scenario's initial estimate");
        e.newInitial = true;
    }
    return e;
}

} // namespace

PlannedTrial planNextTrial(const LoopScenario &s, const PlanRequest &request)
{
    if (s.scenario.payload.enabled)
        return loop::planPayloadTrial(s, request);
    const std::optional<LoopHistory> read = readLoopHistory(request.historyDir);
    if (read)
        checkHistoryFits(*read, request.historyDir, s);
    const NextEstimate estimate = nextEstimate(s, request, read);

    // The session's own planning and check, with the estimate as the current one.
    Scenario scenario = s.scenario;
    scenario.initialParameters = estimate.phi;
    // Gentle (path.gentleTrials) until the history has learned that many times.
    const int learned = read && !estimate.newInitial ? int(read->estimates.size()) - 1 : 0;
    scenario.gentleTrials = std::max(0, scenario.gentleTrials - learned);
    const CommissioningSession session(scenario, s.model, std::make_shared<RecordedTrialRobot>());
    PlannedTrial planned;
    planned.check = session.checkNextTrial();
    planned.trialIndex = read ? int(read->trials.size()) : 0;
    planned.estimateSource = estimate.source;
    const QStringList identifiability =
        planned.check.passed() ? session.identifiability().describe(*s.model) : QStringList();
    planned.checkText =
        preTrialCheckText(planned.check, planned.trialIndex, estimate.source, identifiability);
    if (!planned.passed())
        return planned;

    const LoopHistory history = read ? *read : loop::newLoopHistory(s);
    const QByteArray initial =
        estimate.newInitial ? initialEstimateFile(s, estimate.phi) : QByteArray();
    loop::addPlanFiles(planned, s, request, history, estimate.newInitial ? &initial : nullptr);
    return planned;
}

} // namespace learnid
