#include "cli/LoopCommands.h"

#include "cli/PayloadTrialTable.h"
#include "cli/ResultTable.h"
#include "io/ScenarioFile.h"
#include "model/Error.h"
#include "service/FileLoop.h"

#include <QCoreApplication>
#include <QDir>
#include <QLoggingCategory>

namespace learnid::cli {

namespace {

QString errorLine(const QString &message)
{
    return QCoreApplication::translate("learnid-cli", "learnid-cli: error: %1").arg(message);
}

LoopScenario loadScenario(const LoopOptions &options)
{
    const Scenario scenario =
        options.scenarioPath.isEmpty() ? Scenario{} : readScenarioFile(options.scenarioPath);
    validateScenario(scenario);
    return loopScenario(scenario);
}

// Writes the files; on failure says so and gives the exit code.
ExitCode write(const LoopFiles &files, const LoopOptions &options, QTextStream &err)
{
    try {
        const QStringList written = writeLoopFiles(files);
        if (!options.quiet)
            for (const QString &path : written)
                err << QCoreApplication::translate("learnid-cli", "learnid-cli: wrote %1")
                           .arg(QDir::toNativeSeparators(path))
                    << Qt::endl;
    } catch (const Error &e) {
        err << errorLine(e.message()) << Qt::endl;
        return ExitWriteFailed;
    }
    return ExitOk;
}

} // namespace

ExitCode planCommand(const LoopOptions &options, QTextStream &out, QTextStream &err)
{
    QLoggingCategory::setFilterRules(QStringLiteral("learnid.session=false\n"));
    PlannedTrial planned;
    try {
        const LoopScenario s = loadScenario(options);
        PlanRequest request;
        request.estimatePath = options.estimatePath;
        request.historyDir = options.historyDir;
        request.outDir = options.outDir;
        planned = planNextTrial(s, request);
    } catch (const Error &e) {
        err << errorLine(e.message()) << Qt::endl;
        return ExitBadInput;
    }
    if (!planned.passed()) {
        err << planned.checkText;
        err << errorLine(QCoreApplication::translate("learnid-cli",
                                                     "trial %1 refused by the pre-trial check: %2")
                             .arg(planned.trialIndex)
                             .arg(planned.check.reason()))
            << Qt::endl
            << QCoreApplication::translate("learnid-cli", "learnid-cli: no files written")
            << Qt::endl;
        return ExitTrialFailed;
    }
    const ExitCode written = write(planned.files, options, err);
    if (written != ExitOk)
        return written;
    out << planned.checkText
        << QCoreApplication::translate("learnid-cli", "plan-id: %1").arg(planned.planId)
        << Qt::endl;
    return ExitOk;
}

ExitCode learnCommand(const LoopOptions &options, QTextStream &out, QTextStream &err)
{
    QLoggingCategory::setFilterRules(QStringLiteral("learnid.session=false\n"));
    LearnedTrial learned;
    try {
        const LoopScenario s = loadScenario(options);
        LearnRequest request;
        request.trialLogs = options.trialLogs;
        request.historyDir = options.historyDir;
        learned = learnFromTrial(s, request);
    } catch (const Error &e) {
        err << errorLine(e.message()) << Qt::endl;
        return ExitBadInput;
    }
    if (learned.session) {
        if (!options.quiet)
            err << trialSummary(learned.session->history().constLast()) << Qt::endl;
        out << resultTable(*learned.session);
        out.flush();
    }
    if (learned.payloadSession) {
        // As `run` prints a payload session: a row per trial, then the payload learned.
        out << payloadTrialHeader();
        for (const PayloadTrial &t : learned.payloadSession->history())
            out << payloadTrialRow(t) << Qt::endl;
        if (const QString result = payloadResult(*learned.payloadSession); !result.isEmpty())
            out << Qt::endl << result;
        out.flush();
    }
    if (!learned.failure.isEmpty()) {
        err << errorLine(learned.failure) << Qt::endl
            << QCoreApplication::translate("learnid-cli", "learnid-cli: no files written")
            << Qt::endl;
        return ExitTrialFailed;
    }
    const ExitCode written = write(learned.files, options, err);
    if (written != ExitOk || options.quiet)
        return written;
    const PayloadSession *payload = learned.payloadSession.get();
    if (payload && payload->history().back().baseline) {
        // The technician mounts the payload after the last baseline trial.
        err << (payload->nextTrialIsBaseline()
                    ? QCoreApplication::translate("learnid-cli",
                                                  "learnid-cli: baseline trial %1 (plan %2) "
                                                  "kept; the next trial is a baseline trial too, "
                                                  "without the payload")
                    : QCoreApplication::translate("learnid-cli",
                                                  "learnid-cli: baseline trial %1 (plan %2) "
                                                  "kept; mount the payload before the next trial"))
                   .arg(learned.trialIndex)
                   .arg(learned.planId)
            << Qt::endl;
        return written;
    }
    err << QCoreApplication::translate("learnid-cli",
                                       "learnid-cli: trial %1 (plan %2) learned; the next "
                                       "plan uses estimate %3")
               .arg(learned.trialIndex)
               .arg(learned.planId)
               .arg(learned.trialIndex + 1)
        << Qt::endl;
    return written;
}

} // namespace learnid::cli
