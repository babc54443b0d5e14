#include "cli/PayloadRunCommand.h"

#include "cli/PayloadCommand.h"
#include "cli/PayloadTrialTable.h"
#include "model/Error.h"
#include "service/PayloadReport.h"
#include "service/PayloadRunExport.h"
#include "service/SessionExport.h"

#include <QCoreApplication>
#include <QDir>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <poll.h>
#include <unistd.h>

namespace learnid::cli {

namespace {

// Ctrl-C stops the running trial at its next sample, or the wait for the technician.
PayloadSession *g_session = nullptr;
std::atomic<bool> g_interrupted{false};
extern "C" void onPayloadInterrupt(int)
{
    g_interrupted.store(true); // lock-free atomic stores: async-signal-safe
    if (g_session)
        g_session->requestCancel();
}

// Waits for a line on stdin: true when one came, false at its end or on Ctrl-C. Reads byte by
// byte (nothing after the line is taken) and wakes every 200 ms to see Ctrl-C.
bool waitForEnter()
{
    while (!g_interrupted.load()) {
        pollfd in{STDIN_FILENO, POLLIN, 0};
        const int ready = ::poll(&in, 1, 200);
        if (ready < 0 && errno != EINTR)
            return false;
        if (ready <= 0)
            continue;
        char c = 0;
        if (::read(STDIN_FILENO, &c, 1) != 1)
            return false;
        if (c == '\n')
            return true;
    }
    return false;
}

// On the CAN robot the technician takes the payload off before the baseline trials and mounts
// it after them (the simulated robot has a second, bare arm for them). Before trial i: asks and
// waits when the payload has to change; returns why the run cannot go on, or empty.
QString confirmMounting(const PayloadSession &session, int i, const QString &link, QTextStream &err)
{
    const int baselines = session.scenario().payload.baselineTrials;
    const PayloadMounting mounting = payloadMountingBefore(i, baselines);
    if (mounting == PayloadMounting::Unchanged)
        return {};
    err << (mounting == PayloadMounting::TakeOff
                ? QCoreApplication::translate("learnid-cli",
                                              "learnid-cli: take the payload off %1 for the "
                                              "%2 baseline trial(s), then press Enter "
                                              "(Ctrl-C stops)")
                      .arg(link)
                      .arg(baselines)
                : QCoreApplication::translate("learnid-cli",
                                              "learnid-cli: the baseline trials are done: "
                                              "mount the payload on %1, then press Enter "
                                              "(Ctrl-C stops)")
                      .arg(link))
        << Qt::endl;
    if (waitForEnter())
        return {};
    return g_interrupted.load()
               ? QCoreApplication::translate("learnid-cli", "stopped (Ctrl-C) before trial %1")
                     .arg(i)
               : QCoreApplication::translate("learnid-cli",
                                             "before trial %1: no answer on standard input, so "
                                             "the payload's state was not confirmed")
                     .arg(i);
}

// The options a payload session does not offer yet, by name; empty when none is set.
QString unsupportedOption(const RunOptions &o)
{
    if (o.robot != QLatin1String("sim") && o.robot != QLatin1String("can"))
        return QStringLiteral("--robot %1").arg(o.robot);
    const std::pair<bool, const char *> options[] = {{o.consistent, "--consistent"}};
    for (const auto &[set, name] : options)
        if (set)
            return QString::fromLatin1(name);
    return {};
}

// The outputs asked for, all or none: --report and --trial-csv (every trial that moved), also
// of a run that ended early (endedEarly: why), and --export (the parameter file and its DCF
// fragment, of a completed run only: the payload of a run that ended early is not the one a
// complete run learns).
ExitCode writePayloadOutputs(const RunOptions &options, const PayloadRunSession &run,
                             const QString &endedEarly, QTextStream &err)
{
    const bool completed = endedEarly.isEmpty();
    if (!completed && !options.exportPath.isEmpty())
        err << QCoreApplication::translate(
                   "learnid-cli",
                   "learnid-cli: %1 not written: the session ended before its last trial")
                   .arg(QDir::toNativeSeparators(options.exportPath))
            << Qt::endl;
    try {
        QList<QPair<QString, QByteArray>> files;
        if (!options.reportPath.isEmpty())
            files.append({options.reportPath, payloadReportJson(*run.session, endedEarly)});
        if (!options.trialCsvDir.isEmpty())
            files += payloadTrialCsvFiles(run.session->history(), options.trialCsvDir);
        if (completed && !options.exportPath.isEmpty()) {
            LogExportRequest request;
            request.parameterPath = options.exportPath;
            files += payloadRunExportFiles(payloadRunResult(run), request);
        }
        if (files.isEmpty())
            return ExitOk;
        if (!options.trialCsvDir.isEmpty() && !QDir().mkpath(options.trialCsvDir))
            throw Error(QCoreApplication::translate("learnid-cli", "cannot create the folder %1")
                            .arg(QDir::toNativeSeparators(options.trialCsvDir)));
        const QStringList written = writeExportFiles(files);
        if (!options.quiet || !completed)
            for (const QString &path : written)
                err << (completed
                            ? QCoreApplication::translate("learnid-cli", "learnid-cli: wrote %1")
                            : QCoreApplication::translate(
                                  "learnid-cli", "learnid-cli: wrote %1 (the session ended early)"))
                           .arg(QDir::toNativeSeparators(path))
                    << Qt::endl;
    } catch (const Error &e) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(e.message())
            << Qt::endl;
        return ExitWriteFailed;
    }
    return ExitOk;
}

} // namespace

