#include "cli/LoopOptions.h"

#include "cli/CliOptions.h"
#include "io/OutputPath.h"
#include "model/Error.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace learnid::cli {

namespace {

QString usageOf(bool plan, const QCommandLineParser &parser)
{
    const QString options = optionsHelp(parser);
    return plan ? QCoreApplication::translate(
                      "learnid-cli",
                      "Usage: learnid-cli plan --out DIR [options]\n\n"
                      "Plan the next trial for the robot's own controller: q_d(t) and the\n"
                      "feedforward tau_f(t) per joint (DIR/plan.csv) and the pre-trial check\n"
                      "(DIR/check.txt). A plan that fails the check is not written.\n\n%1")
                      .arg(options)
                : QCoreApplication::translate(
                      "learnid-cli",
                      "Usage: learnid-cli learn --trial-log FILE [options]\n\n"
                      "Learn from the log the robot's own controller recorded while running a\n"
                      "plan: the new estimate joins the history, the convergence table goes to\n"
                      "stdout, and the next plan uses the new estimate.\n\n%1")
                      .arg(options);
}

} // namespace

void parseLoopCommandLine(const QStringList &args, CommandLine *cl)
{
    const bool plan = args.value(1) == QLatin1String("plan");
    QCommandLineParser parser;
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    parser.addOptions({
        cliOption("scenario",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Scenario file (JSON, docs/scenario.md); default: the paper "
                                    "scenario."),
                  "FILE"),
        cliOption(
            "history",
            QT_TRANSLATE_NOOP("learnid-cli",
                              "The learning history's folder; default: learnid-history beside "
                              "plan.csv (plan) or the trial log (learn)."),
            "DIR"),
        cliOption(
            "workspace",
            QT_TRANSLATE_NOOP("learnid-cli", "Folder that relative output paths are taken from."),
            "DIR"),
        cliOption("quiet", QT_TRANSLATE_NOOP("learnid-cli", "No progress lines on stderr.")),
        helpOption(),
    });
    if (plan) {
        parser.addOptions({
            cliOption(
                "out",
                QT_TRANSLATE_NOOP("learnid-cli", "Folder to write plan.csv and check.txt into."),
                "DIR"),
            cliOption("estimate",
                      QT_TRANSLATE_NOOP("learnid-cli",
                                        "Parameter file of the estimate to plan with; default: the "
                                        "history's newest, or the scenario's initial estimate."),
                      "FILE"),
        });
    } else {
        parser.addOption(
            cliOption("trial-log",
                      QT_TRANSLATE_NOOP("learnid-cli",
                                        "The controller's log of a run of the plan (CSV); once per "
                                        "repetition."),
                      "FILE"));
    }
    if (!parseCommandOptions(parser, args, cl, [&] { return usageOf(plan, parser); }))
        return;
    LoopOptions &o = cl->loop;
    o.scenarioPath = parser.value(QStringLiteral("scenario"));
    o.quiet = parser.isSet(QStringLiteral("quiet"));
    if (plan) {
        o.estimatePath = parser.value(QStringLiteral("estimate"));
        if (!parser.isSet(QStringLiteral("out"))) {
            cl->error = QCoreApplication::translate("learnid-cli", "'plan' needs --out DIR");
            return;
        }
    } else {
        o.trialLogs = parser.values(QStringLiteral("trial-log"));
        if (o.trialLogs.isEmpty()) {
            cl->error =
                QCoreApplication::translate("learnid-cli", "'learn' needs --trial-log FILE");
            return;
        }
    }
    const QString ws = parser.isSet(QStringLiteral("workspace"))
                           ? parser.value(QStringLiteral("workspace"))
                           : QDir::currentPath();
    try {
        if (plan)
            o.outDir =
                resolveOutputPath(ws, parser.value(QStringLiteral("out")), QStringLiteral("--out"));
        if (parser.isSet(QStringLiteral("history")))
            o.historyDir = resolveOutputPath(ws, parser.value(QStringLiteral("history")),
                                             QStringLiteral("--history"));
        else if (plan)
            o.historyDir = QDir(o.outDir).filePath(QLatin1String(defaultHistoryFolder));
        else
            o.historyDir = QFileInfo(o.trialLogs.constFirst())
                               .absoluteDir()
                               .filePath(QLatin1String(defaultHistoryFolder));
    } catch (const Error &e) {
        cl->error = e.message();
        cl->errorCode = ExitBadInput;
        return;
    }
    cl->command = plan ? CommandLine::Command::Plan : CommandLine::Command::Learn;
}

} // namespace learnid::cli
