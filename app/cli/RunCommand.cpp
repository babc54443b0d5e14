#include "cli/RunCommand.h"

#include "can/CandumpLog.h"
#include "canrobot/CanRobot.h"
#include "canrobot/CandumpReplayDevice.h"
#include "cli/ResultTable.h"
#include "io/AtomicFile.h"
#include "io/ParameterFile.h"
#include "io/ScenarioFile.h"
#include "io/SessionReport.h"
#include "io/TrialCsv.h"
#include "model/Error.h"
#include "model/ModelFactory.h"
#include "session/ScenarioRobot.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QLoggingCategory>
#include <atomic>
#include <csignal>

namespace learnid::cli {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("learnid-cli", text);
}

// Ctrl-C stops the running trial at its next sample instead of killing the process.
CommissioningSession *g_session = nullptr;
extern "C" void onInterrupt(int)
{
    if (g_session)
        g_session->requestCancel(); // an atomic store: async-signal-safe
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
        throw Error(tr("--estimator: unknown law '%1' (known: %2)")
                        .arg(scenario.law, knownLearningLaws().join(QStringLiteral(", "))));
    }
    validateScenario(scenario);
    return scenario;
}

// Every output of the run, built in memory so that nothing is written unless all can be.
QList<QPair<QString, QByteArray>> buildOutputs(const RunOptions &options,
                                               const CommissioningSession &session)
{
    QList<QPair<QString, QByteArray>> files;
    if (!options.reportPath.isEmpty())
        files.append({options.reportPath, sessionReportJson(session)});
    if (!options.exportPath.isEmpty()) {
        const int last = int(session.estimates().size()) - 1;
        const ParameterFileContent content = parameterFileContent(session, last);
        files.append({options.exportPath, parameterFileToJson(content)});
        const QFileInfo info(options.exportPath);
        files.append({info.dir().filePath(info.completeBaseName() + QStringLiteral(".dcf")),
                      parameterDcfFragment(content)});
    }
    if (!options.trialCsvDir.isEmpty())
        files += trialCsvFiles(session.history(), options.trialCsvDir);
    return files;
}

// The robot the options ask for. A CAN robot is connected here, so that an unreachable bus is
// reported before the session starts (connectError set, robot null).
std::shared_ptr<Robot> makeRobot(const RunOptions &options, const Scenario &scenario,
                                 std::shared_ptr<const RobotModel> model, QString *connectError)
{
    if (options.robot == QLatin1String("sim"))
        return makeSimulatedRobot(scenario, model);
    CanDeviceFactory factory;
    if (options.robot == QLatin1String("replay")) {
        QList<CandumpEntry> entries;
        for (const QString &file : options.candumpFiles)
            entries += candump::readFile(file); // throws Error naming file and line
        factory = [entries](QString *) {
            return new CandumpReplayDevice(entries);
        };
    }
    auto robot = std::make_shared<CanRobot>(std::move(model), options.can, std::move(factory));
    *connectError = robot->connectBus();
    return connectError->isEmpty() ? robot : nullptr;
}

} // namespace

ExitCode printScenarioCommand(QTextStream &out)
{
    out << QString::fromUtf8(scenarioToJson(Scenario{}));
    return ExitOk;
}

ExitCode runCommand(const RunOptions &options, QTextStream &out, QTextStream &err)
{
    // The tool reports trials and errors itself: the session's log lines would repeat them.
    // --quiet silences the CAN robot's progress lines too; its warnings still show.
    QString rules = QStringLiteral("learnid.session=false\n");
    if (options.quiet)
        rules += QStringLiteral("learnid.*.info=false\nlearnid.*.debug=false\n");
    QLoggingCategory::setFilterRules(rules);
    Scenario scenario;
    std::unique_ptr<CommissioningSession> session;
    try {
        scenario = loadScenario(options);
        if (options.robot == QLatin1String("replay") && !options.iterations)
            scenario.iterations = int(options.candumpFiles.size());
        const auto model = makeRobotModel(scenario.model);
        QString connectError;
        std::shared_ptr<Robot> robot = makeRobot(options, scenario, model, &connectError);
        if (!robot) {
            err << tr("learnid-cli: error: %1").arg(connectError) << Qt::endl;
            return ExitTrialFailed;
        }
        session = std::make_unique<CommissioningSession>(scenario, model, std::move(robot));
    } catch (const Error &e) {
        err << tr("learnid-cli: error: %1").arg(e.message()) << Qt::endl;
        return ExitBadInput;
    }

    if (!options.quiet) {
        err << tr("learnid-cli: %1, law %2, %3 learning trials")
                   .arg(session->robot().description(), scenario.law)
                   .arg(scenario.iterations)
            << Qt::endl;
        QObject::connect(session.get(), &CommissioningSession::trialFinished,
                         [&err](const TrialResult &t) { err << trialSummary(t) << Qt::endl; });
    }
    g_session = session.get();
    const auto previous = std::signal(SIGINT, onInterrupt);
    const bool completed = session->runTrials(scenario.iterations);
    std::signal(SIGINT, previous);
    g_session = nullptr;

    out << resultTable(*session);
    out.flush();
    if (!completed) {
        const TrialResult &last = session->history().constLast();
        err << tr("learnid-cli: error: %1")
                   .arg(last.message.isEmpty() ? trialStatusName(last.status()) : last.message)
            << Qt::endl
            << tr("learnid-cli: no files written") << Qt::endl;
        return ExitTrialFailed;
    }

    if (options.apply) {
        const int last = int(session->estimates().size()) - 1;
        QString error = session->accept(last);
        if (error.isEmpty())
            error = session->apply();
        if (!error.isEmpty()) {
            err << tr("learnid-cli: error: apply failed: %1").arg(error) << Qt::endl;
            return ExitTrialFailed;
        }
        if (!options.quiet)
            err << tr("learnid-cli: estimate %1 applied to the robot").arg(last) << Qt::endl;
    }

    try {
        const auto files = buildOutputs(options, *session);
        if (!options.trialCsvDir.isEmpty() && !QDir().mkpath(options.trialCsvDir))
            throw Error(tr("--trial-csv: cannot create the folder %1").arg(options.trialCsvDir));
        writeFilesAtomically(files);
        if (!options.quiet)
            for (const auto &f : files)
                err << tr("learnid-cli: wrote %1").arg(QDir::toNativeSeparators(f.first))
                    << Qt::endl;
    } catch (const Error &e) {
        err << tr("learnid-cli: error: %1").arg(e.message()) << Qt::endl;
        return ExitWriteFailed;
    }
    return ExitOk;
}

} // namespace learnid::cli