ExitCode runPayloadCommand(const RunOptions &options, const Scenario &given,
                           const RobotRequest &robot, QTextStream &out, QTextStream &err)
{
    const auto fail = [&err](const QString &message, ExitCode code) {
        err << QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(message)
            << Qt::endl;
        return code;
    };
    if (options.apply && options.robot != QLatin1String("can")) {
        // The payload is written to drives (0x2500); the simulated robot carries it already.
        return fail(QCoreApplication::translate("learnid-cli",
                                                "--apply: the simulated robot carries its payload "
                                                "already; --apply writes the payload to the "
                                                "drives of --robot can"),
                    ExitBadInput);
    }
    if (const QString option = unsupportedOption(options); !option.isEmpty()) {
        return fail(QCoreApplication::translate(
                        "learnid-cli",
                        "%1: not available with a payload section yet (the payload is learned on "
                        "the simulated or the CAN robot; --export, --report and --trial-csv write "
                        "its files)")
                        .arg(option),
                    ExitBadInput);
    }
    PayloadRunSession run;
    try {
        // The simulated robot carrying its payload, and without it for the baseline trials; or
        // the CAN robot, connected here.
        run = robot.kind == RobotRequest::Kind::Can ? makeCanPayloadSession(given, robot)
                                                    : makeSimulatedPayloadSession(given);
    } catch (const Error &e) {
        return fail(e.message(), ExitBadInput);
    }
    if (!run.session)
        return fail(run.connectError, ExitTrialFailed);
    PayloadSession *session = run.session.get();
    const Scenario &scenario = session->scenario();
    const QString link = session->payloadModel().link();
    if (!options.quiet) {
        err << QCoreApplication::translate(
                   "learnid-cli",
                   "learnid-cli: %1, the payload on %2 learned in %3 trials; the arm's model is "
                   "held fixed (robot.initialParameters)")
                   .arg(session->robot().description(), link)
                   .arg(scenario.iterations)
            << Qt::endl;
        if (scenario.payload.baselineTrials > 0) {
            err << QCoreApplication::translate(
                       "learnid-cli",
                       "learnid-cli: first %1 baseline trial(s) of the same timed path without "
                       "the payload, taken out of every payload trial (payload.baselineTrials)")
                       .arg(scenario.payload.baselineTrials)
                << Qt::endl;
        }
        // What the path lets the trials see, before the robot moves.
        const PayloadObservability o = session->observability();
        err << QCoreApplication::translate(
                   "learnid-cli",
                   "learnid-cli: the path determines %1 of the payload's 10 parameters")
                   .arg(o.rank)
            << Qt::endl;
        QStringList lines = o.advice(link);
        if (const PayloadPathChange change = session->pathChange(); change.valid())
            lines << change.describe(session->payloadModel().arm());
        for (const QString &line : lines)
            err << QCoreApplication::translate("learnid-cli", "learnid-cli: %1").arg(line)
                << Qt::endl;
    }
    out << payloadTrialHeader();
    out.flush();
    g_session = session;
    g_interrupted.store(false);
    const auto previous = std::signal(SIGINT, onPayloadInterrupt);
    bool completed = true;
    QString stopped; // why the technician's answer ended the run
    const bool technicianMounts = robot.kind == RobotRequest::Kind::Can;
    const int trials = scenario.payload.baselineTrials + scenario.iterations;
    for (int i = 0; i < trials && completed; ++i) {
        if (technicianMounts)
            stopped = confirmMounting(*session, i, link, err);
        if (!stopped.isEmpty()) {
            completed = false;
            break;
        }
        const PayloadTrial &t = session->runTrial();
        out << cli::payloadTrialRow(t) << Qt::endl;
        completed = t.usable();
    }
    std::signal(SIGINT, previous);
    g_session = nullptr;
    if (const QString result = payloadResult(*session); !result.isEmpty())
        out << Qt::endl << result;
    out.flush();
    if (options.apply && completed) {
        // Before the files, as the arm's session: what was applied is what they record.
        QString error;
        try {
            error = applyRunPayload(run, payloadRunResult(run));
        } catch (const Error &e) {
            error = e.message();
        }
        if (!error.isEmpty())
            return fail(QCoreApplication::translate("learnid-cli", "apply failed: %1").arg(error),
                        ExitTrialFailed);
        if (!options.quiet)
            err << QCoreApplication::translate("learnid-cli",
                                               "learnid-cli: the payload applied to the robot "
                                               "(0x2500 on every node, stored)")
                << Qt::endl;
    }
    QString endedEarly; // why the run ended before its last trial; empty: it did not
    if (!completed) {
        endedEarly = stopped.isEmpty() ? session->history().back().message : stopped;
        if (endedEarly.isEmpty())
            endedEarly = QCoreApplication::translate("learnid-cli", "trial %1 ended the run")
                             .arg(session->history().back().index);
    }
    if (const ExitCode written = writePayloadOutputs(options, run, endedEarly, err);
        written != ExitOk)
        return written;
    if (!completed)
        return fail(endedEarly, ExitTrialFailed);
    return ExitOk;
}

} // namespace learnid::cli
