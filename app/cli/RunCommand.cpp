#include "cli/RunCommand.h"

#include "cli/PayloadRunCommand.h"
#include "cli/ResultTable.h"
#include "io/ScenarioFile.h"
#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/ModelCheck.h"
#include "service/RobotFactory.h"
#include "service/SessionWorker.h"
#include "session/TrialSeries.h"

#include <QCoreApplication>
#include <QDir>
#include <QLoggingCategory>
#include <csignal>

namespace learnid::cli {

namespace {

// Ctrl-C stops the running trial at its next sample instead of killing the process.
CommissioningSession *g_session = nullptr;
extern "C" void onInterrupt(int)
{
    if (g_session)
        g_session->requestCancel(); // an atomic store: async-signal-safe (no lock, unlike
                                    // SessionWorker::requestCancel)
}

Scenario loadScenario(const RunOptions &options)
{
    Scenario scenario =
        options.scenarioPath.isEmpty() ? Scenario{} : readScenarioFile(options.scenarioPath);
    if (options.law)
        scenario.law = *options.law;
    if (options.iterations)
        scenario.iterations = *options.iterations;
    if (!knownLearningLaws().contains(scenario.law)) {
        throw Error(
            QCoreApplication::translate("learnid-cli", "--estimator: unknown law '%1' (known: %2)")
                .arg(scenario.law, knownLearningLaws().join(QStringLiteral(", "))));
    }
    validateScenario(scenario);
    return scenario;
}

// The CAN options against the scenario (docs/can-protocol.md §8.5): without --nodes joint j is
// node j; the SYNC period is the scenario's controller.samplePeriod, and the bus load at it is
// checked before anything is sent. Returns the error naming the option, or empty.
QString checkCanAgainstScenario(RunOptions &options, const Scenario &scenario)
{
    if (options.robot == QLatin1String("sim"))
        return {};
    const int joints = scenario.controller.dof();
    if (!options.nodesGiven)
        options.can.nodes = defaultNodeList(joints);
    QStringList nodes;
    for (const int n : std::as_const(options.can.nodes))
        nodes << QString::number(n);
    if (options.can.nodes.size() != joints)
        return QCoreApplication::translate("learnid-cli",
                                           "--nodes %1: %2 node ids for a robot of %3 joints: one "
                                           "node per joint is needed")
            .arg(nodes.join(QLatin1Char(',')))
            .arg(options.can.nodes.size())
            .arg(joints);
    setSyncPeriod(options.can, scenario.controller.samplePeriod);
    const QString invalid = canRobotOptionsError(options.can);
    if (invalid.isEmpty())
        return {};
    return options.nodesGiven ? QCoreApplication::translate("learnid-cli", "--nodes %1: %2")
                                    .arg(nodes.join(QLatin1Char(',')), invalid)
                              : QCoreApplication::translate("learnid-cli", "--robot %1: %2")
                                    .arg(options.robot, invalid);
}

// The robot the options ask for, as the session service's factory makes it.
RobotRequest robotRequest(const RunOptions &options)
{
    RobotRequest request;
    if (options.robot == QLatin1String("can"))
        request.kind = RobotRequest::Kind::Can;
    else if (options.robot == QLatin1String("replay"))
        request.kind = RobotRequest::Kind::Replay;
    request.can = options.can;
    request.candumpFiles = options.candumpFiles;
    return request;
}

} // namespace

ExitCode runCommand(const RunOptions &given, QTextStream &out, QTextStream &err)
{
    RunOptions options = given;
    // The tool reports trials and errors itself: the session's log lines would repeat them.
    // --quiet silences the CAN robot's progress lines too; its warnings still show.
    QString rules = QStringLiteral("learnid.session=false\n");
    if (options.quiet)
        rules += QStringLiteral("learnid.*.info=false\nlearnid.*.debug=false\n");
    QLoggingCategory::setFilterRules(rules);
    Scenario scenario;
    try {
        scenario = loadScenario(options);
    } catch (const Error &e) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(e.message())
            << Qt::endl;
        return ExitBadInput;
    }
    if (options.robot == QLatin1String("replay")) {
        int recorded = 0;
        try {
            recorded = recordedTrialCount(options.candumpFiles);
        } catch (const Error &e) {
            err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1")
                       .arg(e.message())
                << Qt::endl;
            return ExitBadInput;
        }
        if (options.iterations && *options.iterations > recorded) {
            err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1")
                       .arg(QCoreApplication::translate(
                                "learnid-cli",
                                "--iterations: %1 trials need %1 recorded trials, the logs hold %2")
                                .arg(*options.iterations)
                                .arg(recorded))
                << Qt::endl;
            return ExitBadInput;
        }
        if (!options.iterations)
            scenario.iterations = recorded;
    }
    if (const QString canError = checkCanAgainstScenario(options, scenario); !canError.isEmpty()) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(canError)
            << Qt::endl;
        return ExitBadInput;
    }
    if (scenario.payload.enabled)
        return runPayloadCommand(options, scenario, robotRequest(options), out, err);

    // The session service, run synchronously in this thread: its robot factory, its session,
    // its export path, as the window uses them from its worker thread.
    SessionWorker worker;
    worker.setRobotRequest(robotRequest(options));
    std::optional<ExitCode> openFailure;
    QObject::connect(
        &worker, &SessionWorker::openFailed, [&](const QString &message, bool unreachable) {
            err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(message)
                << Qt::endl;
            openFailure = unreachable ? ExitTrialFailed : ExitBadInput;
        });
    worker.open(scenario);
    if (openFailure)
        return *openFailure;
    CommissioningSession *session = worker.session();

    if (!options.quiet) {
        err << QCoreApplication::translate("learnid-cli",
                                           "learnid-cli: %1, law %2, %3 learning trials")
                   .arg(session->robot().description(), scenario.law)
                   .arg(scenario.iterations)
            << Qt::endl;
        // The URDF's own values as a real robot's: a warning, the session runs all the same.
        if (const auto *chain = dynamic_cast<const ChainModel *>(&session->model())) {
            for (const QString &line : modelWarnings(*chain))
                err << QCoreApplication::translate("learnid-cli",
                                                   "learnid-cli: warning: the URDF as a real "
                                                   "robot: %1")
                           .arg(line)
                    << Qt::endl;
        }
        // What the trials can learn, before the robot moves.
        for (const QString &line : session->identifiability().describe(session->model()))
            err << QCoreApplication::translate("learnid-cli", "learnid-cli: %1").arg(line)
                << Qt::endl;
        QObject::connect(session, &CommissioningSession::trialFinished,
                         [&err](const TrialResult &t) { err << trialSummary(t) << Qt::endl; });
    }
    g_session = session;
    const auto previous = std::signal(SIGINT, onInterrupt);
    const bool completed = session->runTrials(scenario.iterations);
    std::signal(SIGINT, previous);
    g_session = nullptr;

    out << resultTable(*session);
    const int lastEstimate = int(session->estimates().size()) - 1;
    const EstimateConsistency consistency = session->consistency(lastEstimate);
    if (consistency.applicable) {
        out << QCoreApplication::translate("learnid-cli", "estimate %1:").arg(lastEstimate);
        for (const QString &line : consistency.describe(session->model()))
            out << QStringLiteral(" ") << line << QLatin1Char(';');
        if (!consistency.consistent) {
            out << QStringLiteral(" ")
                << (consistency.nearestError.isEmpty()
                        ? QCoreApplication::translate("learnid-cli",
                                                      "the nearest consistent estimate changes "
                                                      "the torques on the path by %1 % "
                                                      "(--consistent exports and applies it)")
                              .arg(consistency.pathTorqueChangePercent, 0, 'g', 3)
                        : QCoreApplication::translate("learnid-cli",
                                                      "no consistent estimate found: %1")
                              .arg(consistency.nearestError));
        }
        out << Qt::endl;
    }
    out.flush();
    // The estimate Accept proposes: the newest, unless a trial tracked worse (TrialSeries.h).
    const int proposed = proposedEstimate(session->history(), int(session->estimates().size()));
    QString endedEarly;
    if (!completed) {
        // The session ended early: the outputs asked for are still written, marked so, for
        // the technician to see what happened (the aborted trial's record in the trial CSVs).
        const TrialResult &last = session->history().constLast();
        endedEarly = last.seriesStop.isEmpty()
                         ? (last.message.isEmpty() ? trialStatusName(last.status()) : last.message)
                         : last.seriesStop;
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(endedEarly)
            << Qt::endl;
    } else if (proposed != int(session->estimates().size()) - 1 && !options.quiet) {
        err << QCoreApplication::translate("learnid-cli",
                                           "learnid-cli: estimate %1 tracked best: it is the one "
                                           "accepted, applied and exported")
                   .arg(proposed)
            << Qt::endl;
    }

    if (options.apply && completed) {
        const int last = proposed;
        QString error;
        QObject::connect(&worker, &SessionWorker::operationFailed,
                         [&error](SessionOperation, const QString &message) { error = message; });
        worker.accept(last, options.consistent);
        if (error.isEmpty())
            worker.apply();
        if (!error.isEmpty()) {
            err << QCoreApplication::translate("learnid-cli",
                                               "learnid-cli: error: apply failed: %1")
                       .arg(error)
                << Qt::endl;
            return ExitTrialFailed;
        }
        if (!options.quiet)
            err << QCoreApplication::translate("learnid-cli",
                                               "learnid-cli: estimate %1 applied to the robot")
                       .arg(last)
                << Qt::endl;
    }

    ExportRequest request;
    request.reportPath = options.reportPath;
    request.parameterPath = options.exportPath;
    request.estimateIndex = proposed;
    request.nearestConsistent = options.consistent;
    request.trialCsvDir = options.trialCsvDir;
    request.endedEarly = endedEarly;
    if (proposed < 1 && !request.parameterPath.isEmpty()) {
        // Nothing learned: there is no estimate to write as a parameter file.
        err << QCoreApplication::translate("learnid-cli",
                                           "learnid-cli: %1 not written: nothing was learned")
                   .arg(QDir::toNativeSeparators(request.parameterPath))
            << Qt::endl;
        request.parameterPath.clear();
    }
    if (!completed && request.reportPath.isEmpty() && request.trialCsvDir.isEmpty() &&
        request.parameterPath.isEmpty()) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: no files written")
            << Qt::endl;
        return ExitTrialFailed;
    }
    QStringList written;
    QString writeError;
    QObject::connect(&worker, &SessionWorker::exported,
                     [&](const QStringList &paths, const QString &error) {
                         written = paths;
                         writeError = error;
                     });
    worker.exportOutputs(request);
    if (!writeError.isEmpty()) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(writeError)
            << Qt::endl;
        return ExitWriteFailed;
    }
    if (!options.quiet || !completed)
        for (const QString &path : written)
            err << (completed ? QCoreApplication::translate("learnid-cli", "learnid-cli: wrote %1")
                              : QCoreApplication::translate("learnid-cli",
                                                            "learnid-cli: wrote %1 (the session "
                                                            "ended early)"))
                       .arg(QDir::toNativeSeparators(path))
                << Qt::endl;
    return completed ? ExitOk : ExitTrialFailed;
}

} // namespace learnid::cli
